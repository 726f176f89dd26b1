// vtkHexahedralRayCastMapper, traversal pass: the current segment (its isosurfaces, the cubic
// along it, the integration of one piece).
// Part of uvHexahedralTraverseFS.glsl (its marker //UV::HexahedralSegment): reads and writes the
// uniforms and globals declared there.

// ---- The current segment (set by IntegrateCell before it integrates)
vec3 segmentXi0, segmentXi1;  // the segment's ends in the cell's trilinear coordinates
vec3 segmentStartPoint, segmentEndPoint; // and in model space

/// Composites isosurface `k` at model point x, lit with the model-space normal (any length).
void CompositeLitSurface(int k, vec3 x, vec3 normal)
{
  vec4 surface = texelFetch(isosurfaces, ivec2(k, 0), 0);
  vec3 eyePoint = (modelToEye * vec4(x, 1.0)).xyz;
  vec3 toEye = parallelProjection == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-eyePoint);
  vec3 lit = Light(surface.rgb, normalToEye * normal, toEye);
  colour += transmittance * surface.a * lit;
  transmittance *= 1.0 - surface.a;
}

#ifdef UV_VERTEX_GRADIENTS
/// The loaded cell's vertex gradients interpolated at model point x (trilinear coordinates near
/// `xi`) with the cell's own trilinear weights. A tetrahedron's collapsed corners make those weights
/// its barycentric coordinates, found directly; other cells' xi is refined by the inverse map, as
/// the segment's coordinates are exact at its ends only.
vec3 InterpolatedVertexGradient(vec3 x, vec3 xi)
{
  float weights[8];
  if (cellShape == TETRAHEDRON)
  {
    mat3 edges = mat3(points[1] - points[0], points[2] - points[0], points[4] - points[0]);
    vec3 b = IsSingular(edges) ? vec3(0.0) : inverse(edges) * (x - points[0]);
    weights = float[8](1.0 - b.x - b.y - b.z, b.x, b.y, 0.0, b.z, 0.0, 0.0, 0.0);
  }
  else
  {
    vec3 at = InverseTrilinear(x, xi);
    vec3 m = vec3(1.0) - at;
    weights = float[8](m.x * m.y * m.z, at.x * m.y * m.z, at.x * at.y * m.z, m.x * at.y * m.z, m.x * m.y * at.z,
      at.x * m.y * at.z, at.x * at.y * at.z, m.x * at.y * at.z);
  }
  vec3 gradient = vec3(0.0);
  for (int k = 0; k < 8; ++k)
    gradient += weights[k] * texelFetch(pointGradients, int(cellIds[k])).xyz;
  return gradient;
}
#endif

/// Composites isosurface `k` where the segment's parameter is u.
void CompositeSurface(int k, float u)
{
  vec3 x = mix(segmentStartPoint, segmentEndPoint, u), xi = mix(segmentXi0, segmentXi1, u);
#ifdef UV_VERTEX_GRADIENTS
  CompositeLitSurface(k, x, InterpolatedVertexGradient(x, xi));
#else
  CompositeLitSurface(k, x, FieldGradient(xi));
#endif
}

float IsoValue(int k)
{
  return texelFetch(isosurfaces, ivec2(k, 1), 0).r;
}

/// A cell scalar's isosurfaces are the faces between cells on either side of the value
/// (uv::ForEachSurfaceBetweenCells): those of the face at x, normal `normal`, from a cell of value
/// `from` into one of value `to`, in the order the ray meets them.
void CompositeSurfacesBetweenCells(float from, float to, vec3 x, vec3 normal)
{
  for (int i = 0; i < isosurfaceCount; ++i)
  {
    int k = from < to ? i : isosurfaceCount - 1 - i;
    float v = IsoValue(k);
    if ((from < v) != (to < v))
      CompositeLitSurface(k, x, normal);
  }
}

// ---- The cubic along the ray (uvHexahedronRay.h)
float CubicValue(vec4 c, float u)
{
  return c.x + u * (c.y + u * (c.z + u * c.w));
}

float CubicSlope(vec4 c, float u)
{
  return c.y + u * (2.0 * c.z + 3.0 * u * c.w);
}

float CubicIntegral(vec4 p, float x)
{
  return x * (p.x + x * (p.y / 2.0 + x * (p.z / 3.0 + x * p.w / 4.0)));
}

/// The w in [0, width] where CubicIntegral(tau, w) reaches `depth` (the extinction tau is not
/// negative, so the integral rises). The power of two of width that brackets it first (a dense
/// medium reaches it within a 1e-20th of the width), then bisection inside that bracket.
float WidthOfDepth(vec4 tau, float width, float depth)
{
  int fewer = 0, more = 126; // halvings: the integral reaches depth at width / 2^fewer, not at width / 2^more
  while (more - fewer > 1)
  {
    int middle = (fewer + more) / 2;
    if (CubicIntegral(tau, width * exp2(-float(middle))) >= depth)
      fewer = middle;
    else
      more = middle;
  }
  float high = width * exp2(-float(fewer)), low = 0.5 * high;
  for (int i = 0; i < 24; ++i)
  {
    float middle = 0.5 * (low + high);
    if (CubicIntegral(tau, middle) < depth)
      low = middle;
    else
      high = middle;
  }
  return high;
}

vec4 TrilinearAlongSegment(float f[8], vec3 xi0, vec3 xi1)
{
  float a000 = f[0], a100 = f[1] - f[0], a010 = f[3] - f[0], a001 = f[4] - f[0];
  float a110 = f[0] - f[1] + f[2] - f[3];
  float a101 = f[0] - f[1] - f[4] + f[5];
  float a011 = f[0] - f[3] - f[4] + f[7];
  float a111 = -f[0] + f[1] - f[2] + f[3] + f[4] - f[5] + f[6] - f[7];
  float r = xi0.x, s = xi0.y, t = xi0.z;
  vec3 d = xi1 - xi0;
  float fr = a100 + a110 * s + a101 * t + a111 * s * t;
  float fs = a010 + a110 * r + a011 * t + a111 * r * t;
  float ft = a001 + a101 * r + a011 * s + a111 * r * s;
  return vec4(a000 + a100 * r + a010 * s + a001 * t + a110 * r * s + a101 * r * t + a011 * s * t + a111 * r * s * t,
    fr * d.x + fs * d.y + ft * d.z,
    (a110 + a111 * t) * d.x * d.y + (a101 + a111 * s) * d.x * d.z + (a011 + a111 * r) * d.y * d.z,
    a111 * d.x * d.y * d.z);
}

/// The cubic through the values at u = 0, 1/4, 3/4, 1 (uv::CubicThroughSamples).
vec4 CubicThroughSamples(float f0, float fNear, float fFar, float f1)
{
  return vec4(f0, (-19.0 * f0 + 24.0 * fNear - 8.0 * fFar + 3.0 * f1) / 3.0,
    (32.0 * f0 - 56.0 * fNear + 40.0 * fFar - 16.0 * f1) / 3.0,
    16.0 * (-f0 + 2.0 * fNear - 2.0 * fFar + f1) / 3.0);
}

float RootInBracket(vec4 c, float value, float a, float b)
{
  bool rising = CubicValue(c, b) > CubicValue(c, a);
  float u = 0.5 * (a + b);
  for (int iteration = 0; iteration < 40; ++iteration)
  {
    float fu = CubicValue(c, u) - value;
    if ((fu < 0.0) == rising)
      a = u;
    else
      b = u;
    float slope = CubicSlope(c, u);
    float next = slope != 0.0 ? u - fu / slope : 0.5 * (a + b);
    if (!(next > a && next < b))
      next = 0.5 * (a + b);
    if (abs(next - u) <= 1e-7 || b - a <= 1e-7)
      return next;
    u = next;
  }
  return u;
}

// ---- Integration of one cell's segment

/// FAST: the piece [u0, u1]'s scalar linear between its ends, with the Psi table.
void IntegratePieceFast(vec4 c, float len, float u0, float u1)
{
  vec4 a = Evaluate(CubicValue(c, u0)), b = Evaluate(CubicValue(c, u1));
  float pieceLength = len * (u1 - u0);
  float da = a.a * pieceLength, db = b.a * pieceLength;
  if (da + db > 0.0)
  {
    float psi = Psi(da, db);
    float zeta = exp(-0.5 * (da + db));
    Composite(a.rgb * (1.0 - psi) + b.rgb * (psi - zeta), 0.5 * (da + db));
  }
}

/// ACCURATE: the transfer function is linear on the piece [u0, u1], so extinction and colour are
/// cubics; exact optical depth, Gauss-Legendre colour on sub-pieces of bounded depth.
void IntegratePieceAccurate(vec4 c, float len, float u0, float u1)
{
  float mid = CubicValue(c, 0.5 * (u0 + u1));
  int below = NodesAtOrBelow(mid);
  vec4 base, slope = vec4(0.0);
  float baseScalar = 0.0;
  if (below <= 0 || below >= nodeCount)
  {
    base = NodeValue(below <= 0 ? 0 : nodeCount - 1);
  }
  else
  {
    float s0 = NodeScalar(below - 1), s1 = NodeScalar(below);
    base = NodeValue(below - 1);
    slope = (NodeValue(below) - NodeValue(below - 1)) / (s1 - s0);
    baseScalar = s0;
  }
  vec4 g = vec4(CubicValue(c, u0), CubicSlope(c, u0), c.z + 3.0 * c.w * u0, c.w);
  vec4 tau = len * vec4(base.a + slope.a * (g.x - baseScalar), slope.a * g.y, slope.a * g.z, slope.a * g.w);
  float width = u1 - u0;
  float totalDepth = CubicIntegral(tau, width);
  if (!(totalDepth > 0.0))
    return;
  int pieces = int(clamp(ceil(4.0 * totalDepth), 1.0, 16.0));
  // A dense piece: equal widths would leave every sub-piece deep, and the thin front layer all the
  // light comes from between the Gauss nodes (black). There sub-piece k ends where the depth reaches
  // k + 1; behind the last, the transmittance is below exp(-16) and only the depth is composited.
  bool dense = totalDepth > 16.0;
  float w1 = 0.0;
  for (int k = 0; k < pieces; ++k)
  {
    float w0 = w1;
    w1 = dense ? WidthOfDepth(tau, width, float(k + 1)) : width * float(k + 1) / float(pieces);
    float depthBefore = CubicIntegral(tau, w0);
    float halfWidth = 0.5 * (w1 - w0), centre = 0.5 * (w0 + w1);
    vec3 pieceColour = vec3(0.0);
    for (int q = 0; q < 6; ++q)
    {
      float w = centre + halfWidth * gaussNodes[q];
      float scalar = g.x + w * (g.y + w * (g.z + w * g.w));
      float extinction = tau.x + w * (tau.y + w * (tau.z + w * tau.w));
      vec3 rgb = base.rgb + slope.rgb * (scalar - baseScalar);
      pieceColour += gaussWeights[q] * extinction * exp(-(CubicIntegral(tau, w) - depthBefore)) * rgb;
    }
    Composite(pieceColour * halfWidth, CubicIntegral(tau, w1) - depthBefore);
  }
  if (dense)
    Composite(vec3(0.0), totalDepth - CubicIntegral(tau, w1));
}
