// vtkHexahedralRayCastMapper, traversal pass: the loaded cell (its corners, map, faces, neighbours,
// field gradient).
// Part of uvHexahedralTraverseFS.glsl (its marker //UV::HexahedralLoadedCell): reads and writes the
// uniforms and globals declared there.

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
#ifdef UV_TANGLED_CELLS
// Whether it folds over itself (IsTangledCell): the walk then takes its parts and its field as the
// reference does (FindExitThroughParts, IntegrateCell).
bool cellTangled;
#endif
// Its CellHandedness, which orients its faces (0 in a program for convex cells, whose centre lies
// inside every face: OutwardFaceNormal turns faces away from it).
float cellHandedness;

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

/// The corners of `cell` (point ids `ids`) and their scalars.
void CellCorners(int cell, uint ids[8], out vec3 q[8], out float f[8])
{
  for (int k = 0; k < 8; ++k)
  {
    vec4 data = texelFetch(pointData, int(ids[k]));
    q[k] = data.xyz;
    f[k] = data.w;
  }
#ifdef UV_CELL_SCALARS
  // Every corner takes the cell's value: the cubic along the ray is that constant.
  float value = texelFetch(cellScalars, cell).r;
  for (int k = 0; k < 8; ++k)
    f[k] = value;
#endif
}

void LoadCell(int cell)
{
  CellPointIds(cell, cellIds);
  CellCorners(cell, cellIds, points, scalars);
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
  cellHandedness = 0.0;
#else
  cellFlat = IsFlat();
  cellHandedness = CellHandedness(points);
#endif
#ifdef UV_TANGLED_CELLS
  cellTangled = cellShape == HEXAHEDRON && !cellFlat && IsTangledCell(points);
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

/// The loaded cell's isoparametric map at xi.
vec3 MapTrilinear(vec3 xi)
{
  float r = xi.x, s = xi.y, t = xi.z;
  return points[0] + mapB * r + mapC * s + mapD * t + mapE * r * s + mapF * r * t + mapG * s * t + mapH * r * s * t;
}

/// Trilinear coordinates of x in the loaded cell: Newton on the isoparametric map from `xi`.
vec3 InverseTrilinear(vec3 x, vec3 xi)
{
  for (int iteration = 0; iteration < 8; ++iteration)
  {
    vec3 mapped = MapTrilinear(xi);
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

#ifdef UV_TANGLED_CELLS
/// Coordinates of x in the cell with corners q by Newton from its centre, as the reference finds
/// them (uv::SafeguardedNewton): steps limited to half the cell and more iterations than
/// InverseTrilinear's, since Newton converges slowly near a fold, where the Jacobian vanishes.
vec3 InverseFromCentreOf(vec3 q[8], vec3 x)
{
  vec3 xi = vec3(0.5);
  for (int iteration = 0; iteration < 32; ++iteration)
  {
    mat3 jacobian = MapJacobian(q, xi);
    if (IsSingular(jacobian))
      break;
    vec3 step = inverse(jacobian) * (MapPoint(q, xi) - x);
    float longest = MaxComponent(step);
    xi = clamp(xi - (longest > 0.5 ? 0.5 / longest : 1.0) * step, vec3(-0.5), vec3(1.5));
    if (longest < 1e-6)
      break;
  }
  return xi;
}

/// Whether x lies in the cell with corners q (of that size) as the reference judges it
/// (uv::IntersectIsoparametric): its coordinates xi by Newton from the centre map back onto it and
/// lie in the unit cube. Where a folded cell covers x twice, it counts once.
bool ClaimsPointOf(vec3 q[8], float size, vec3 x, out vec3 xi)
{
  xi = InverseFromCentreOf(q, x);
  const float slack = 1e-5;
  return MaxComponent(MapPoint(q, xi) - x) <= 1e-4 * size && all(greaterThanEqual(xi, vec3(-slack))) &&
    all(lessThanEqual(xi, vec3(1.0 + slack)));
}

vec3 InverseFromCentre(vec3 x)
{
  return InverseFromCentreOf(points, x);
}

/// ClaimsPointOf for the loaded cell.
bool ClaimsPoint(vec3 x, float size)
{
  vec3 xi;
  return ClaimsPointOf(points, size, x, xi);
}
#endif

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
