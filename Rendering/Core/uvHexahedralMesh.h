// The connectivity of a hexahedral mesh as vtkHexahedralRayCastMapper's passes walk it, free of VTK:
// face adjacency and boundary faces from the cells' point ids, the cells whose map folds, and the cell
// holding a point (where rays start when the eye is inside the mesh). Cells are 8 point ids each in
// VTK's hexahedron order; points are 4 floats each (recentred position, normalised scalar).
// Tetrahedra, pyramids and wedges are hexahedra with repeated corners (the *AsHexahedron orders):
// a face with a repeated corner is a triangle, one with fewer than three distinct corners no face.
#ifndef uvHexahedralMesh_h
#define uvHexahedralMesh_h

#include "uvHexahedronRay.h"
#include "uvLinearCellSplit.h"
#include "uvCoincidentCells.h"
#include "uvRayCellGeometry.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace uv
{

/// Where a tetrahedron's, a pyramid's and a wedge's points (VTK's orders) go among a hexahedron's 8
/// corners. The hexahedron's trilinear map then is the cell's own isoparametric map -- the
/// tetrahedron's linear one, the pyramid's, the wedge's (barycentric across, linear along) -- so its
/// field is the cell's field, and one walk takes all four. The wedge's base is reversed because
/// VTK's wedge base faces out, a hexahedron's in: every collapsed cell keeps a positive Jacobian.
inline constexpr std::array<int, 8> TetrahedronAsHexahedron = { 0, 1, 2, 2, 3, 3, 3, 3 };
inline constexpr std::array<int, 8> PyramidAsHexahedron = { 0, 1, 2, 3, 4, 4, 4, 4 };
inline constexpr std::array<int, 8> WedgeAsHexahedron = { 0, 2, 1, 1, 3, 5, 4, 4 };

/// A face's key: its distinct point ids ascending, padded with NoPoint (a triangle has one pad).
/// Returns how many are distinct: under 3 the face is collapsed to an edge or a point.
constexpr std::uint32_t NoPoint = std::numeric_limits<std::uint32_t>::max();
inline int FaceKey(const std::uint32_t corners[4], std::array<std::uint32_t, 4>& key)
{
  key = { corners[0], corners[1], corners[2], corners[3] };
  std::sort(key.begin(), key.end());
  const int distinct = static_cast<int>(std::unique(key.begin(), key.end()) - key.begin());
  std::fill(key.begin() + distinct, key.end(), NoPoint);
  return distinct;
}

/// The corners of hexahedron `cell` in double.
inline void HexahedronCornerPoints(
  const std::vector<std::uint32_t>& cellPoints, const std::vector<float>& pointData, std::size_t cell, glm::dvec3 p[8])
{
  for (int k = 0; k < 8; ++k)
  {
    const float* x = &pointData[4 * static_cast<std::size_t>(cellPoints[8 * cell + k])];
    p[k] = glm::dvec3(x[0], x[1], x[2]);
  }
}

/// A face by its sorted point ids, and which cell's local face it is (cell * 8 + face).
struct HexahedronFaceRecord
{
  std::array<std::uint32_t, 4> Key;
  std::uint32_t CellFace;
  bool operator<(const HexahedronFaceRecord& other) const
  {
    return this->Key < other.Key || (this->Key == other.Key && this->CellFace < other.CellFace);
  }
};

struct HexahedralFaces
{
  std::vector<std::int32_t> Neighbours; // 8 per cell (6 used): neighbour * 8 + its local face, or -1
  std::vector<std::int32_t> Boundary;   // 4 per boundary face: cell, local face, 0, 0
};

/// Per point, the smallest id of the points at exactly its position (points are 4 floats each): a
/// mesh that repeats its points along internal faces (as some writers do) is still joined across
/// them. `sort(begin, end, less)` orders point ids.
template <typename Sort>
std::vector<std::uint32_t> CoincidentPointRepresentatives(const std::vector<float>& pointData, Sort&& sort)
{
  const std::size_t pointCount = pointData.size() / 4;
  std::vector<std::uint32_t> order(pointCount), representative(pointCount);
  for (std::size_t p = 0; p < pointCount; ++p)
    order[p] = static_cast<std::uint32_t>(p);
  auto position = [&pointData](std::uint32_t p) {
    return std::array<float, 3>{ pointData[4 * p], pointData[4 * p + 1], pointData[4 * p + 2] };
  };
  sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return position(a) < position(b) || (position(a) == position(b) && a < b);
  });
  for (std::size_t i = 0; i < pointCount;)
  {
    std::size_t j = i + 1;
    while (j < pointCount && position(order[j]) == position(order[i]))
      ++j;
    for (std::size_t k = i; k < j; ++k)
      representative[order[k]] = order[i];
    i = j;
  }
  return representative;
}

/// Face `cellFace` (cell * 8 + local face) keyed by its corners, compared through `samePoint` (empty:
/// by id); a collapsed face (FaceKey) is keyed all NoPoint.
inline HexahedronFaceRecord MakeFaceRecord(
  const std::vector<std::uint32_t>& cellPoints, const std::vector<std::uint32_t>& samePoint, std::uint32_t cellFace)
{
  HexahedronFaceRecord record;
  std::uint32_t corners[4];
  for (int k = 0; k < 4; ++k)
  {
    const std::uint32_t point = cellPoints[8 * (cellFace / 8) + HexahedronFaces[cellFace % 8].Vertices[k]];
    corners[k] = samePoint.empty() ? point : samePoint[point];
  }
  if (FaceKey(corners, record.Key) < 3)
    record.Key.fill(NoPoint);
  record.CellFace = cellFace;
  return record;
}

/// Marks collapsed (all NoPoint) the six faces of a cell that has no volume by its point ids: fewer
/// than four distinct corners, or two faces on the same points (a layer pinched out, its top
/// nodes merged with its bottom ones). Such a cell bounds nothing, so the cells above and below it
/// share their face as two cells, not four.
inline void CollapseFacesOfFlatCell(HexahedronFaceRecord* faces)
{
  std::array<std::uint32_t, 24> corners;
  for (int f = 0; f < 6; ++f)
    std::copy(faces[f].Key.begin(), faces[f].Key.end(), corners.begin() + 4 * f);
  std::sort(corners.begin(), corners.end());
  const auto distinct = std::unique(corners.begin(), corners.end()) - corners.begin();
  bool flat = distinct - (corners[distinct - 1] == NoPoint ? 1 : 0) < 4;
  for (int f = 0; f < 6 && !flat; ++f)
    for (int g = f + 1; g < 6 && !flat; ++g)
      flat = faces[f].Key[0] != NoPoint && faces[f].Key == faces[g].Key;
  if (flat)
    for (int f = 0; f < 6; ++f)
      faces[f].Key.fill(NoPoint);
}

/// Joins the faces (sorted) whose key exactly two of them share, in `neighbours`; returns the others,
/// but for the collapsed ones, which are neither joined nor boundary.
inline std::vector<HexahedronFaceRecord> JoinFacePairs(
  const std::vector<HexahedronFaceRecord>& faces, std::vector<std::int32_t>& neighbours)
{
  std::vector<HexahedronFaceRecord> unmatched;
  for (std::size_t i = 0; i < faces.size();)
  {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].Key == faces[i].Key)
      ++j;
    if (faces[i].Key[0] == NoPoint)
      break; // the collapsed faces, all at the end
    if (j - i == 2)
    {
      neighbours[faces[i].CellFace] = static_cast<std::int32_t>(faces[i + 1].CellFace);
      neighbours[faces[i + 1].CellFace] = static_cast<std::int32_t>(faces[i].CellFace);
    }
    else
      unmatched.insert(unmatched.end(), faces.begin() + static_cast<std::ptrdiff_t>(i),
        faces.begin() + static_cast<std::ptrdiff_t>(j));
    i = j;
  }
  return unmatched;
}

/// Which cells share each face (uv::HexahedronFaces numbering): a face two cells share joins them;
/// any other (a boundary face, or a non-manifold one, every copy) is a boundary face; a collapsed
/// face (FaceKey), and every face of a cell flat by its ids (CollapseFacesOfFlatCell), is neither,
/// and has no neighbour. Faces are matched by point id first; those left
/// over, by the points' `samePoint` representatives (CoincidentPointRepresentatives; empty: none), so
/// a mesh repeating its points along internal faces is joined across them. By id first: a flat
/// layer of cells (its points moved onto the layer below) would otherwise make four faces of each
/// key, non-manifold, and cut the mesh there. Faces are matched by sorting them by their sorted
/// point ids: `parallelFor(count, function(begin, end))` lists them, `sort(begin, end)` orders
/// HexahedronFaceRecords, and `progress(fraction)` is told 0.5 once they are listed and 1 once
/// sorted.
template <typename ParallelFor, typename Sort, typename Progress>
HexahedralFaces MakeHexahedralFaces(const std::vector<std::uint32_t>& cellPoints,
  const std::vector<std::uint32_t>& samePoint, ParallelFor&& parallelFor, Sort&& sort, Progress&& progress)
{
  const std::size_t cellCount = cellPoints.size() / 8;
  std::vector<HexahedronFaceRecord> faces(6 * cellCount);
  parallelFor(cellCount, [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c)
    {
      for (int f = 0; f < 6; ++f)
        faces[6 * c + f] = MakeFaceRecord(cellPoints, {}, static_cast<std::uint32_t>(8 * c + f));
      CollapseFacesOfFlatCell(&faces[6 * c]);
    }
  });
  progress(0.5);
  sort(faces.begin(), faces.end());
  HexahedralFaces result;
  result.Neighbours.assign(8 * cellCount, -1);
  std::vector<HexahedronFaceRecord> unmatched = JoinFacePairs(faces, result.Neighbours);
  if (!samePoint.empty())
  {
    for (HexahedronFaceRecord& record : unmatched)
      record = MakeFaceRecord(cellPoints, samePoint, record.CellFace);
    sort(unmatched.begin(), unmatched.end());
    unmatched = JoinFacePairs(unmatched, result.Neighbours);
  }
  progress(1.0);
  for (const HexahedronFaceRecord& record : unmatched)
    result.Boundary.insert(result.Boundary.end(),
      { static_cast<std::int32_t>(record.CellFace / 8), static_cast<std::int32_t>(record.CellFace % 8), 0, 0 });
  return result;
}

/// For a cell scalar's isosurfaces on a tetrahedral mesh: per tetrahedron the value of the
/// neighbour across the face opposite each corner (its own where there is none, so no surface lies
/// on a boundary face), and its scalar range widened to them (a cell is drawn for the surfaces on
/// its faces too).
struct TetrahedronFaceNeighbours
{
  std::vector<float> Values; // 4 per tetrahedron, by opposite corner
  std::vector<float> Low, High;
};

/// TetrahedronFaceNeighbours of 4 point ids per tetrahedron (`tetrahedronPoints`), each with the
/// constant value `values`. The faces are matched as MakeHexahedralFaces matches a collapsed
/// hexahedron's; `parallelFor` and `sort` as there.
template <typename ParallelFor, typename Sort>
TetrahedronFaceNeighbours MakeTetrahedronFaceNeighbours(const std::vector<std::uint32_t>& tetrahedronPoints,
  const std::vector<float>& values, ParallelFor&& parallelFor, Sort&& sort)
{
  const std::size_t count = values.size();
  std::vector<std::uint32_t> collapsed(8 * count);
  parallelFor(count, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
      for (int k = 0; k < 8; ++k)
        collapsed[8 * t + k] = tetrahedronPoints[4 * t + TetrahedronAsHexahedron[k]];
  });
  const HexahedralFaces faces = MakeHexahedralFaces(collapsed, {}, parallelFor, sort, [](double) {});
  // The collapsed hexahedron's face opposite each tetrahedron corner (TetrahedronAsHexahedron).
  constexpr int oppositeFace[4] = { 3, 5, 2, 0 };
  TetrahedronFaceNeighbours result;
  result.Values.resize(4 * count);
  result.Low.resize(count);
  result.High.resize(count);
  parallelFor(count, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
    {
      float low = values[t], high = values[t];
      for (int k = 0; k < 4; ++k)
      {
        const std::int32_t neighbour = faces.Neighbours[8 * t + oppositeFace[k]];
        const float across = neighbour < 0 ? values[t] : values[static_cast<std::size_t>(neighbour / 8)];
        result.Values[4 * t + k] = across;
        low = std::min(low, across);
        high = std::max(high, across);
      }
      result.Low[t] = low;
      result.High[t] = high;
    }
  });
  return result;
}

/// `classify(corners, ids)` of every cell, its corners in double and its 8 point ids; `parallelFor`
/// as above.
template <typename ParallelFor, typename Classify>
std::vector<unsigned char> ClassifyHexahedra(const std::vector<std::uint32_t>& cellPoints,
  const std::vector<float>& pointData, ParallelFor&& parallelFor, Classify&& classify)
{
  const std::size_t cellCount = cellPoints.size() / 8;
  std::vector<unsigned char> kind(cellCount, 0);
  parallelFor(cellCount, [&](std::size_t begin, std::size_t end) {
    glm::dvec3 p[8];
    for (std::size_t c = begin; c < end; ++c)
    {
      HexahedronCornerPoints(cellPoints, pointData, c, p);
      kind[c] = classify(p, &cellPoints[8 * c]);
    }
  });
  return kind;
}

/// How many cells fold over themselves (uv::IsTangledHexahedron); `parallelFor` as above.
template <typename ParallelFor>
std::size_t CountTangledHexahedra(
  const std::vector<std::uint32_t>& cellPoints, const std::vector<float>& pointData, ParallelFor&& parallelFor)
{
  const std::vector<unsigned char> tangled = ClassifyHexahedra(cellPoints, pointData, parallelFor,
    [](const glm::dvec3* p, const std::uint32_t*) { return static_cast<unsigned char>(IsTangledHexahedron(p)); });
  return static_cast<std::size_t>(std::count(tangled.begin(), tangled.end(), 1));
}

/// Whether the cell with corners p (collapsed ones repeated, as `ids` tell) is convex with planar
/// faces, every corner within `1e-6` of its size of every face's plane through the face's centroid
/// (its normal the cross product of its diagonals, which a triangle stored as a quad with a repeated
/// corner also has) and its centre inside every face by more than 1e-3 of its size (a volume, not
/// a sliver). A ray leaves such a cell through the nearest face plane it heads out of.
inline bool IsConvexWithPlanarFaces(const glm::dvec3 p[8], const std::uint32_t ids[8])
{
  glm::dvec3 low = p[0], high = p[0], centre(0.0);
  for (int k = 0; k < 8; ++k)
  {
    low = glm::min(low, p[k]);
    high = glm::max(high, p[k]);
    centre += 0.125 * p[k];
  }
  const double size = std::max({ high.x - low.x, high.y - low.y, high.z - low.z });
  if (!(size > 0.0))
    return false;
  for (int f = 0; f < 6; ++f)
  {
    const int* corner = HexahedronFaces[f].Vertices.data();
    std::uint32_t faceIds[4] = { ids[corner[0]], ids[corner[1]], ids[corner[2]], ids[corner[3]] };
    std::array<std::uint32_t, 4> key;
    if (FaceKey(faceIds, key) < 3)
      continue; // collapsed: the other faces bound the cell
    const glm::dvec3 normal = glm::cross(p[corner[2]] - p[corner[0]], p[corner[3]] - p[corner[1]]);
    const double length = glm::length(normal);
    if (!(length > 0.0))
      return false;
    const glm::dvec3 centroid = 0.25 * (p[corner[0]] + p[corner[1]] + p[corner[2]] + p[corner[3]]);
    glm::dvec3 outward = normal / length;
    const double centreDepth = glm::dot(outward, centroid - centre);
    if (!(std::abs(centreDepth) > 1e-3 * size))
      return false;
    outward = centreDepth < 0.0 ? -outward : outward;
    for (int k = 0; k < 4; ++k)
    {
      if (std::abs(glm::dot(outward, p[corner[k]] - centroid)) > 1e-6 * size)
        return false;
    }
    for (int k = 0; k < 8; ++k)
    {
      if (glm::dot(outward, p[k] - centroid) > 1e-6 * size)
        return false;
    }
  }
  return true;
}

/// Whether the cell with corners p is a parallelepiped: eight distinct corners, its trilinear map's
/// bilinear and trilinear terms within 1e-6 of its edges' size (its affine frame is then its map).
inline bool IsParallelepiped(const glm::dvec3 p[8], const std::uint32_t ids[8])
{
  std::array<std::uint32_t, 8> sorted;
  std::copy(ids, ids + 8, sorted.begin());
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    return false;
  const double size = glm::length(p[1] - p[0]) + glm::length(p[3] - p[0]) + glm::length(p[4] - p[0]);
  const glm::dvec3 twists[4] = { p[0] - p[1] + p[2] - p[3], p[0] - p[1] - p[4] + p[5], p[0] - p[3] - p[4] + p[7],
    -p[0] + p[1] - p[2] + p[3] + p[4] - p[5] + p[6] - p[7] };
  for (const glm::dvec3& twist : twists)
  {
    if (!(glm::length(twist) <= 1e-6 * size))
      return false;
  }
  return true;
}

/// What every cell of a mesh is, from the most general to the most particular: the walk compiles
/// the code of this kind alone (a CPU driver runs every branch some pixel of a SIMD group takes).
enum class CellGeometry
{
  Any = 0,
  ConvexPlanar = 1,   // IsConvexWithPlanarFaces: left through face planes
  Parallelepipeds = 2 // also IsParallelepiped: no collapsed corner, the affine frame exact
};

/// The CellGeometry every cell of the mesh has; `parallelFor` as above.
template <typename ParallelFor>
CellGeometry MeshCellGeometry(
  const std::vector<std::uint32_t>& cellPoints, const std::vector<float>& pointData, ParallelFor&& parallelFor)
{
  const std::vector<unsigned char> kind =
    ClassifyHexahedra(cellPoints, pointData, parallelFor, [](const glm::dvec3* p, const std::uint32_t* ids) {
      return static_cast<unsigned char>(!IsConvexWithPlanarFaces(p, ids) ? 0 : (IsParallelepiped(p, ids) ? 2 : 1));
    });
  if (kind.empty())
    return CellGeometry::Any;
  return static_cast<CellGeometry>(*std::min_element(kind.begin(), kind.end()));
}

/// The first cell holding `x` (by its bounding box, then the isoparametric inverse), or -1.
inline int HexahedronHolding(
  const std::vector<std::uint32_t>& cellPoints, const std::vector<float>& pointData, const glm::dvec3& x)
{
  const std::size_t cellCount = cellPoints.size() / 8;
  for (std::size_t c = 0; c < cellCount; ++c)
  {
    glm::dvec3 p[8];
    HexahedronCornerPoints(cellPoints, pointData, c, p);
    glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
    for (int k = 0; k < 8; ++k)
    {
      low = glm::min(low, p[k]);
      high = glm::max(high, p[k]);
    }
    if (glm::any(glm::lessThan(x, low)) || glm::any(glm::greaterThan(x, high)))
      continue;
    glm::dvec3 xi(0.5);
    if (InverseTrilinear(p, x, xi) && InUnitCube(xi, 1e-9))
      return static_cast<int>(c);
  }
  return -1;
}

} // namespace uv

#endif
