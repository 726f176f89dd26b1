// vtkHexahedralRayCastMapper, traversal pass: the segment cut at monotonic ends, isovalues and nodes, and one
// cell integrated along the ray.
// Part of uvHexahedralTraverseFS.glsl (its marker //UV::HexahedralCuts): reads and writes the
// uniforms and globals declared there.

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
#ifdef UV_TANGLED_CELLS
  // A folded cell maps some points from two places: Newton from the centre picks the reference's.
  xi0 = cellTangled ? InverseFromCentre(entryPoint) : xi0;
  xi1 = cellTangled ? InverseFromCentre(exitPoint) : xi1;
#endif
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
