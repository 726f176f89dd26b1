//VTK::System::Dec
//VTK::Output::Dec
// vtkHexahedralRayCastMapper, traversal pass (full screen): from the boundary face the entry pass
// found, walks the ray through the hexahedra by face adjacency and integrates the exact trilinear
// field in each (the GPU twin of uvHexahedronRay.h: same steps, same names). Writes the composited
// colour (front to back, premultiplied, alpha) and where the walk left the mesh (for the next peel).
//
// Each cell's field is the cubic of its corner values along the ray, in the cell's affine frame
// (exact for every parallelepiped). Faces are exact bilinear patches, parameterised the same way by
// every cell (uvBilinearFaceLib.glsl): the exit found in one cell is the entry of the next.
//
// Isosurfaces are further cuts: where the cubic crosses an isovalue the surface's colour is
// composited, Phong-lit with the exact gradient of the cell's trilinear field there.
uniform sampler2D entry;        // (ray parameter, boundary face) of this peel, face < 0: none
uniform sampler2D accumulated;  // colour so far: premultiplied rgb, alpha
uniform sampler2D opaqueDepth;
uniform isamplerBuffer boundaryFaces;
uniform usamplerBuffer cellPoints;   // 8 point ids per cell
uniform isamplerBuffer cellNeighbours; // per cell 6 values (2 texels): neighbour * 8 + its face, or -1
uniform samplerBuffer pointData;
uniform mat4 clipToModel;
uniform vec2 viewportSize;
uniform int integrationMode;    // 0 accurate, 1 fast, 2 fixed steps
uniform int fixedSteps;
uniform int exactEnds;           // 1: segment ends by the isoparametric inverse (curved cells)
uniform float opacityThreshold; // early ray termination
uniform int maximumCells;       // bound on the walk (also guards against cycles)
uniform int eyeCell;            // first peel, perspective: the cell holding the eye, or -1
uniform vec3 eyeModel;
uniform sampler2D isosurfaces;  // row 0 (r, g, b, opacity), row 1 (normalised value), ascending
uniform int isosurfaceCount;
uniform mat4 modelToEye;
uniform mat3 normalToEye;       // inverse transpose of modelToEye's linear part
uniform int parallelProjection;

const int faceCorners[24] = int[24](0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7);
const float gaussNodes[6] = float[6](-0.9324695142, -0.6612093865, -0.2386191861, 0.2386191861, 0.6612093865,
  0.9324695142);
const float gaussWeights[6] = float[6](0.1713244924, 0.3607615730, 0.4679139346, 0.4679139346, 0.3607615730,
  0.1713244924);
const int maximumCuts = 32;

vec3 colour = vec3(0.0);
float transmittance = 1.0;

//UV::TransferFunction

//UV::Phong

vec4 Evaluate(float s) // (r, g, b, extinction)
{
  return EvaluateBetween(s, NodesAtOrBelow(s));
}

void Composite(vec3 premultiplied, float depth)
{
  colour += transmittance * premultiplied;
  transmittance *= exp(-depth);
}

// ---- The current segment (set by the traversal before it integrates a cell)
vec3 points[8];
float scalars[8];
// The loaded cell's isoparametric map, x = p0 + b r + c s + d t + e rs + f rt + g st + h rst (set
// by LoadCell: the Jacobian, the inverse map and the curved-cell test all read it).
vec3 mapB, mapC, mapD, mapE, mapF, mapG, mapH;
vec3 segmentXi0, segmentXi1;  // the segment's ends in the cell's trilinear coordinates
vec3 segmentStartPoint, segmentEndPoint; // and in model space

/// d(position)/d(r, s, t) of the loaded cell at xi.
mat3 Jacobian(vec3 xi)
{
  float r = xi.x, s = xi.y, t = xi.z;
  return mat3(mapB + mapE * s + mapF * t + mapH * s * t, mapC + mapE * r + mapG * t + mapH * r * t,
    mapD + mapF * r + mapG * s + mapH * r * s);
}

/// The gradient of the loaded cell's trilinear field at xi, in model space.
vec3 FieldGradient(vec3 xi)
{
  float r = xi.x, s = xi.y, t = xi.z;
  float a100 = scalars[1] - scalars[0], a010 = scalars[3] - scalars[0], a001 = scalars[4] - scalars[0];
  float a110 = scalars[0] - scalars[1] + scalars[2] - scalars[3];
  float a101 = scalars[0] - scalars[1] - scalars[4] + scalars[5];
  float a011 = scalars[0] - scalars[3] - scalars[4] + scalars[7];
  float a111 = -scalars[0] + scalars[1] - scalars[2] + scalars[3] + scalars[4] - scalars[5] + scalars[6] - scalars[7];
  vec3 local = vec3(a100 + a110 * s + a101 * t + a111 * s * t, a010 + a110 * r + a011 * t + a111 * r * t,
    a001 + a101 * r + a011 * s + a111 * r * s);
  mat3 jacobian = Jacobian(xi);
  if (abs(determinant(jacobian)) < 1e-30)
    return vec3(0.0);
  return transpose(inverse(jacobian)) * local;
}

/// Composites isosurface `k` where the segment's parameter is u.
void CompositeSurface(int k, float u)
{
  vec4 surface = texelFetch(isosurfaces, ivec2(k, 0), 0);
  vec3 eyePoint = (modelToEye * vec4(mix(segmentStartPoint, segmentEndPoint, u), 1.0)).xyz;
  vec3 toEye = parallelProjection == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-eyePoint);
  vec3 lit = Light(surface.rgb, normalToEye * FieldGradient(mix(segmentXi0, segmentXi1, u)), toEye);
  colour += transmittance * surface.a * lit;
  transmittance *= 1.0 - surface.a;
}

float IsoValue(int k)
{
  return texelFetch(isosurfaces, ivec2(k, 1), 0).r;
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

/// One piece [u0, u1] of the segment, between consecutive split points: the transfer function is
/// linear on it. FAST: the scalar linear between the ends, with the Psi table.
void IntegratePiece(vec4 c, float len, float u0, float u1)
{
  if (integrationMode == 1)
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
    return;
  }
  // Accurate: the transfer function is linear on this piece; extinction and colour are cubics.
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
  for (int k = 0; k < pieces; ++k)
  {
    float w0 = width * float(k) / float(pieces), w1 = width * float(k + 1) / float(pieces);
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
}

/// Integrates the cell's segment of `len` whose scalar is the cubic c(u), u in [0, 1].
void IntegrateCubicSegment(vec4 c, float len)
{
  if (!(len > 0.0))
    return;
  // Split points: 0, extrema, 1, then per monotonic interval the node and isovalue crossings (an
  // isovalue equal to an interval's far end counts there, at its near end not: once per ray).
  float cuts[maximumCuts];
  int surfaceAt[maximumCuts]; // the isosurface a cut is on, or -1
  int cutCount = 0;
  float bounds[4];
  int boundCount = 0;
  bounds[boundCount++] = 0.0;
  float qa = 3.0 * c.w, qb = 2.0 * c.z, qc = c.y;
  float scale = abs(qa) + abs(qb) + abs(qc);
  float e0 = -1.0, e1 = -1.0;
  if (scale > 0.0)
  {
    if (abs(qa) <= 1e-7 * scale)
    {
      e0 = qb != 0.0 ? -qc / qb : -1.0;
    }
    else
    {
      float discriminant = qb * qb - 4.0 * qa * qc;
      if (discriminant >= 0.0)
      {
        float q = -0.5 * (qb + (qb >= 0.0 ? 1.0 : -1.0) * sqrt(discriminant));
        e0 = q / qa;
        e1 = q != 0.0 ? qc / q : -1.0;
      }
    }
  }
  float low = min(e0, e1), high = max(e0, e1);
  if (low > 0.0 && low < 1.0)
    bounds[boundCount++] = low;
  if (high > 0.0 && high < 1.0 && high != low)
    bounds[boundCount++] = high;
  bounds[boundCount++] = 1.0;
  for (int i = 0; i < boundCount; ++i)
  {
    surfaceAt[cutCount] = -1;
    cuts[cutCount++] = bounds[i];
  }
  bool constantSteps = integrationMode == 2;
  for (int i = 0; i + 1 < boundCount; ++i)
  {
    float a = bounds[i], b = bounds[i + 1];
    float fa = CubicValue(c, a), fb = CubicValue(c, b);
    float lo = min(fa, fb), hi = max(fa, fb);
    for (int k = 0; k < isosurfaceCount && cutCount < maximumCuts; ++k)
    {
      float v = IsoValue(k);
      if ((v > lo && v < hi) || (v == fb && v != fa))
      {
        surfaceAt[cutCount] = k;
        cuts[cutCount++] = RootInBracket(c, v, a, b);
      }
    }
    for (int k = NodesAtOrBelow(lo); !constantSteps && k < nodeCount && NodeScalar(k) < hi && cutCount < maximumCuts; ++k)
    {
      if (NodeScalar(k) > lo)
      {
        surfaceAt[cutCount] = -1;
        cuts[cutCount++] = RootInBracket(c, NodeScalar(k), a, b);
      }
    }
  }
  for (int i = 1; i < cutCount; ++i) // insertion sort: a handful of values
  {
    float v = cuts[i];
    int kind = surfaceAt[i];
    int j = i - 1;
    while (j >= 0 && cuts[j] > v)
    {
      cuts[j + 1] = cuts[j];
      surfaceAt[j + 1] = surfaceAt[j];
      --j;
    }
    cuts[j + 1] = v;
    surfaceAt[j + 1] = kind;
  }
  if (constantSteps)
  {
    // Constant steps over the cell (the paper's Hexa_CONST); a surface goes in before the first step
    // whose midpoint lies beyond it.
    float h = len / float(fixedSteps);
    int next = 0;
    for (int i = 0; i < fixedSteps; ++i)
    {
      float middle = (float(i) + 0.5) / float(fixedSteps);
      for (; next < cutCount && cuts[next] <= middle; ++next)
        if (surfaceAt[next] >= 0)
          CompositeSurface(surfaceAt[next], cuts[next]);
      vec4 n = Evaluate(CubicValue(c, middle));
      Composite((1.0 - exp(-n.a * h)) * n.rgb, n.a * h);
    }
    for (; next < cutCount; ++next)
      if (surfaceAt[next] >= 0)
        CompositeSurface(surfaceAt[next], cuts[next]);
    return;
  }
  for (int i = 0; i + 1 < cutCount; ++i)
  {
    float u0 = cuts[i], u1 = cuts[i + 1];
    if (u1 > u0)
      IntegratePiece(c, len, u0, u1);
    if (surfaceAt[i + 1] >= 0)
      CompositeSurface(surfaceAt[i + 1], u1);
  }
}

//UV::BilinearFace

/// False when the transfer function is transparent over the whole scalar range [low, high] and no
/// isovalue lies in it: such a cell costs this test, and no integration.
bool RangeVisible(float low, float high)
{
  if (Evaluate(low).a > 0.0 || Evaluate(high).a > 0.0)
    return true;
  for (int k = 0; k < isosurfaceCount; ++k)
  {
    float v = IsoValue(k);
    if (v >= low && v <= high)
      return true;
  }
  for (int k = NodesAtOrBelow(low); k < nodeCount && NodeScalar(k) < high; ++k)
  {
    if (NodeValue(k).a > 0.0)
      return true;
  }
  return false;
}

// ---- Traversal

void LoadCell(int cell)
{
  uvec4 a = texelFetch(cellPoints, 2 * cell), b = texelFetch(cellPoints, 2 * cell + 1);
  uint ids[8] = uint[8](a.x, a.y, a.z, a.w, b.x, b.y, b.z, b.w);
  for (int k = 0; k < 8; ++k)
  {
    vec4 data = texelFetch(pointData, int(ids[k]));
    points[k] = data.xyz;
    scalars[k] = data.w;
  }
  mapB = points[1] - points[0];
  mapC = points[3] - points[0];
  mapD = points[4] - points[0];
  mapE = points[0] - points[1] + points[2] - points[3];
  mapF = points[0] - points[1] - points[4] + points[5];
  mapG = points[0] - points[3] - points[4] + points[7];
  mapH = -points[0] + points[1] - points[2] + points[3] + points[4] - points[5] + points[6] - points[7];
}

/// Trilinear coordinates of x in the loaded cell: Newton on the isoparametric map from `xi`.
vec3 InverseTrilinear(vec3 x, vec3 xi)
{
  for (int iteration = 0; iteration < 8; ++iteration)
  {
    float r = xi.x, s = xi.y, t = xi.z;
    vec3 mapped = points[0] + mapB * r + mapC * s + mapD * t + mapE * r * s + mapF * r * t + mapG * s * t +
      mapH * r * s * t;
    mat3 jacobian = Jacobian(xi);
    if (abs(determinant(jacobian)) < 1e-30)
      break;
    vec3 step = inverse(jacobian) * (mapped - x);
    xi = clamp(xi - step, vec3(-0.5), vec3(1.5));
    if (max(abs(step.x), max(abs(step.y), abs(step.z))) < 1e-6)
      break;
  }
  return xi;
}

/// Whether a ray along `direction` leaves a cell where its face's normal is `normal` (either
/// orientation; `outward`, the face's mean outward normal, orients it). A vanishing normal (a
/// collapsed edge) falls back to `outward`; a collapsed face does not block.
bool Leaves(vec3 normal, vec3 outward, vec3 direction)
{
  float tiny = 1e-6 * dot(outward, outward);
  if (!(tiny > 0.0))
    return true;
  normal = dot(normal, normal) > tiny ? normal : outward;
  normal = dot(normal, outward) < 0.0 ? -normal : normal;
  return dot(normal, direction) > 0.0;
}

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 before = texelFetch(accumulated, pixel, 0);
  colour = before.rgb;
  transmittance = 1.0 - before.a;
  vec4 start = texelFetch(entry, pixel, 0);
  float exitParameter = 3.0e38; // no further peel
  bool fromEye = eyeCell >= 0;
  if ((start.g >= 0.0 || fromEye) && transmittance > 1.0 - opacityThreshold)
  {
    vec2 ndc = gl_FragCoord.xy / viewportSize * 2.0 - 1.0;
    vec4 nearPoint = clipToModel * vec4(ndc, -1.0, 1.0);
    vec4 farPoint = clipToModel * vec4(ndc, 1.0, 1.0);
    vec3 origin = nearPoint.xyz / nearPoint.w;
    vec3 direction = normalize(farPoint.xyz / farPoint.w - origin);
    // Opaque geometry ends the ray.
    float depth = texelFetch(opaqueDepth, pixel, 0).r;
    vec4 opaque = clipToModel * vec4(ndc, 2.0 * depth - 1.0, 1.0);
    float opaqueT = depth < 1.0 ? dot(opaque.xyz / opaque.w - origin, direction) : 3.0e38;

    int cell, enterFace;
    float t;
    if (fromEye)
    {
      // The camera is inside the mesh: every ray starts at the eye, in its cell.
      cell = eyeCell;
      enterFace = -1;
      t = dot(eyeModel - origin, direction);
    }
    else
    {
      ivec4 cellFace = texelFetch(boundaryFaces, int(start.g));
      cell = cellFace.x;
      enterFace = cellFace.y;
      t = start.r;
    }
    for (int step = 0; step < maximumCells; ++step)
    {
      LoadCell(cell);
      // The exit: the nearest face (other than the entry) the ray meets beyond t.
      float exitT = 3.0e38;
      int exitFace = -1;
      uvec4 idsA = texelFetch(cellPoints, 2 * cell), idsB = texelFetch(cellPoints, 2 * cell + 1);
      uint ids[8] = uint[8](idsA.x, idsA.y, idsA.z, idsA.w, idsB.x, idsB.y, idsB.z, idsB.w);
      vec3 cellCentre = vec3(0.0);
      for (int k = 0; k < 8; ++k)
        cellCentre += 0.125 * points[k];
      float tolerance = 1e-6 * (1.0 + abs(t));
      for (int f = 0; f < 6; ++f)
      {
        if (f == enterFace)
          continue;
        int corner[4] = int[4](faceCorners[4 * f], faceCorners[4 * f + 1], faceCorners[4 * f + 2], faceCorners[4 * f + 3]);
        // The face exactly, as the bilinear patch through its corners (parameterised canonically).
        vec3 q[4] = vec3[4](points[corner[0]], points[corner[1]], points[corner[2]], points[corner[3]]);
        uint qi[4] = uint[4](ids[corner[0]], ids[corner[1]], ids[corner[2]], ids[corner[3]]);
        vec3 a, b, c, d;
        CanonicalQuad(q, qi, a, b, c, d);
        float h0, h1;
        vec2 uv0, uv1;
        int hits = HitPatchAt(origin, direction, a, b, c, d, h0, h1, uv0, uv1);
        // Only where the ray leaves the cell: near an edge the ray can also meet (within the edge
        // slack) a face it enters through, just after the entry on the neighbouring face.
        vec3 outward = PatchNormal(a, b, c, d, cellCentre);
        if (hits > 0 && h0 > t + tolerance && h0 < exitT && Leaves(PatchNormalAt(a, b, c, d, uv0), outward, direction))
        {
          exitT = h0;
          exitFace = f;
        }
        if (hits > 1 && h1 > t + tolerance && h1 < exitT && Leaves(PatchNormalAt(a, b, c, d, uv1), outward, direction))
        {
          exitT = h1;
          exitFace = f;
        }
      }
      if (exitFace < 0)
      {
        // No face claims the ray: it passed within rounding of an edge or a corner into a cell it
        // only touches. Find the cell holding a point just ahead by walking towards it across the
        // faces it lies outside of, and go on from there.
        bool located = false;
        float ahead = 0.0;
        int startCell = cell;
        for (int attempt = 0; attempt < 3 && !located; ++attempt)
        {
          // A point a little ahead (farther on each attempt), located by walking towards it.
          cell = startCell;
          LoadCell(cell);
          ahead = (attempt == 0 ? 1e-3 : (attempt == 1 ? 1e-2 : 5e-2)) * length(points[6] - points[0]);
          vec3 target = origin + (t + ahead) * direction;
          for (int walk = 0; walk < 32; ++walk)
          {
            // The point's trilinear coordinates in this cell decide, consistently with the exact
            // bilinear faces, whether it is inside, and if not, which face to cross: the one of the
            // most violated coordinate (r = 0: face 5, r = 1: face 3, s = 0: 2, s = 1: 4, t = 0: 0,
            // t = 1: 1), preferring faces with a neighbour.
            ivec4 m0 = texelFetch(cellNeighbours, 2 * cell), m1 = texelFetch(cellNeighbours, 2 * cell + 1);
            int across[6] = int[6](m0.x, m0.y, m0.z, m0.w, m1.x, m1.y);
            vec3 centre = vec3(0.0);
            for (int k = 0; k < 8; ++k)
              centre += 0.125 * points[k];
            vec3 r = 0.25 * ((points[1] - points[0]) + (points[2] - points[3]) + (points[5] - points[4]) + (points[6] - points[7]));
            vec3 s = 0.25 * ((points[3] - points[0]) + (points[2] - points[1]) + (points[7] - points[4]) + (points[6] - points[5]));
            vec3 w = 0.25 * ((points[4] - points[0]) + (points[5] - points[1]) + (points[6] - points[2]) + (points[7] - points[3]));
            vec3 xi = InverseTrilinear(target, inverse(mat3(r, s, w)) * (target - (centre - 0.5 * (r + s + w))));
            float violation[6] = float[6](-xi.z, xi.z - 1.0, -xi.y, xi.x - 1.0, xi.y - 1.0, -xi.x);
            int outside = -1, outsideBoundary = -1;
            float farthest = 1e-6, farthestBoundary = 1e-6;
            for (int f = 0; f < 6; ++f)
            {
              if (across[f] >= 0 && violation[f] > farthest)
              {
                farthest = violation[f];
                outside = f;
              }
              if (across[f] < 0 && violation[f] > farthestBoundary)
              {
                farthestBoundary = violation[f];
                outsideBoundary = f;
              }
            }
            if (outside < 0)
            {
              located = outsideBoundary < 0; // inside this cell, or outside the mesh
              break;
            }
            cell = across[outside] / 8;
            LoadCell(cell);
          }
        }
        if (!located)
        {
          exitParameter = t;
          break;
        }
        enterFace = -1;
        t += ahead; // the skipped sliver of path is a thousandth of a cell
        continue;
      }
      float segmentEnd = min(exitT, opaqueT);
      float low = scalars[0], high = scalars[0];
      for (int k = 1; k < 8; ++k)
      {
        low = min(low, scalars[k]);
        high = max(high, scalars[k]);
      }
      if (segmentEnd > t && RangeVisible(low, high))
      {
        // Parametric coordinates of both ends in the cell's affine frame.
        vec3 r = 0.25 * ((points[1] - points[0]) + (points[2] - points[3]) + (points[5] - points[4]) + (points[6] - points[7]));
        vec3 s = 0.25 * ((points[3] - points[0]) + (points[2] - points[1]) + (points[7] - points[4]) + (points[6] - points[5]));
        vec3 w = 0.25 * ((points[4] - points[0]) + (points[5] - points[1]) + (points[6] - points[2]) + (points[7] - points[3]));
        vec3 centre = vec3(0.0);
        for (int k = 0; k < 8; ++k)
          centre += 0.125 * points[k];
        mat3 toLocal = inverse(mat3(r, s, w));
        vec3 frameOrigin = centre - 0.5 * (r + s + w);
        vec3 entryPoint = origin + t * direction, exitPoint = origin + segmentEnd * direction;
        vec3 xi0 = toLocal * (entryPoint - frameOrigin);
        vec3 xi1 = toLocal * (exitPoint - frameOrigin);
        // A parallelepiped's map is its frame (no bilinear terms): the frame's cubic is exact.
        float twist = max(max(length(mapE), length(mapF)), max(length(mapG), length(mapH)));
        bool curved = twist > 1e-5 * (length(r) + length(s) + length(w));
        vec4 field;
        if (exactEnds == 1 && curved)
        {
          // Through the isoparametric map (the frame's coordinates are the start): the ends, so the
          // field matches the cell's where the ray crosses faces and is continuous from cell to cell
          // on curved meshes, and two inner points; the field is the cubic through those four exact
          // values (on a parallelepiped the same cubic as the frame's).
          vec3 xiNear = InverseTrilinear(mix(entryPoint, exitPoint, 0.25), mix(xi0, xi1, 0.25));
          vec3 xiFar = InverseTrilinear(mix(entryPoint, exitPoint, 0.75), mix(xi0, xi1, 0.75));
          xi0 = InverseTrilinear(entryPoint, xi0);
          xi1 = InverseTrilinear(exitPoint, xi1);
          field = CubicThroughSamples(TrilinearAlongSegment(scalars, xi0, xi0).x,
            TrilinearAlongSegment(scalars, xiNear, xiNear).x, TrilinearAlongSegment(scalars, xiFar, xiFar).x,
            TrilinearAlongSegment(scalars, xi1, xi1).x);
        }
        else
        {
          field = TrilinearAlongSegment(scalars, xi0, xi1);
        }
        segmentXi0 = xi0;
        segmentXi1 = xi1;
        segmentStartPoint = entryPoint;
        segmentEndPoint = exitPoint;
        IntegrateCubicSegment(field, segmentEnd - t);
      }
      if (transmittance <= 1.0 - opacityThreshold || exitT >= opaqueT)
      {
        break;
      }
      ivec4 n0 = texelFetch(cellNeighbours, 2 * cell), n1 = texelFetch(cellNeighbours, 2 * cell + 1);
      int neighbours[6] = int[6](n0.x, n0.y, n0.z, n0.w, n1.x, n1.y);
      int next = neighbours[exitFace];
      if (next < 0)
      {
        exitParameter = exitT; // left the mesh: the next peel looks beyond here
        break;
      }
      cell = next / 8;
      enterFace = next % 8;
      t = exitT;
    }
  }
  gl_FragData[0] = vec4(colour, 1.0 - transmittance);
  gl_FragData[1] = vec4(exitParameter, 0.0, 0.0, 1.0);
}
