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
// the others' go through the isoparametric inverse; their triangular faces are flat. Faces are exact
// bilinear patches, parameterised the same way by every cell (uvBilinearFaceLib.glsl): the exit
// found in one cell is the entry of the next.
//
// Isosurfaces are further cuts: where the cubic crosses an isovalue the surface's colour is
// composited, Phong-lit with the exact gradient of the cell's trilinear field there, or with
// UV_VERTEX_GRADIENTS the vertex gradients interpolated by the cell's trilinear weights there
// (smooth across cells). For a cell scalar they are the faces between cells on either side of the
// value, lit with the face's normal.
//
// This file holds the pass's uniforms, its state and the walk; the sections it names below
// (uvHexahedral*Lib.glsl) hold the loaded cell, the segment, its cuts and the cell exits.
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

//UV::HexahedralLoadedCell

//UV::HexahedralSegment

//UV::HexahedralCuts

//UV::HexahedralExit

#ifdef UV_TANGLED_CELLS
//UV::HexahedralOverlap
#endif


#ifdef UV_SKIP_INVISIBLE_CELLS
/// Whether `cell` is in the visible region (the cells whose entry faces the next peel draws).
bool InVisibleRegion(int cell)
{
  return ((texelFetch(visibleCells, cell / 32).r >> uint(cell % 32)) & 1u) != 0u;
}

/// Whether the loaded cell, in the visible region or not, adds to the ray. The region's cells are
/// those CellVisible would pass, classified on the CPU from the same ranges: one bit read instead of
/// the transfer function's searches on every step. A cell scalar's region also holds the neighbours
/// of its isosurfaces' cells, which CellVisible sorts.
bool LoadedCellVisible(bool inRegion)
{
#ifdef UV_CELL_SCALARS
  return inRegion && CellVisible();
#else
  return inRegion;
#endif
}
#endif

/// The walk's way on where no face claimed the ray at t, or it crossed a fault from `faultFrom`
/// (its far side's cell in `cell`): finds the ray's cell a little ahead by walking and moves t, the
/// cell and the entry face there. False when the ray ends here (exitParameter and stopKind set).
bool GoOnFromRelocation(vec3 origin, vec3 direction, inout float t, inout int cell, inout int enterFace,
  inout int faultFrom, inout float exitParameter)
{
  // No face claims the ray, or it crossed a fault: find its cell a little ahead by walking.
  // Across a fault only just ahead: a face that merely lies near the far side's (a thin hole
  // between them) is a gap for the next peel, not medium.
  float ahead;
  int attempts;
  int from = cell;
  bool located = Relocate(origin, direction, t, cell, ahead, attempts) && (faultFrom < 0 || attempts == 1);
#ifdef UV_TANGLED_CELLS
  if (!located && faultFrom < 0)
  {
    cell = from;
    located = PartnerAhead(origin, direction, t, cell, ahead);
  }
#endif
  if (!located && faultFrom >= 0)
  {
    exitParameter = t; // the fault's face is bare here (its throw): the ray left the mesh
    stopKind = LEFT_THROUGH_BOUNDARY;
    leftCell = faultFrom;
    return false;
  }
  if (!located)
  {
    exitParameter = t;
    stopKind = LOST;
    return false;
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
  return true;
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
      bool inRegion = InVisibleRegion(cell);
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
      bool visible = LoadedCellVisible(inRegion);
#else
      bool visible = CellVisible();
#endif
      float segmentStart = t;
      bool overlapped = false;
#ifdef UV_TANGLED_CELLS
      segmentStart = cellTangled ? partStart : t;
      // Where folded cells overlap others the media add, as in the reference. Isosurfaces keep the
      // walk's one medium: the midpoint steps do not find them.
      overlapped = isosurfaceCount == 0 && segmentEnd > t && !cellFlat &&
        IntegrateOverlapping(origin, direction, t, segmentEnd, cell);
#endif
      if (!overlapped && segmentEnd > segmentStart && !cellFlat && visible)
        IntegrateCell(origin, direction, segmentStart, segmentEnd, CellDensity(cell));
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
#ifdef UV_TANGLED_CELLS
      // A fold may have pushed a partner of this cell through the boundary here: the ray goes on in it.
      float ahead;
      int partner = cell;
      if (next < 0 && PartnerAhead(origin, direction, exitT, partner, ahead))
      {
        cell = partner;
        enterFace = -1;
        t = exitT;
        continue;
      }
#endif
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
    if (!GoOnFromRelocation(origin, direction, t, cell, enterFace, faultFrom, exitParameter))
      break;
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
