// vtkHexahedralRayCastMapper, traversal pass: where folded cells overlap other cells, the media of
// every cell that claims a point of the walk's segment, added as the reference's optical model adds
// them (uv::IntegrateOverlap). Which cells overlap is found once on the CPU (uvOverlappingCells.h).
// Part of uvHexahedralTraverseFS.glsl (its marker //UV::HexahedralOverlap), in programs with
// UV_TANGLED_CELLS only: reads the uniforms and globals declared there.

// Per cell, where its partners start and (the next cell's entry) end in this buffer; then the
// partners (uv::OverlapPartners::Packed).
uniform isamplerBuffer overlapPartners;

const int overlapSteps = 32;  // midpoint steps over a segment that partners overlap
const int partnersRead = 16;  // a cell's partners read at most

/// Whether `cell` claims x (the reference's rule, ClaimsPointOf); its coordinates there, and its
/// corners' scalars.
bool CellClaims(int cell, vec3 x, out vec3 xi, out float f[8])
{
  uint ids[8];
  vec3 q[8];
  CellPointIds(cell, ids);
  CellCorners(cell, ids, q, f);
  vec3 low = q[0], high = q[0];
  for (int k = 1; k < 8; ++k)
  {
    low = min(low, q[k]);
    high = max(high, q[k]);
  }
  xi = vec3(0.5);
  return all(greaterThanEqual(x, low)) && all(lessThanEqual(x, high)) &&
    ClaimsPointOf(q, MaxComponent(high - low), x, xi);
}

/// The medium `cell` adds at x, its density times over: (extinction times colour, extinction);
/// nothing where it does not claim x.
vec4 CellMediumAt(int cell, vec3 x)
{
  vec3 xi;
  float f[8];
  if (!CellClaims(cell, x, xi, f))
    return vec4(0.0);
  vec4 node = Evaluate(TrilinearAlongSegment(f, xi, xi).x);
  return CellDensity(cell) * node.a * vec4(node.rgb, 1.0);
}

/// Where the walk found no cell ahead of t from `cell`, a partner of it may hold the ray there: a
/// folded cell's fold can hide a stretch of the ray from its faces (a fold pushed into the next
/// layer), with the next layer's cell reaching through it. The partner that claims a point a little
/// ahead (farther on each of three attempts, as Relocate), loaded in `cell`; false if none.
bool PartnerAhead(vec3 origin, vec3 direction, float t, inout int cell, out float ahead)
{
  int first = texelFetch(overlapPartners, cell).r;
  int end = min(texelFetch(overlapPartners, cell + 1).r, first + partnersRead);
  ahead = 0.0;
  if (first == end)
    return false;
  LoadCell(cell);
  float size = length(points[6] - points[0]);
  for (int attempt = 0; attempt < 3; ++attempt)
  {
    ahead = (attempt == 0 ? 1e-3 : (attempt == 1 ? 1e-2 : 5e-2)) * size;
    for (int k = first; k < end; ++k)
    {
      int partner = texelFetch(overlapPartners, k).r;
      vec3 xi;
      float f[8];
      if (CellClaims(partner, origin + (t + ahead) * direction, xi, f))
      {
        cell = partner;
        LoadCell(cell);
        return true;
      }
    }
  }
  return false;
}

/// Whether the ray's stretch [t0, t1] meets the box of `cell`'s corners.
bool SegmentMeetsCellBox(vec3 origin, vec3 direction, float t0, float t1, int cell)
{
  uint ids[8];
  CellPointIds(cell, ids);
  vec3 low = PointPosition(ids[0]), high = low;
  for (int k = 1; k < 8; ++k)
  {
    low = min(low, PointPosition(ids[k]));
    high = max(high, PointPosition(ids[k]));
  }
  float enter = t0, leave = t1;
  for (int i = 0; i < 3; ++i)
  {
    if (direction[i] != 0.0)
    {
      float a = (low[i] - origin[i]) / direction[i], b = (high[i] - origin[i]) / direction[i];
      enter = max(enter, min(a, b));
      leave = min(leave, max(a, b));
    }
    else if (origin[i] < low[i] || origin[i] > high[i])
      return false;
  }
  return enter <= leave;
}

/// Where a partner of the loaded cell `cell` may overlap its stretch [t0, t1] of the ray (the walk's
/// segment, from where it entered), integrates the stretch by midpoint steps of the added media: the
/// cell's own where it claims the point (a folded cell's part may start later), each partner's
/// where it does. False, with nothing done, where no partner's box meets the stretch.
bool IntegrateOverlapping(vec3 origin, vec3 direction, float t0, float t1, int cell)
{
  int first = texelFetch(overlapPartners, cell).r;
  int end = min(texelFetch(overlapPartners, cell + 1).r, first + partnersRead);
  bool met = false;
  for (int k = first; k < end && !met; ++k)
    met = SegmentMeetsCellBox(origin, direction, t0, t1, texelFetch(overlapPartners, k).r);
  if (!met)
    return false;
  float h = (t1 - t0) / float(overlapSteps);
  for (int i = 0; i < overlapSteps && transmittance > 1.0 - opacityThreshold; ++i)
  {
    vec3 x = origin + (t0 + (float(i) + 0.5) * h) * direction;
    vec4 medium = vec4(0.0);
    for (int k = first - 1; k < end; ++k) // first - 1: the cell itself
      medium += CellMediumAt(k < first ? cell : texelFetch(overlapPartners, k).r, x);
    if (medium.a > 0.0)
      Composite((1.0 - exp(-medium.a * h)) / medium.a * medium.rgb, medium.a * h);
  }
  return true;
}
