// Faces that lie against each other without sharing their corners, free of VTK: across a fault of a
// reservoir grid (the columns on one side moved by the throw, the nodes on the fault written once per
// side), or where two blocks of a mesh meet with different cell sizes. Neither face has a neighbour
// by its point ids, yet a ray leaving through one goes on in a cell on the other side.
//
// For every boundary face this finds the nearest face that lies against it (opposite orientation,
// the same surface, overlapping extents) and records that face's cell in the neighbour slot as
// -2 - cell: still negative, so everything that reads the slot as "no neighbour" still does, while
// the walk can start there and locate the ray's cell on the far side by walking, since which cell
// there holds the ray depends on where the ray crosses. A face that overlaps nothing stays -1.
#ifndef uvNonConformingFaces_h
#define uvNonConformingFaces_h

#include "uvHexahedralMesh.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace uv
{

/// The neighbour slot's value for a face whose far side is `cell` of a non-conforming interface.
constexpr std::int32_t FarSideSlot(std::int32_t cell)
{
  return -2 - cell;
}

/// The cell a FarSideSlot names, or -1 for a plain boundary face (and for a neighbour, >= 0).
constexpr std::int32_t FarSideCell(std::int32_t slot)
{
  return slot <= -2 ? -2 - slot : -1;
}

/// A boundary face's shape, as the search compares it.
struct BoundaryFaceShape
{
  glm::dvec3 Centre, Normal; // the mean of its distinct corners; its unit outward normal
  glm::dvec3 Low, High;      // its bounding box
  double Size = 0.0;         // its bounding box's diagonal
  std::array<glm::dvec3, 4> Corners; // its distinct corners in order (CornerCount of them)
  int CornerCount = 0;
  std::int32_t Cell = -1, Face = -1;
};

/// The shape of face f of `cell`, or one with Size 0 for a collapsed face.
inline BoundaryFaceShape MeasureBoundaryFace(
  const std::vector<std::uint32_t>& cellPoints, const std::vector<float>& pointData, std::int32_t cell, int f)
{
  BoundaryFaceShape shape;
  shape.Cell = cell;
  shape.Face = f;
  glm::dvec3 p[8];
  HexahedronCornerPoints(cellPoints, pointData, static_cast<std::size_t>(cell), p);
  glm::dvec3 cellCentre(0.0);
  for (const glm::dvec3& q : p)
    cellCentre += q / 8.0;
  glm::dvec3 q[4];
  std::uint32_t ids[4];
  for (int k = 0; k < 4; ++k)
  {
    const int corner = HexahedronFaces[f].Vertices[k];
    q[k] = p[corner];
    ids[k] = cellPoints[8 * static_cast<std::size_t>(cell) + corner];
  }
  std::array<std::uint32_t, 4> key;
  const int distinct = FaceKey(ids, key);
  if (distinct < 3)
    return shape;
  shape.Low = shape.High = q[0];
  for (int k = 0; k < 4; ++k)
  {
    shape.Low = glm::min(shape.Low, q[k]);
    shape.High = glm::max(shape.High, q[k]);
  }
  // The diagonals' cross product: the quad's mean normal, and a repeated corner's triangle's too.
  glm::dvec3 normal = glm::cross(q[2] - q[0], q[3] - q[1]);
  shape.Centre = 0.25 * (q[0] + q[1] + q[2] + q[3]);
  const double length = glm::length(normal);
  shape.Size = glm::length(shape.High - shape.Low);
  if (!(length > 0.0) || !(shape.Size > 0.0))
  {
    shape.Size = 0.0;
    return shape;
  }
  normal /= length;
  shape.Normal = glm::dot(normal, shape.Centre - cellCentre) < 0.0 ? -normal : normal;
  for (int k = 0; k < 4; ++k)
    if (ids[k] != ids[(k + 3) % 4])
      shape.Corners[static_cast<std::size_t>(shape.CornerCount++)] = q[k];
  return shape;
}

/// Whether the two faces, seen along a's normal, overlap over more than a sliver (a thousandth of
/// the smaller face's size): separating axes, the normals of both outlines' edges in a's plane.
/// Faces that only meet along an edge, or share a plane far apart, do not.
inline bool OutlinesOverlap(const BoundaryFaceShape& a, const BoundaryFaceShape& b, double margin)
{
  const glm::dvec3 u = glm::normalize(glm::abs(a.Normal.x) < 0.9 ? glm::cross(a.Normal, glm::dvec3(1.0, 0.0, 0.0))
                                                                 : glm::cross(a.Normal, glm::dvec3(0.0, 1.0, 0.0)));
  const glm::dvec3 v = glm::cross(a.Normal, u);
  auto flat = [&](const glm::dvec3& x) { return glm::dvec2(glm::dot(x, u), glm::dot(x, v)); };
  auto extent = [&](const BoundaryFaceShape& shape, const glm::dvec2& axis) { // (low, high) along axis
    glm::dvec2 range(1e300, -1e300);
    for (int i = 0; i < shape.CornerCount; ++i)
    {
      const double d = glm::dot(flat(shape.Corners[static_cast<std::size_t>(i)]), axis);
      range = glm::dvec2(std::min(range.x, d), std::max(range.y, d));
    }
    return range;
  };
  for (const BoundaryFaceShape* edges : { &a, &b })
    for (int k = 0; k < edges->CornerCount; ++k)
    {
      const glm::dvec2 edge = flat(edges->Corners[static_cast<std::size_t>((k + 1) % edges->CornerCount)]) -
        flat(edges->Corners[static_cast<std::size_t>(k)]);
      if (!(glm::length(edge) > 0.0))
        continue;
      const glm::dvec2 axis = glm::normalize(glm::dvec2(-edge.y, edge.x));
      const glm::dvec2 onA = extent(a, axis), onB = extent(b, axis);
      if (std::min(onA.y, onB.y) - std::max(onA.x, onB.x) < margin)
        return false;
    }
  return true;
}

/// Whether face b lies against face a: facing it, on its surface within a hundredth of the smaller
/// face's size, their outlines overlapping. The walk still checks where the ray goes on, so a face
/// that barely overlaps costs a step, never a wrong cell.
inline bool LiesAgainst(const BoundaryFaceShape& a, const BoundaryFaceShape& b)
{
  if (a.Cell == b.Cell || glm::dot(a.Normal, b.Normal) > -0.5)
    return false;
  const double size = std::min(a.Size, b.Size);
  const double slack = 0.01 * size;
  if (glm::any(glm::greaterThan(a.Low - slack, b.High)) || glm::any(glm::greaterThan(b.Low - slack, a.High)))
    return false;
  return std::abs(glm::dot(b.Centre - a.Centre, a.Normal)) < slack &&
    std::abs(glm::dot(a.Centre - b.Centre, b.Normal)) < slack && OutlinesOverlap(a, b, 1e-3 * size);
}

/// Records, in `faces.Neighbours`, the far side of every boundary face that lies against another
/// (LiesAgainst; the one with the nearest centre); returns how many. Faces are found through a hash
/// of grid buckets the size of the mean face, so the search is linear in the boundary faces.
inline std::size_t LinkNonConformingFaces(
  const std::vector<std::uint32_t>& cellPoints, const std::vector<float>& pointData, HexahedralFaces& faces)
{
  std::vector<BoundaryFaceShape> shapes;
  double meanSize = 0.0;
  for (std::size_t i = 0; i + 3 < faces.Boundary.size(); i += 4)
  {
    BoundaryFaceShape shape = MeasureBoundaryFace(cellPoints, pointData, faces.Boundary[i], faces.Boundary[i + 1]);
    if (shape.Size > 0.0)
    {
      meanSize += shape.Size;
      shapes.push_back(shape);
    }
  }
  if (shapes.size() < 2)
    return 0;
  const double bucket = meanSize / static_cast<double>(shapes.size());
  glm::dvec3 origin = shapes[0].Low;
  for (const BoundaryFaceShape& shape : shapes)
    origin = glm::min(origin, shape.Low);
  auto index = [&](const glm::dvec3& x) { return glm::i64vec3(glm::floor((x - origin) / bucket)); };
  auto keyOf = [](const glm::i64vec3& i) {
    return (static_cast<std::uint64_t>(i.x) & 0x1FFFFF) | ((static_cast<std::uint64_t>(i.y) & 0x1FFFFF) << 21) |
      ((static_cast<std::uint64_t>(i.z) & 0x1FFFFF) << 42);
  };
  // Every bucket a face's box touches, but for a face far larger than the mean (bounded work): it
  // goes in by its centre only, and may then miss small faces against its rim.
  auto forEachBucket = [&](const BoundaryFaceShape& shape, auto&& visit) {
    const glm::i64vec3 low = index(shape.Low), high = index(shape.High);
    const glm::i64vec3 extent = high - low + glm::i64vec3(1);
    if (extent.x * extent.y * extent.z > 4096)
    {
      visit(keyOf(index(shape.Centre)));
      return;
    }
    for (std::int64_t x = low.x; x <= high.x; ++x)
      for (std::int64_t y = low.y; y <= high.y; ++y)
        for (std::int64_t z = low.z; z <= high.z; ++z)
          visit(keyOf(glm::i64vec3(x, y, z)));
  };
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> buckets;
  for (std::size_t s = 0; s < shapes.size(); ++s)
    forEachBucket(shapes[s], [&](std::uint64_t key) { buckets[key].push_back(static_cast<std::uint32_t>(s)); });
  std::size_t linked = 0;
  for (const BoundaryFaceShape& shape : shapes)
  {
    std::int32_t best = -1;
    double nearest = 0.0;
    forEachBucket(shape, [&](std::uint64_t key) {
      for (std::uint32_t other : buckets.find(key)->second)
      {
        const double distance = glm::length(shapes[other].Centre - shape.Centre);
        if ((best < 0 || distance < nearest) && LiesAgainst(shape, shapes[other]))
        {
          best = shapes[other].Cell;
          nearest = distance;
        }
      }
    });
    if (best >= 0)
    {
      faces.Neighbours[8 * static_cast<std::size_t>(shape.Cell) + static_cast<std::size_t>(shape.Face)] =
        FarSideSlot(best);
      ++linked;
    }
  }
  return linked;
}

} // namespace uv

#endif
