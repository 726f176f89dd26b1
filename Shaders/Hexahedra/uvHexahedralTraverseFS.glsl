//VTK::System::Dec
//VTK::Output::Dec
// vtkHexahedralRayCastMapper, traversal pass (full screen): from the boundary face the entry pass
// found, walks the ray through the hexahedra by face adjacency and integrates the exact trilinear
// field in each (the GPU twin of uvHexahedronRay.h: same steps, same names). Writes the composited
// colour (front to back, premultiplied, alpha) and, for the next peel, where and how the walk ended
// and the boundary face it entered by.
//
// Each cell's field is the cubic of its corner values along the ray, in the cell's affine frame
// (exact for every parallelepiped). Tetrahedra, pyramids and wedges come as hexahedra with repeated
// corners (uvHexahedralMesh.h), whose trilinear map is their own: a tetrahedron's field is linear,
// the others' go through the isoparametric inverse; their triangular faces are flat. Faces are exact bilinear patches, parameterised the same way by
// every cell (uvBilinearFaceLib.glsl): the exit found in one cell is the entry of the next.
//
// Isosurfaces are further cuts: where the cubic crosses an isovalue the surface's colour is
// composited, Phong-lit with the exact gradient of the cell's trilinear field there, or with
// UV_VERTEX_GRADIENTS the vertex gradients interpolated by the cell's trilinear weights there
// (smooth across cells). For a cell scalar they are the faces between cells on either side of the
// value, lit with the face's normal.
uniform sampler2D entry;        // (ray parameter, boundary face) of this peel, face < 0: none
uniform sampler2D accumulated;  // colour so far: premultiplied rgb, alpha
uniform sampler2D opaqueDepth;
uniform isamplerBuffer boundaryFaces;
uniform isamplerBuffer cellNeighbours; // per cell 6 values (2 texels): neighbour * 8 + its face, or -1;
                                       // -2 - cell: a boundary face against that cell's (a fault)
#ifdef UV_CELL_DENSITIES
uniform samplerBuffer cellDensities;    // per cell, the coincident copies it stands for (media add up)
#endif
#ifdef UV_CELL_SCALARS
uniform samplerBuffer cellScalars;      // cell data: one normalised value per cell, constant in it
#endif
#ifdef UV_VERTEX_GRADIENTS
uniform samplerBuffer pointGradients;   // per point: the scalar's gradient in model space (xyz)
#endif
uniform mat4 clipToModel;       // for the opaque geometry's depth
uniform vec3 nearPlane[3];      // the rays (EyeRay)
uniform vec3 rayDirection[3];
uniform vec2 viewportSize;
// The program's integration mode (0 accurate, 1 fast, 2 fixed steps): a constant, so that the modes not
// taken cost nothing (a CPU driver runs every branch some pixel of a SIMD group takes, and more).
const int integrationMode = UV_INTEGRATION_MODE;
uniform int fixedSteps;
uniform int exactEnds;           // 1: segment ends by the isoparametric inverse (curved cells)
uniform float opacityThreshold; // early ray termination
uniform int maximumCells;       // bound on the walk (also guards against cycles)
#ifdef UV_SKIP_INVISIBLE_CELLS
uniform usamplerBuffer visibleCells; // the visible region's cells (whose entry faces are drawn), a bit each
uniform int invisibleCellLimit; // cells outside it in a row after which the walk leaves the ray to
                                // the next peel's entry faces
uniform vec3 visibleLow, visibleHigh; // a box holding every cell of the visible region
#endif
uniform int startCell;          // first peel, the near plane inside the mesh: the cell holding the
                                // eye or the near plane's centre, or -1
uniform sampler2D isosurfaces;  // row 0 (r, g, b, opacity), row 1 (normalised value), ascending
uniform int isosurfaceCount;
uniform mat4 modelToEye;
uniform mat3 normalToEye;       // inverse transpose of modelToEye's linear part
uniform int parallelProjection;

const float gaussNodes[6] = float[6](-0.9324695142, -0.6612093865, -0.2386191861, 0.2386191861, 0.6612093865,
  0.9324695142);
const float gaussWeights[6] = float[6](0.1713244924, 0.3607615730, 0.4679139346, 0.4679139346, 0.3607615730,
  0.1713244924);
const float noExit = 3.0e38; // a ray parameter beyond every other

vec3 colour = vec3(0.0);
float transmittance = 1.0;
// How the walk ended, for the next peel's entry pass: opaque, out of the mesh through a boundary
// face, or lost at an edge (Relocate found no cell ahead).
// UNLOCATED: the first peel's walk from startCell did not reach the ray's near-plane point (a hole in
// the way, or the point is outside the mesh); the next peel's entry pass takes the nearest crossing
// of either kind for it.
const float STOPPED = 0.0, LEFT_THROUGH_BOUNDARY = 1.0, LOST = 2.0, UNLOCATED = 3.0;
const int nearPlaneSteps = 256; // cells a ray walks from startCell to its near-plane point
float stopKind = STOPPED;
// The cell the walk left the mesh from (LEFT_THROUGH_BOUNDARY), -1 otherwise: the next peel does not
// enter that cell again where it was left (a flat cell's faces coincide: entering by another of
// them, the walk would leave it there again, peel after peel).
int leftCell = -1;

//UV::TransferFunction

//UV::Phong

//UV::BilinearFace

//UV::Hexahedron

vec4 Evaluate(float s) // (r, g, b, extinction)
{
  return EvaluateBetween(s, NodesAtOrBelow(s));
}

void Composite(vec3 premultiplied, float depth)
{
  colour += transmittance * premultiplied;
  transmittance *= exp(-depth);
}

// ---- The loaded cell (set by LoadCell; the walk, the integration and the lighting read it)
uint cellIds[8];
vec3 points[8];
float scalars[8];
// Its isoparametric map, x = p0 + b r + c s + d t + e rs + f rt + g st + h rst: the Jacobian, the
// inverse map and the curved-cell test read it.
vec3 mapB, mapC, mapD, mapE, mapF, mapG, mapH;
// What its repeated corners make it, and for a tetrahedron its field's constant gradient.
const int HEXAHEDRON = 0, WEDGE = 1, PYRAMID = 2, TETRAHEDRON = 3;
int cellShape;
vec3 tetrahedronGradient;
// Whether it has no thickness up to rounding (a collapsed layer, a sliver): it holds no point, adds
// nothing to the ray, and its inverse map and frame are singular.
bool cellFlat;

/// A tetrahedron (corners 0, 1, 2, 4 distinct) has a linear field: its gradient.
vec3 LinearFieldGradient()
{
  mat3 edges = mat3(points[1] - points[0], points[2] - points[0], points[4] - points[0]);
  if (IsSingular(edges))
    return vec3(0.0);
  return transpose(inverse(edges)) * vec3(scalars[1] - scalars[0], scalars[2] - scalars[0], scalars[4] - scalars[0]);
}

/// Face f of the loaded cell's corners in cyclic order (outward for a cell of positive volume).
void CyclicFace(int f, out vec3 q[4])
{
  for (int k = 0; k < 4; ++k)
    q[k] = points[FaceCorner(f, k)];
}

/// Whether the loaded cell's centre lies in the plane of each of its faces up to rounding.
bool IsFlat()
{
  vec3 centre = CellCentre(points);
  for (int f = 0; f < 6; ++f)
  {
    vec3 q[4];
    CyclicFace(f, q);
    if (!CentreInFacePlane(q, centre))
      return false;
  }
  return true;
}

void LoadCell(int cell)
{
  CellPointIds(cell, cellIds);
  for (int k = 0; k < 8; ++k)
  {
    vec4 data = texelFetch(pointData, int(cellIds[k]));
    points[k] = data.xyz;
    scalars[k] = data.w;
  }
#ifdef UV_CELL_SCALARS
  // Every corner takes the cell's value: the cubic along the ray is that constant.
  float value = texelFetch(cellScalars, cell).r;
  for (int k = 0; k < 8; ++k)
    scalars[k] = value;
#endif
  mapB = points[1] - points[0];
  mapC = points[3] - points[0];
  mapD = points[4] - points[0];
  mapE = points[0] - points[1] + points[2] - points[3];
  mapF = points[0] - points[1] - points[4] + points[5];
  mapG = points[0] - points[3] - points[4] + points[7];
  mapH = -points[0] + points[1] - points[2] + points[3] + points[4] - points[5] + points[6] - points[7];
#ifdef UV_ALL_PARALLELEPIPEDS
  cellShape = HEXAHEDRON;
  tetrahedronGradient = vec3(0.0);
#else
  bool apex = cellIds[4] == cellIds[5] && cellIds[5] == cellIds[6] && cellIds[6] == cellIds[7];
  bool collapsedEdge = cellIds[2] == cellIds[3];
  cellShape = apex ? (collapsedEdge ? TETRAHEDRON : PYRAMID)
                   : (collapsedEdge && cellIds[6] == cellIds[7] ? WEDGE : HEXAHEDRON);
  tetrahedronGradient = cellShape == TETRAHEDRON ? LinearFieldGradient() : vec3(0.0);
#endif
#ifdef UV_ALL_CELLS_CONVEX
  cellFlat = false; // a convex cell has a volume
#else
  cellFlat = IsFlat();
#endif
}

/// Face f of the loaded cell as CanonicalFace gives it; returns its distinct corners.
int LoadedCellFace(int f, out vec3 a, out vec3 b, out vec3 c, out vec3 d)
{
  vec3 q[4];
  uint qi[4];
  for (int k = 0; k < 4; ++k)
  {
    q[k] = points[FaceCorner(f, k)];
    qi[k] = cellIds[FaceCorner(f, k)];
  }
  return CanonicalFace(q, qi, a, b, c, d);
}

/// How many distinct corners face f of the loaded cell has (under 3: collapsed, no face).
int FaceCornerCount(int f)
{
  vec3 a, b, c, d;
  return LoadedCellFace(f, a, b, c, d);
}

/// The neighbour across each face of `cell`: neighbour * 8 + its face, or -1.
void CellNeighbours(int cell, out int across[6])
{
  ivec4 a = texelFetch(cellNeighbours, 2 * cell), b = texelFetch(cellNeighbours, 2 * cell + 1);
  across = int[6](a.x, a.y, a.z, a.w, b.x, b.y);
}

/// d(position)/d(r, s, t) of the loaded cell at xi.
mat3 Jacobian(vec3 xi)
{
  float r = xi.x, s = xi.y, t = xi.z;
  return mat3(mapB + mapE * s + mapF * t + mapH * s * t, mapC + mapE * r + mapG * t + mapH * r * t,
    mapD + mapF * r + mapG * s + mapH * r * s);
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
    if (IsSingular(jacobian))
      break;
    vec3 step = inverse(jacobian) * (mapped - x);
    xi = clamp(xi - step, vec3(-0.5), vec3(1.5));
    if (max(abs(step.x), max(abs(step.y), abs(step.z))) < 1e-6)
      break;
  }
  return xi;
}

/// Wedge coordinates (r, s, t) of x in the loaded wedge (VTK's points 0..5 are corners 0, 2, 1,
/// 4, 6, 5 of its collapsed hexahedron): x = (1 - t) B(r, s) + t T(r, s), B and T the bottom and top
/// triangles at barycentric (1 - r - s, r, s). Newton from the centre.
vec3 InverseWedge(vec3 x)
{
  vec3 p0 = points[0], p1 = points[2], p2 = points[1], p3 = points[4], p4 = points[6], p5 = points[5];
  vec3 w = vec3(1.0 / 3.0, 1.0 / 3.0, 0.5);
  for (int iteration = 0; iteration < 10; ++iteration)
  {
    float r = w.x, s = w.y, t = w.z;
    vec3 bottom = p0 + r * (p1 - p0) + s * (p2 - p0), top = p3 + r * (p4 - p3) + s * (p5 - p3);
    vec3 mapped = mix(bottom, top, t);
    mat3 jacobian = mat3(mix(p1 - p0, p4 - p3, t), mix(p2 - p0, p5 - p3, t), top - bottom);
    if (IsSingular(jacobian))
      break;
    vec3 step = inverse(jacobian) * (mapped - x);
    w = clamp(w - step, vec3(-0.5), vec3(1.5));
    if (max(abs(step.x), max(abs(step.y), abs(step.z))) < 1e-6)
      break;
  }
  return w;
}

/// Whether the loaded cell's map has bilinear terms: a parallelepiped's map is its frame, whose cubic
/// is exact.
bool IsCurved(HexahedronFrame frame)
{
  float twist = max(max(length(mapE), length(mapF)), max(length(mapG), length(mapH)));
  return twist > 1e-5 * (length(frame.axes[0]) + length(frame.axes[1]) + length(frame.axes[2]));
}

/// The gradient of the loaded cell's trilinear field at xi, in model space.
vec3 FieldGradient(vec3 xi)
{
  if (cellShape == TETRAHEDRON)
    return tetrahedronGradient;
  float r = xi.x, s = xi.y, t = xi.z;
  float a100 = scalars[1] - scalars[0], a010 = scalars[3] - scalars[0], a001 = scalars[4] - scalars[0];
  float a110 = scalars[0] - scalars[1] + scalars[2] - scalars[3];
  float a101 = scalars[0] - scalars[1] - scalars[4] + scalars[5];
  float a011 = scalars[0] - scalars[3] - scalars[4] + scalars[7];
  float a111 = -scalars[0] + scalars[1] - scalars[2] + scalars[3] + scalars[4] - scalars[5] + scalars[6] - scalars[7];
  vec3 local = vec3(a100 + a110 * s + a101 * t + a111 * s * t, a010 + a110 * r + a011 * t + a111 * r * t,
    a001 + a101 * r + a011 * s + a111 * r * s);
  mat3 jacobian = Jacobian(xi);
  if (IsSingular(jacobian))
    return vec3(0.0);
  return transpose(inverse(jacobian)) * local;
}

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

// ---- The segment's cuts, one at a time along the ray
// The segment is cut at the ends of the cubic's monotonic intervals, where it crosses an isovalue,
// and (ACCURATE and FAST) where it crosses a transfer-function node. Inside a monotonic interval the
// crossings come in the order of their values, so they are produced one by one from the sorted nodes
// and the isovalues, with nothing stored: no array is written at a per-pixel index. A GPU keeps such
// an array in slow memory, and softpipe's interpreter writes it at the index of the first pixel of
// each 2x2 quad for all four pixels.
vec4 cutCubic;          // c(u), u in [0, 1]
bool cutAtNodes;        // nodes cut the segment too
vec4 cutBounds;         // 0, the cubic's extrema inside (0, 1), 1 (cutBoundCount of them), ascending
int cutBoundCount;
int cutInterval;        // the monotonic interval [cutBounds[i], cutBounds[i + 1]] being walked
float cutValue;         // the scalar at the last cut

/// 0, the cubic's extrema inside (0, 1), and 1: the ends of its monotonic intervals, ascending.
int MonotonicBounds(vec4 c, out vec4 bounds)
{
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
  bool hasLow = low > 0.0 && low < 1.0;
  bool hasHigh = high > 0.0 && high < 1.0 && high != low;
  bounds = vec4(0.0, hasLow ? low : (hasHigh ? high : 1.0), hasLow && hasHigh ? high : 1.0, 1.0);
  return 2 + int(hasLow) + int(hasHigh);
}

/// Starts the cuts of the cubic c(u) on [0, 1] at u = 0.
void StartCuts(vec4 c, bool nodes)
{
  cutCubic = c;
  cutAtNodes = nodes;
  cutBoundCount = MonotonicBounds(c, cutBounds);
  cutInterval = 0;
  cutValue = c.x;
}

/// Whether `v` lies beyond the last cut inside the current interval, which runs toward `to`: an
/// isovalue equal to the interval's far end counts there (and not again at the next one's start).
bool IsovalueAhead(float v, float to, bool rising)
{
  return rising ? v > cutValue && v <= to : v < cutValue && v >= to;
}

/// The next cut: its u, and whether isovalues lie there (all those equal to the returned scalar).
/// False once the cut at u = 1 has been returned.
bool NextCut(out float u, out float value, out bool surfaces)
{
  float a = cutBounds[cutInterval], b = cutBounds[cutInterval + 1];
  float to = CubicValue(cutCubic, b);
  bool rising = to > cutValue;
  bool found = false;
  value = to;
  for (int k = 0; k < isosurfaceCount; ++k)
  {
    float v = IsoValue(k);
    if (IsovalueAhead(v, to, rising) && (!found || (rising ? v < value : v > value)))
    {
      value = v;
      found = true;
    }
  }
  if (cutAtNodes)
  {
    // The first node beyond the last cut, strictly inside the interval.
    int k = rising ? NodesAtOrBelow(cutValue) : NodesBelow(cutValue) - 1;
    if (k >= 0 && k < nodeCount)
    {
      float v = NodeScalar(k);
      bool inside = rising ? v < to : v > to;
      if (inside && (!found || (rising ? v < value : v > value)))
      {
        value = v;
        found = true;
      }
    }
  }
  surfaces = false;
  for (int k = 0; k < isosurfaceCount; ++k)
    surfaces = surfaces || (found && IsoValue(k) == value);
  if (found)
  {
    u = RootInBracket(cutCubic, value, a, b);
    cutValue = value;
    return true;
  }
  // No cut is left inside the interval: its end, then the next interval.
  u = b;
  value = to;
  cutValue = to;
  ++cutInterval;
  return cutInterval + 1 < cutBoundCount;
}

/// More than the cuts a segment can have (each is a node, an isovalue or one of at most three interval
/// ends): bounds the loops over them.
int CutBound()
{
  return 3 * (nodeCount + isosurfaceCount + 1) + 1;
}

/// Composites, in order, the isosurfaces whose isovalue is `value`, at the segment's parameter u.
void CompositeSurfacesAt(float value, float u)
{
  for (int k = 0; k < isosurfaceCount; ++k)
    if (IsoValue(k) == value)
      CompositeSurface(k, u);
}

/// FIXED_STEPS: constant steps over the cell (the paper's Hexa_CONST); a surface goes in before the
/// first step whose midpoint lies beyond it.
void IntegrateFixedSteps(vec4 c, float len)
{
  StartCuts(c, false);
  float u, value;
  bool surfaces;
  bool more = NextCut(u, value, surfaces), pending = true;
  int most = CutBound();
  float h = len / float(fixedSteps);
  for (int i = 0; i < fixedSteps; ++i)
  {
    float middle = (float(i) + 0.5) / float(fixedSteps);
    for (int n = 0; n < most && pending && u <= middle; ++n)
    {
      if (surfaces)
        CompositeSurfacesAt(value, u);
      pending = more;
      if (more)
        more = NextCut(u, value, surfaces);
    }
    vec4 n = Evaluate(CubicValue(c, middle));
    Composite((1.0 - exp(-n.a * h)) * n.rgb, n.a * h);
  }
  for (int n = 0; n < most && pending; ++n)
  {
    if (surfaces)
      CompositeSurfacesAt(value, u);
    pending = more;
    if (more)
      more = NextCut(u, value, surfaces);
  }
}

/// ACCURATE and FAST: each piece between consecutive cuts, then the surfaces at its far end.
void IntegratePieces(vec4 c, float len)
{
  StartCuts(c, true);
  float u0 = 0.0;
  bool more = true;
  int most = CutBound();
  for (int n = 0; n < most && more; ++n)
  {
    float u1, value;
    bool surfaces;
    more = NextCut(u1, value, surfaces);
    u1 = max(u1, u0);
    if (u1 > u0)
    {
      if (integrationMode == 1)
        IntegratePieceFast(c, len, u0, u1);
      else
        IntegratePieceAccurate(c, len, u0, u1);
    }
    if (surfaces)
      CompositeSurfacesAt(value, u1);
    u0 = u1;
  }
}

/// Integrates the cell's segment of `len` whose scalar is the cubic c(u), u in [0, 1].
void IntegrateCubicSegment(vec4 c, float len)
{
  if (!(len > 0.0))
    return;
  if (integrationMode == 2)
    IntegrateFixedSteps(c, len);
  else
    IntegratePieces(c, len);
}

/// False when the transfer function is transparent over the loaded cell's whole scalar range and no
/// isovalue lies in it (the GPU side of uvCellVisibility.h): such a cell costs this test, and no
/// integration.
bool CellVisible()
{
  float low = scalars[0], high = scalars[0];
  for (int k = 1; k < 8; ++k)
  {
    low = min(low, scalars[k]);
    high = max(high, scalars[k]);
  }
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

/// The field along the segment through the isoparametric map (the frame's coordinates xi0, xi1 are
/// the start): its ends, so the field matches the cell's where the ray crosses faces and is
/// continuous from cell to cell on curved meshes, and two inner points; the cubic through those four
/// exact values (on a parallelepiped the same cubic as the frame's). The ends' coordinates are
/// updated.
vec4 FieldThroughExactEnds(vec3 entryPoint, vec3 exitPoint, inout vec3 xi0, inout vec3 xi1)
{
  vec3 xiNear = InverseTrilinear(mix(entryPoint, exitPoint, 0.25), mix(xi0, xi1, 0.25));
  vec3 xiFar = InverseTrilinear(mix(entryPoint, exitPoint, 0.75), mix(xi0, xi1, 0.75));
  xi0 = InverseTrilinear(entryPoint, xi0);
  xi1 = InverseTrilinear(exitPoint, xi1);
  return CubicThroughSamples(TrilinearAlongSegment(scalars, xi0, xi0).x,
    TrilinearAlongSegment(scalars, xiNear, xiNear).x, TrilinearAlongSegment(scalars, xiFar, xiFar).x,
    TrilinearAlongSegment(scalars, xi1, xi1).x);
}

/// Integrates the loaded cell along the ray from parameter t to segmentEnd, its medium `density`
/// times over.
void IntegrateCell(vec3 origin, vec3 direction, float t, float segmentEnd, float density)
{
  HexahedronFrame frame = MakeHexahedronFrame(points);
  vec3 entryPoint = origin + t * direction, exitPoint = origin + segmentEnd * direction;
  vec3 xi0 = FrameCoordinates(frame, entryPoint);
  vec3 xi1 = FrameCoordinates(frame, exitPoint);
  vec4 field;
#ifdef UV_ALL_PARALLELEPIPEDS
  field = TrilinearAlongSegment(scalars, xi0, xi1); // the frame is the cell's map
#else
  if (cellShape == TETRAHEDRON)
  {
    float f0 = scalars[0] + dot(tetrahedronGradient, entryPoint - points[0]);
    float f1 = scalars[0] + dot(tetrahedronGradient, exitPoint - points[0]);
    field = vec4(f0, f1 - f0, 0.0, 0.0);
  }
  else if ((exactEnds == 1 || cellShape != HEXAHEDRON) && IsCurved(frame))
    field = FieldThroughExactEnds(entryPoint, exitPoint, xi0, xi1); // a collapsed cell is never its frame
  else
    field = TrilinearAlongSegment(scalars, xi0, xi1);
#endif
  segmentXi0 = xi0;
  segmentXi1 = xi1;
  segmentStartPoint = entryPoint;
  segmentEndPoint = exitPoint;
  // Coincident copies add their media: the same as a path `density` times as long.
  IntegrateCubicSegment(field, (segmentEnd - t) * density);
}

/// How many coincident copies `cell` stands for (uvHexahedralMesh.h's CoincidentCellDensities).
float CellDensity(int cell)
{
#ifdef UV_CELL_DENSITIES
  return texelFetch(cellDensities, cell).r;
#else
  return 1.0;
#endif
}

// ---- Traversal

/// Whether a ray along `direction` leaves a cell where its face's normal is `normal` (either
/// orientation; `outward`, the face's mean outward normal, orients it). A collapsed face does not
/// block.
bool Leaves(vec3 normal, vec3 outward, vec3 direction)
{
  if (!(MaxComponent(outward) > 0.0))
    return true;
  return dot(OrientedNormal(normal, outward), direction) > 0.0;
}

/// The ray's hits on face f of the loaded cell (none on a collapsed face), as the exact bilinear
/// patch (or triangle) through its corners, parameterised canonically, with the face's normal at
/// each; a hit where the ray enters the cell instead of leaving it is -3e38 (near an edge the ray can
/// meet, within the edge slack, a face it enters through, just after the entry on the neighbouring
/// face).
void LeavingHits(int f, vec3 origin, vec3 direction, vec3 cellCentre, out float h0, out float h1, out vec3 n0,
  out vec3 n1)
{
  h0 = -3.0e38;
  h1 = -3.0e38;
  n0 = vec3(0.0);
  n1 = vec3(0.0);
  vec3 a, b, c, d;
  int corners = LoadedCellFace(f, a, b, c, d);
  if (corners < 3)
    return;
  int hits = HitFace(origin, direction, a, b, c, d, corners, h0, h1, n0, n1);
  vec3 q[4];
  CyclicFace(f, q);
  vec3 outward = OutwardFaceNormal(q, cellCentre);
  if (!(hits > 0 && Leaves(n0, outward, direction)))
    h0 = -3.0e38;
  if (!(hits > 1 && Leaves(n1, outward, direction)))
    h1 = -3.0e38;
}

vec3 exitNormal; // the face's normal where FindExit found the ray leaving

/// One face plane of FindExitThroughPlanes: face f with corners p0..p3 in cyclic order (a triangle
/// repeats one; a collapsed face has no normal and is passed over).
void PlaneExit(int f, vec3 p0, vec3 p1, vec3 p2, vec3 p3, vec3 cellCentre, vec3 origin, vec3 direction,
  int enterFace, inout float exitT, inout int exitFace)
{
  vec3 normal = SafeNormalize(cross(p2 - p0, p3 - p1));
  vec3 faceMiddle = 0.25 * (p0 + p1 + p2 + p3);
  normal = dot(normal, faceMiddle - cellCentre) < 0.0 ? -normal : normal;
  float along = dot(normal, direction);
  float hit = dot(normal, faceMiddle - origin) / along;
  // Not where the ray enters through the plane, or runs along it.
  if (f != enterFace && along > 0.0 && hit < exitT)
  {
    exitT = hit;
    exitFace = f;
    exitNormal = normal;
  }
}

/// FindExit for a convex cell with planar faces (every cell of the mesh is, UV_ALL_CELLS_CONVEX):
/// where the ray crosses the nearest face plane it heads out of (no patch to solve, no inside test:
/// in a convex cell that crossing is on its face). The ray goes on from there in the neighbour,
/// which does not test that face again, so the two cells need not compute it alike. The faces are
/// written out (uv::HexahedronFaces): corners by constant index, which a CPU driver reads from
/// registers where a loop's index would make it gather from memory.
int FindExitThroughPlanes(vec3 origin, vec3 direction, float t, int enterFace, out float exitT)
{
  exitT = noExit;
  int exitFace = -1;
  vec3 c = CellCentre(points);
  vec3 o = origin, d = direction;
  PlaneExit(0, points[0], points[3], points[2], points[1], c, o, d, enterFace, exitT, exitFace);
  PlaneExit(1, points[4], points[5], points[6], points[7], c, o, d, enterFace, exitT, exitFace);
  PlaneExit(2, points[0], points[1], points[5], points[4], c, o, d, enterFace, exitT, exitFace);
  PlaneExit(3, points[1], points[2], points[6], points[5], c, o, d, enterFace, exitT, exitFace);
  PlaneExit(4, points[2], points[3], points[7], points[6], c, o, d, enterFace, exitT, exitFace);
  PlaneExit(5, points[3], points[0], points[4], points[7], c, o, d, enterFace, exitT, exitFace);
  if (exitFace >= 0)
    exitT = max(exitT, t);
  return exitFace;
}

/// FindExit for any other cell: the exact bilinear faces.
int FindExitThroughPatches(vec3 origin, vec3 direction, float t, int enterFace, out float exitT)
{
  exitT = noExit;
  int exitFace = -1;
  vec3 cellCentre = CellCentre(points);
  // In proportion to the ray parameter and the cell, not absolute: meshes of any size and distance.
  float tolerance = 1e-6 * (abs(t) + 2.0 * length(points[0] - cellCentre));
  for (int pass = 0; pass < 2 && exitFace < 0; ++pass)
  {
    float after = pass == 0 ? t + tolerance : t - tolerance;
    for (int f = 0; f < 6; ++f)
    {
      if (f == enterFace)
        continue;
      float h0, h1;
      vec3 n0, n1;
      LeavingHits(f, origin, direction, cellCentre, h0, h1, n0, n1);
      if (h0 > after && h0 < exitT)
      {
        exitT = h0;
        exitFace = f;
        exitNormal = n0;
      }
      if (h1 > after && h1 < exitT)
      {
        exitT = h1;
        exitFace = f;
        exitNormal = n1;
      }
    }
    if (pass == 1 && exitFace >= 0)
      exitT = max(exitT, t);
  }
  return exitFace;
}

/// The face of the loaded cell (other than `enterFace`) where the ray leaves it nearest beyond t, with
/// that parameter in exitT; -1 when no face claims the ray. Where none does beyond rounding of t, the
/// ray leaves where it entered (a flat cell, whose faces coincide): exitT is then t, no length.
int FindExit(vec3 origin, vec3 direction, float t, int enterFace, out float exitT)
{
  // One of the two per program: a CPU driver runs both sides of a branch that differs between pixels.
#ifdef UV_ALL_CELLS_CONVEX
  return FindExitThroughPlanes(origin, direction, t, enterFace, exitT);
#else
  return FindExitThroughPatches(origin, direction, t, enterFace, exitT);
#endif
}

/// The neighbour (as `across` gives it) across a face of the loaded cell, other than `enterFace`,
/// where the ray leaves within rounding of exitT, or -1. Where the ray leaves through an edge or a
/// vertex, the faces there tie, and FindExit's may be a boundary face (a hole's): the walk goes on
/// through the face with a neighbour instead of stopping at the hole's edge, where the next peel's
/// rasterised entry faces fold and may leave that very pixel out.
int NeighbourAcrossTiedFace(vec3 origin, vec3 direction, float exitT, int enterFace, int across[6])
{
  vec3 cellCentre = CellCentre(points);
  float tolerance = 1e-6 * (abs(exitT) + 2.0 * length(points[0] - cellCentre));
  for (int f = 0; f < 6; ++f)
  {
    if (f == enterFace || across[f] < 0)
      continue;
    float h0, h1;
    vec3 n0, n1;
    LeavingHits(f, origin, direction, cellCentre, h0, h1, n0, n1);
    if (abs(h0 - exitT) <= tolerance || abs(h1 - exitT) <= tolerance)
      return across[f];
  }
  return -1;
}

/// How far `target` lies beyond the plane of the loaded cell's face f, per cell size (-1 for a
/// collapsed face).
float BeyondFace(int f, vec3 target)
{
  vec3 q[4];
  CyclicFace(f, q);
  if (FaceCornerCount(f) < 3)
    return -1.0;
  vec3 normal = OutwardFaceNormal(q, CellCentre(points));
  return dot(SafeNormalize(normal), target - q[0]) / length(points[6] - points[0]);
}

/// One step of the walk towards `target` from the loaded cell `cell`: the neighbour to cross to
/// (neighbour * 8 + its face), or -1 when the walk stops, `inside` telling whether the cell holds
/// the target (or it lies beyond a boundary face). The target's trilinear coordinates decide,
/// consistently with the exact bilinear faces: the face crossed is the one of the most violated
/// coordinate (r = 0: face 5, r = 1: face 3, s = 0: 2, s = 1: 4, t = 0: 0, t = 1: 1), preferring
/// faces with a neighbour.
int StepTowards(vec3 target, int cell, out bool inside)
{
  int across[6];
  CellNeighbours(cell, across);
  float violation[6];
  if (cellFlat)
  {
    // No point lies inside: the faces the target lies beyond, by their cyclic order's sides (the
    // inverse maps are singular).
    for (int f = 0; f < 6; ++f)
      violation[f] = BeyondFace(f, target);
  }
  else if (cellShape == TETRAHEDRON)
  {
    // Barycentric coordinates, exact (the collapsed map's inverse is singular at the apex): each
    // face is violated by the coordinate of the corner opposite it.
    mat3 edges = mat3(points[1] - points[0], points[2] - points[0], points[4] - points[0]);
    vec3 l = inverse(edges) * (target - points[0]);
    float l0 = 1.0 - l.x - l.y - l.z;
    violation = float[6](-l.z, -1.0, -l.y, -l0, -1.0, -l.x);
  }
  else if (cellShape == WEDGE)
  {
    // The wedge's own coordinates (barycentric across, linear along): its map is regular where
    // the collapsed hexahedron's is singular, and its faces are the same bilinear patches.
    vec3 w = InverseWedge(target);
    float r = w.x, s = w.y, t = w.z;
    violation = float[6](-t, t - 1.0, -r, r + s - 1.0, -1.0, -s);
  }
  else if (cellShape == PYRAMID)
  {
    // The four triangles are flat: the target's distance beyond each; the base by the inverse
    // map, regular there (singular only at the apex).
    for (int f = 1; f < 6; ++f)
      violation[f] = BeyondFace(f, target);
    violation[0] = -InverseTrilinear(target, FrameCoordinates(MakeHexahedronFrame(points), target)).z;
  }
  else
  {
    vec3 xi = InverseTrilinear(target, FrameCoordinates(MakeHexahedronFrame(points), target));
    violation = float[6](-xi.z, xi.z - 1.0, -xi.y, xi.x - 1.0, xi.y - 1.0, -xi.x);
  }
  int outside = -1, outsideBoundary = -1;
  float farthest = 1e-6, farthestBoundary = 1e-6;
  for (int f = 0; f < 6; ++f)
  {
    if (FaceCornerCount(f) < 3)
      continue; // collapsed: the others bound the cell
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
  inside = outside < 0 && outsideBoundary < 0;
  return outside < 0 ? -1 : across[outside];
}

/// Walks from the loaded cell towards `target` across the faces it lies outside of, at most `steps`
/// cells; true when it found the cell holding it (then loaded, in `cell`).
bool WalkTowards(vec3 target, inout int cell, int steps)
{
  bool located = false;
  for (int walk = 0; walk < steps; ++walk)
  {
    bool inside;
    int next = StepTowards(target, cell, inside);
    if (next < 0)
    {
      located = inside;
      break;
    }
    cell = next / 8;
    LoadCell(cell);
  }
  return located;
}

/// No face claims the ray at t: it passed within rounding of an edge or a corner into a cell it only
/// touches. Finds the cell holding a point a little ahead (farther on each of three attempts) by
/// walking towards it from `cell`; false when there is none (the ray is outside the mesh). `ahead`
/// is how far past t that point lies: the sliver of path skipped; `attempts`, how many it took.
/// (The loop's bound stays constant: Mesa 26's llvmpipe miscompiled it as a parameter.)
bool Relocate(vec3 origin, vec3 direction, float t, inout int cell, out float ahead, out int attempts)
{
  int startCell = cell;
  bool located = false;
  attempts = 0;
  for (int attempt = 0; attempt < 3 && !located; ++attempt)
  {
    cell = startCell;
    LoadCell(cell);
    ahead = (attempt == 0 ? 1e-3 : (attempt == 1 ? 1e-2 : 5e-2)) * length(points[6] - points[0]);
    located = WalkTowards(origin + (t + ahead) * direction, cell, 32);
    attempts = attempt + 1;
  }
  return located;
}

/// Where the ray leaves the box [low, high] for good (-noExit where it runs beside the box). No
/// division by zero: GLSL leaves its result undefined.
float BoxExit(vec3 origin, vec3 direction, vec3 low, vec3 high)
{
  float exitT = noExit;
  for (int i = 0; i < 3; ++i)
  {
    if (direction[i] != 0.0)
      exitT = min(exitT, max((low[i] - origin[i]) / direction[i], (high[i] - origin[i]) / direction[i]));
    else if (origin[i] < low[i] || origin[i] > high[i])
      exitT = -noExit; // parallel to this slab and outside it
  }
  return exitT;
}

/// Walks the ray from parameter t in `cell` (entered through `enterFace`, -1: none) cell by cell,
/// integrating each, until it is opaque enough, meets opaque geometry (opaqueT), leaves the mesh,
/// or, with skipping, has crossed more than invisibleCellLimit cells outside the visible region in a
/// row (the next peel's entry faces pick it up where the region starts again) or meets an invisible
/// cell past the visible cells' box. Returns where the next peel should pick the ray up (noExit:
/// nowhere).
float Walk(vec3 origin, vec3 direction, float opaqueT, int cell, int enterFace, float t)
{
  float exitParameter = noExit;
#ifdef UV_SKIP_INVISIBLE_CELLS
  int invisibleRun = 0; // cells outside the visible region in a row
  // Past this the ray meets no visible cell again (a box once left is never re-entered): there an
  // invisible cell ends the ray, with no peel left to pick it up.
  float pastVisible = BoxExit(origin, direction, visibleLow, visibleHigh);
#endif
  int faultFrom = -1; // the cell the ray left through a fault face, its far side's cell in `cell`
  // The steps run in the inner loop; a ray to relocate (no face claims it, or it crossed a fault)
  // leaves it for the outer one, so the relocation's code runs once per relocation rather than on
  // every step (a CPU driver runs every branch of a loop body that any pixel of a SIMD group takes).
  int step = 0;
  for (int round = 0; round < maximumCells && step < maximumCells; ++round)
  {
    bool relocate = false;
    for (; step < maximumCells; ++step)
    {
      LoadCell(cell);
#ifdef UV_SKIP_INVISIBLE_CELLS
      // Region membership, not CellVisible: the next peel enters where the region does, and its
      // cells include those beside a cell-data isosurface.
      bool inRegion = ((texelFetch(visibleCells, cell / 32).r >> uint(cell % 32)) & 1u) != 0u;
      invisibleRun = inRegion ? 0 : invisibleRun + 1;
      if (invisibleRun > 0 && t > pastVisible)
        break;
      if (invisibleRun > invisibleCellLimit)
      {
        exitParameter = t;
        stopKind = LEFT_THROUGH_BOUNDARY;
        break;
      }
#endif
      float exitT;
      int exitFace = faultFrom >= 0 ? -1 : FindExit(origin, direction, t, enterFace, exitT);
      if (exitFace < 0)
      {
        relocate = true;
        break;
      }
      float segmentEnd = min(exitT, opaqueT);
#ifdef UV_SKIP_INVISIBLE_CELLS
      // The region's cells are those CellVisible would pass, classified on the CPU from the same
      // ranges: one bit read instead of the transfer function's searches on every step. A cell
      // scalar's region also holds the neighbours of its isosurfaces' cells, which CellVisible sorts.
#ifdef UV_CELL_SCALARS
      bool visible = inRegion && CellVisible();
#else
      bool visible = inRegion;
#endif
#else
      bool visible = CellVisible();
#endif
      if (segmentEnd > t && !cellFlat && visible)
        IntegrateCell(origin, direction, t, segmentEnd, CellDensity(cell));
      if (transmittance <= 1.0 - opacityThreshold || exitT >= opaqueT)
        break;
      int across[6];
      CellNeighbours(cell, across);
      int next = across[exitFace];
      if (next < 0)
        next = NeighbourAcrossTiedFace(origin, direction, exitT, enterFace, across);
      if (next < 0 && across[exitFace] <= -2)
      {
        faultFrom = cell;
        cell = -2 - across[exitFace];
        t = exitT;
        continue;
      }
      if (next < 0)
      {
        exitParameter = exitT; // left the mesh: the next peel looks beyond here
        stopKind = LEFT_THROUGH_BOUNDARY;
        leftCell = cell;
        break;
      }
#ifdef UV_CELL_SCALARS
      if (isosurfaceCount > 0)
        CompositeSurfacesBetweenCells(scalars[0], texelFetch(cellScalars, next / 8).r, origin + exitT * direction,
          exitNormal);
#endif
      cell = next / 8;
      enterFace = next % 8;
      t = exitT;
    }
    if (!relocate)
      break;
    ++step; // the relocation takes this step
    // No face claims the ray, or it crossed a fault: find its cell a little ahead by walking.
    // Across a fault only just ahead: a face that merely lies near the far side's (a thin hole
    // between them) is a gap for the next peel, not medium.
    float ahead;
    int attempts;
    bool located = Relocate(origin, direction, t, cell, ahead, attempts) && (faultFrom < 0 || attempts == 1);
    if (!located && faultFrom >= 0)
    {
      exitParameter = t; // the fault's face is bare here (its throw): the ray left the mesh
      stopKind = LEFT_THROUGH_BOUNDARY;
      leftCell = faultFrom;
      break;
    }
    if (!located)
    {
      exitParameter = t;
      stopKind = LOST;
      break;
    }
#ifdef UV_CELL_SCALARS
    if (faultFrom >= 0 && isosurfaceCount > 0)
      CompositeSurfacesBetweenCells(texelFetch(cellScalars, faultFrom).r, scalars[0], origin + t * direction,
        exitNormal);
#endif
    // Across a fault the faces lie against each other: the ray goes on from where it crossed.
    t += faultFrom >= 0 ? 0.0 : ahead;
    enterFace = -1;
    faultFrom = -1;
  }
  return exitParameter;
}

/// The pixel's ray from where this peel enters the mesh (`start`: ray parameter, boundary face), or
/// from the eye in its cell; returns where the next peel picks it up.
float CastRay(ivec2 pixel, vec4 start, bool fromStartCell)
{
  vec2 ndc = PixelNdc(gl_FragCoord.xy, viewportSize);
  vec3 origin, direction;
  EyeRay(ndc, nearPlane, rayDirection, origin, direction);
  // Opaque geometry ends the ray.
  float depth = texelFetch(opaqueDepth, pixel, 0).r;
  vec4 opaque = clipToModel * vec4(ndc, 2.0 * depth - 1.0, 1.0);
  float opaqueT = depth < 1.0 ? dot(opaque.xyz / opaque.w - origin, direction) : noExit;
  // With the near plane inside the mesh, the first peel starts every ray at its own near-plane point
  // (t = 0), in the cell found by walking there from startCell. Where that walk does not get there,
  // the next peel takes the nearest boundary crossing beyond the point: where the ray enters the
  // mesh, the walk starts there; where it leaves (`start.b`), the point is in the mesh and the ray
  // inside it all the way, and the point's cell is found by walking back to it from that face's
  // cell. (One call each of Walk and WalkTowards: the compiler inlines every call, and each copy
  // costs seconds of compilation on a CPU driver.)
  bool seeking = !fromStartCell && start.b > 0.5;
  ivec4 cellFace = fromStartCell ? ivec4(startCell, -1, 0, 0) : texelFetch(boundaryFaces, int(start.g));
  int cell = cellFace.x;
  if (fromStartCell || seeking)
  {
    LoadCell(cell);
    if (!WalkTowards(origin, cell, nearPlaneSteps))
    {
      stopKind = fromStartCell ? UNLOCATED : LEFT_THROUGH_BOUNDARY;
      return 0.0;
    }
  }
  float t = fromStartCell || seeking ? 0.0 : start.r;
  return Walk(origin, direction, opaqueT, cell, seeking ? -1 : cellFace.y, t);
}

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 before = texelFetch(accumulated, pixel, 0);
  colour = before.rgb;
  transmittance = 1.0 - before.a;
  vec4 start = texelFetch(entry, pixel, 0);
  float exitParameter = noExit; // no further peel
  bool fromStartCell = startCell >= 0;
  if ((start.g >= 0.0 || fromStartCell) && transmittance > 1.0 - opacityThreshold)
    exitParameter = CastRay(pixel, start, fromStartCell);
  gl_FragData[0] = vec4(colour, 1.0 - transmittance);
  // The cell as a float: exact up to 2^24 cells; beyond, a neighbouring number may match, which only
  // skips a face of that cell at the very parameter the walk stopped at.
  gl_FragData[1] = vec4(exitParameter, stopKind, fromStartCell ? -1.0 : start.g, float(leftCell));
}
