// vtkHexahedralRayCastMapper, traversal pass: where the ray leaves the loaded cell, the neighbour it
// crosses to, and the walk back onto the ray when it is lost at an edge.
// Part of uvHexahedralTraverseFS.glsl (its marker //UV::HexahedralExit): reads and writes the
// uniforms and globals declared there.

// ---- Traversal

/// Whether a ray along `direction` leaves a cell where its face's normal is `normal` (the face's
/// canonical orientation; OutwardNormalAt turns it outward by `centreNormal` and `outward`, the face's
/// mean outward normal). A collapsed face does not block.
bool Leaves(vec3 normal, vec3 centreNormal, vec3 outward, vec3 direction)
{
  if (!(MaxComponent(outward) > 0.0))
    return true;
  return dot(OutwardNormalAt(normal, centreNormal, outward), direction) > 0.0;
}

/// The ray's hits on face f of the loaded cell (none on a collapsed face), as the exact bilinear
/// patch (or triangle) through its corners, parameterised canonically, with the face's normal at
/// each; a hit where the ray enters the cell instead of leaving it is -3e38 (near an edge the ray can
/// meet, within the edge slack, a face it enters through, just after the entry on the neighbouring
/// face; a curved face can be entered on one part and left on another).
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
  vec3 outward = OutwardFaceNormal(q, cellCentre, cellHandedness);
  vec3 centreNormal = PatchNormalAt(a, b, c, d, vec2(0.5));
  if (!(hits > 0 && Leaves(n0, centreNormal, outward, direction)))
    h0 = -3.0e38;
  if (!(hits > 1 && Leaves(n1, centreNormal, outward, direction)))
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
      // The entry face only beyond the entry: a curved face can be entered and left again.
      float beyond = f == enterFace ? t + tolerance : after;
      float h0, h1;
      vec3 n0, n1;
      LeavingHits(f, origin, direction, cellCentre, h0, h1, n0, n1);
      if (h0 > beyond && h0 < exitT)
      {
        exitT = h0;
        exitFace = f;
        exitNormal = n0;
      }
      if (h1 > beyond && h1 < exitT)
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

#ifdef UV_TANGLED_CELLS
float partStart; // where FindExitThroughParts found the folded cell's part to start

/// The index of the smallest of `hits` beyond `after`, or -1.
int NextHit(float hits[12], float after)
{
  int next = -1;
  for (int k = 0; k < 12; ++k)
  {
    if (hits[k] > after && hits[k] < noExit && (next < 0 || hits[k] < hits[next]))
      next = k;
  }
  return next;
}

/// FindExit for a folded cell (IsTangledCell), whose faces' normals do not tell entering from leaving:
/// its faces' hits beyond t in order, each stretch between two of them the cell's where ClaimsPoint
/// holds at its middle, as the reference takes a cell's parts. The cell's part starts at t, or at the
/// first hit after which a stretch is the cell's (partStart: where a fold's face only seemed to
/// enter it), and the ray leaves it at the first hit after that where a stretch is not, or at the
/// last. Each face's two hits have their own slots, written by constant indices only: softpipe
/// writes an array element at the index the first pixel of the 2x2 quad has (HitPatchAt), and where
/// that pixel is done with its walk, even this loop's counter is stale there.
int FindExitThroughParts(vec3 origin, vec3 direction, float t, out float exitT)
{
  float size = MaxComponent(points[6] - points[0]) + MaxComponent(points[7] - points[1]);
  float tolerance = 1e-6 * (abs(t) + size);
  float hits[12];
  vec3 normals[12];
  for (int f = 0; f < 6; ++f)
  {
    vec3 a, b, c, d;
    float h0 = noExit, h1 = noExit;
    vec3 n0 = vec3(0.0), n1 = vec3(0.0);
    int corners = LoadedCellFace(f, a, b, c, d);
    int count = corners < 3 ? 0 : HitFace(origin, direction, a, b, c, d, corners, h0, h1, n0, n1);
    h0 = count > 0 && h0 > t + tolerance ? h0 : noExit;
    h1 = count > 1 && h1 > t + tolerance ? h1 : noExit;
    for (int j = 0; j < 6; ++j) // constant indices once unrolled
    {
      hits[2 * j] = j == f ? h0 : hits[2 * j];
      hits[2 * j + 1] = j == f ? h1 : hits[2 * j + 1];
      normals[2 * j] = j == f ? n0 : normals[2 * j];
      normals[2 * j + 1] = j == f ? n1 : normals[2 * j + 1];
    }
  }
  exitT = noExit;
  int exitFace = -1;
  int first = NextHit(hits, t);
  bool inside = first >= 0 && ClaimsPoint(origin + 0.5 * (t + hits[first]) * direction, size);
  partStart = inside ? t : noExit;
  float after = t;
  for (int part = 0; part < 12; ++part)
  {
    int k = NextHit(hits, after);
    if (k < 0)
      break;
    exitT = hits[k];
    exitFace = k / 2;
    exitNormal = normals[k];
    int following = NextHit(hits, exitT);
    if (following < 0)
      break;
    bool claimed = hits[following] - exitT <= tolerance ? inside
                                                        : ClaimsPoint(origin + 0.5 * (exitT + hits[following]) * direction, size);
    if (inside && !claimed)
      break;
    partStart = !inside && claimed ? exitT : partStart;
    inside = claimed;
    after = exitT;
  }
  partStart = min(partStart, exitT); // nothing of the cell on this ray: no length
  return exitFace;
}
#endif

/// The face of the loaded cell where the ray leaves it nearest beyond t (the entry face `enterFace`
/// only beyond rounding of t, or not at all through planes), with that parameter in exitT; -1 when
/// no face claims the ray. Where none does beyond rounding of t, the ray leaves where it entered (a
/// flat cell, whose faces coincide): exitT is then t, no length.
int FindExit(vec3 origin, vec3 direction, float t, int enterFace, out float exitT)
{
  // One of the two per program: a CPU driver runs both sides of a branch that differs between pixels.
#ifdef UV_ALL_CELLS_CONVEX
  return FindExitThroughPlanes(origin, direction, t, enterFace, exitT);
#else
#ifdef UV_TANGLED_CELLS
  if (cellTangled)
    return FindExitThroughParts(origin, direction, t, exitT);
#endif
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
  vec3 normal = OutwardFaceNormal(q, CellCentre(points), cellHandedness);
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
