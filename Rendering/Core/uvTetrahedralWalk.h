// Walking a ray through a tetrahedral mesh by face adjacency, free of VTK: what the tetrahedra
// mapper's ray-casting route uploads (each face's neighbour with the neighbour's own corner, the
// boundary faces rays enter by) and the step its fragment stage takes (uvTetrahedralWalkFS.glsl is
// the GPU twin of ExitFace and Walk).
//
// The exit face comes from Plücker products: the ray against each edge of the tetrahedron, as the
// triple product d . ((a - o) x (b - o)). Around a face these are the barycentric weights of the
// ray's crossing of its plane, all of one sign where the ray passes through it, the sign telling
// in or out. Each edge's product is computed from its lower point id first whichever tetrahedron
// asks, so the two tetrahedra sharing a face find bitwise the same numbers for it: the walk cannot
// slip between them, and the exit point of one is the entry point of the next.
#ifndef uvTetrahedralWalk_h
#define uvTetrahedralWalk_h

#include "uvBoundaryGapOrder.h"
#include "uvFaceAdjacencyOrder.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <tuple>
#include <utility>
#include <vector>

namespace uv
{

/// Per tetrahedron and corner, the tetrahedron across the face opposite the corner and that
/// tetrahedron's corner opposite the same face, packed as neighbour * 4 + corner, or -1 on the
/// boundary. `neighbours` is MakeTetrahedronFaceAdjacency's (symmetric). `parallelFor(count,
/// function(begin, end))` runs over tetrahedra.
template <typename ParallelFor>
std::vector<std::int32_t> PackedFaceNeighbours(const std::vector<std::int32_t>& neighbours, ParallelFor&& parallelFor)
{
  std::vector<std::int32_t> packed(neighbours.size(), -1);
  parallelFor(neighbours.size() / 4, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
      for (int k = 0; k < 4; ++k)
      {
        const std::int32_t n = neighbours[4 * t + k];
        if (n < 0)
          continue;
        for (int m = 0; m < 4; ++m)
          if (neighbours[4 * std::size_t(n) + m] == static_cast<std::int32_t>(t))
            packed[4 * t + k] = 4 * n + m;
      }
  });
  return packed;
}

/// Per point, the least id of the points at bitwise the same position (`positions`: `stride` floats
/// per point, xyz first). Meshes repeat points along seams (periodic cuts, blocks written apart, a
/// cell scalar's copies per cell); the ray sees no boundary there, so adjacency is matched through
/// these ids. `sort(begin, end, less)` sorts a range of point ids (std::sort will do).
template <typename Sort>
std::vector<std::uint32_t> CoincidentPointIds(const std::vector<float>& positions, int stride, Sort&& sort)
{
  const std::size_t count = positions.size() / stride;
  std::vector<std::uint32_t> order(count), representative(count);
  for (std::size_t i = 0; i < count; ++i)
    order[i] = static_cast<std::uint32_t>(i);
  const auto at = [&](std::uint32_t i) {
    const float* p = &positions[std::size_t(i) * stride];
    return std::make_tuple(p[0], p[1], p[2]);
  };
  sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const auto pa = at(a), pb = at(b);
    return pa < pb || (pa == pb && a < b);
  });
  for (std::size_t i = 0; i < count;)
  {
    std::size_t j = i;
    while (j < count && at(order[j]) == at(order[i]))
      ++j;
    for (std::size_t k = i; k < j; ++k)
      representative[order[k]] = order[i]; // the run's least id: ties sort by id
    i = j;
  }
  return representative;
}

/// The boundary faces, tetrahedron * 4 + the corner opposite the face, in tetrahedron order. A
/// tetrahedron with a repeated corner id (`corners`, matched as for the adjacency) bounds nothing:
/// MakeTetrahedronFaceAdjacency gives it no neighbour, and a ray entering by one of its two
/// coincident faces would leave at once by the other, peel after peel.
inline std::vector<std::int32_t> BoundaryFaceRecords(
  const std::vector<std::int32_t>& packedNeighbours, const std::vector<std::uint32_t>& corners)
{
  std::vector<std::int32_t> faces;
  for (std::size_t i = 0; i < packedNeighbours.size(); ++i)
    if (packedNeighbours[i] < 0 && !HasRepeatedCorner(&corners[i & ~std::size_t(3)]))
      faces.push_back(static_cast<std::int32_t>(i));
  return faces;
}

/// Puts first in `boundary` (BoundaryFaceRecords, ascending) the faces by which a ray can enter the
/// mesh again after leaving it, and returns how many: the faces off the mesh's convex hull. A ray
/// that enters by a face on the hull comes from beyond the hull's plane there, where nothing of the
/// mesh lies, so it cannot have left the mesh before. None on a convex mesh; all of them when there
/// are more than `maximumFaces` (the test takes each face against each boundary point).
/// `corners`: 4 point ids per tetrahedron, matched as `neighbours` (MakeTetrahedronFaceAdjacency's)
/// were; `position(t, k)`: corner k of tetrahedron t.
template <typename Position, typename ParallelFor>
std::size_t MoveReentryFacesFirst(std::vector<std::int32_t>& boundary, const std::vector<std::uint32_t>& corners,
  const std::vector<std::int32_t>& neighbours, Position&& position, ParallelFor&& parallelFor,
  std::size_t maximumFaces)
{
  if (BoundaryIsConvex(corners, position, neighbours))
    return 0;
  if (boundary.size() > maximumFaces)
    return boundary.size();
  std::vector<std::pair<std::uint32_t, int>> faces;
  faces.reserve(boundary.size());
  for (std::int32_t record : boundary)
    faces.emplace_back(static_cast<std::uint32_t>(record / 4), static_cast<int>(record % 4));
  std::vector<std::int32_t> reentry;
  for (const auto& face : FacesOffTheHull(faces, position, parallelFor))
    reentry.push_back(static_cast<std::int32_t>(4 * face.first + face.second));
  // Both lists ascend: the rest is what remains of the boundary after the reentry faces.
  std::vector<std::int32_t> ordered = reentry;
  std::set_difference(boundary.begin(), boundary.end(), reentry.begin(), reentry.end(), std::back_inserter(ordered));
  boundary.swap(ordered);
  return reentry.size();
}

/// Whether position a comes before b (lexicographically): the order an edge's product is computed in,
/// by position rather than point id, so a point repeated at the same place orders alike everywhere.
inline bool Before(const glm::vec3& a, const glm::vec3& b)
{
  return a.x != b.x ? a.x < b.x : (a.y != b.y ? a.y < b.y : a.z < b.z);
}

/// The interior faces whose two tetrahedra lie on the same side of it (folded, or overlapping:
/// tangled input cells), each counted once. A walk crosses one tetrahedron at a time and cannot add
/// up overlapping ones as the optical model does; where there are such faces the mapper projects.
/// `positions`: `stride` floats per point, xyz first.
template <typename ParallelFor>
std::size_t FoldedFaces(const std::vector<std::uint32_t>& corners, const std::vector<float>& positions, int stride,
  const std::vector<std::int32_t>& packedNeighbours, ParallelFor&& parallelFor)
{
  const auto at = [&](std::uint32_t id) {
    const float* p = &positions[std::size_t(id) * stride];
    return glm::dvec3(p[0], p[1], p[2]);
  };
  std::vector<unsigned char> folded(packedNeighbours.size(), 0);
  parallelFor(packedNeighbours.size() / 4, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
      for (int k = 0; k < 4; ++k)
      {
        const std::int32_t across = packedNeighbours[4 * t + k];
        if (across < 0 || std::size_t(across / 4) < t)
          continue; // the boundary, or counted from the other side
        const glm::dvec3 a = at(corners[4 * t + (k + 1) % 4]), b = at(corners[4 * t + (k + 2) % 4]),
                         c = at(corners[4 * t + (k + 3) % 4]);
        const glm::dvec3 normal = glm::cross(b - a, c - a);
        const double mine = glm::dot(normal, at(corners[4 * t + k]) - a);
        const double theirs = glm::dot(normal, at(corners[std::size_t(across)]) - a);
        folded[4 * t + k] = (mine > 0.0 && theirs > 0.0) || (mine < 0.0 && theirs < 0.0);
      }
  });
  std::size_t count = 0;
  for (unsigned char f : folded)
    count += f;
  return count;
}

/// One tetrahedron as the walk sees it, for a ray from `origin` along unit `direction`.
struct WalkedTetrahedron
{
  glm::vec4 Along{ 0.0f };   // the corners' ray parameters (their projections on the ray)
  float Edges[6] = {};       // products with edges 01, 02, 03, 12, 13, 23 (local corners)

  WalkedTetrahedron(const glm::vec3 corners[4], const glm::vec3& origin, const glm::vec3& direction)
  {
    glm::vec3 p[4];
    for (int k = 0; k < 4; ++k)
    {
      p[k] = corners[k] - origin;
      this->Along[k] = glm::dot(p[k], direction);
    }
    const int pairs[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
    for (int e = 0; e < 6; ++e)
    {
      const glm::vec3 a = p[pairs[e][0]], b = p[pairs[e][1]];
      const bool flip = Before(b, a);
      const glm::vec3 moment = glm::cross(flip ? b : a, flip ? a : b);
      float product = glm::dot(direction, moment);
      if (product == 0.0f)
      {
        // A tie: the first-order term once the direction is turned by a tiny fixed generic amount,
        // scaled far below any other product (positive where that is 0 too).
        const float tie = glm::dot(glm::vec3(0.3112f, 0.5697f, 0.7607f), moment) * 1e-20f;
        product = tie != 0.0f ? tie : 1e-30f;
      }
      this->Edges[e] = flip ? -product : product;
    }
  }

  /// The products around the face opposite `corner`, outward for a positive tetrahedron, each
  /// standing at the corner it does not touch (0 at `corner`): unnormalised barycentric weights of
  /// the crossing of the face's plane, all >= 0 times the volume's sign where the ray leaves
  /// through the face, all <= 0 where it enters.
  glm::vec4 FaceWeights(int corner) const
  {
    const float* e = this->Edges;
    switch (corner)
    {
      case 0:
        return { 0.0f, e[5], -e[4], e[3] };
      case 1:
        return { -e[5], 0.0f, e[2], -e[1] };
      case 2:
        return { e[4], -e[2], 0.0f, e[0] };
      default:
        return { -e[3], e[1], -e[0], 0.0f };
    }
  }

  /// The face the ray leaves by, other than `entered`'s: the one whose least oriented weight is the
  /// largest, so rounding at an edge still picks a face. The orientation is read from the entry
  /// face's weights (the sign opposite to leaving), not from the volume, whose sign rounding can
  /// flip on a sliver. `weights`: the exit face's, normalised.
  int ExitFace(int entered, glm::vec4& weights) const
  {
    const glm::vec4 in = this->FaceWeights(entered);
    const float orientation = in.x + in.y + in.z + in.w > 0.0f ? -1.0f : 1.0f;
    int best = -1;
    float bestLeast = -3.0e38f;
    for (int k = 0; k < 4; ++k)
    {
      if (k == entered)
        continue;
      glm::vec4 w = this->FaceWeights(k) * orientation;
      w[k] = 3.0e38f;
      const float least = glm::min(glm::min(w.x, w.y), glm::min(w.z, w.w));
      if (least > bestLeast)
      {
        bestLeast = least;
        best = k;
      }
    }
    weights = Normalised(this->FaceWeights(best));
    return best;
  }

  static glm::vec4 Normalised(const glm::vec4& weights)
  {
    const float sum = weights.x + weights.y + weights.z + weights.w;
    return sum != 0.0f ? weights / sum : glm::vec4(1.0f / 3.0f);
  }
};

/// One segment of a walked ray: the tetrahedron, the ray parameters where the ray enters and leaves
/// it, and the barycentric weights there (the field's values and gradients follow from them).
struct WalkSegment
{
  std::int32_t Tetrahedron = -1;
  float Front = 0.0f, Back = 0.0f;
  glm::vec4 FrontWeights{ 0.0f }, BackWeights{ 0.0f };
};

/// The walk from boundary face `record` (tetrahedron * 4 + corner) to where the ray leaves the mesh
/// (or `maximumSteps` tetrahedra), as uvTetrahedralWalkFS.glsl takes it: ray parameters from
/// `origin`, products from the entry point on. `corners` holds 4 point ids per tetrahedron,
/// `positions` 3 floats per point, `packedNeighbours` is PackedFaceNeighbours'. `leftMesh`: whether
/// the walk ended at a boundary face (rather than at maximumSteps).
inline std::vector<WalkSegment> Walk(std::int32_t record, const std::vector<std::uint32_t>& corners,
  const std::vector<float>& positions, const std::vector<std::int32_t>& packedNeighbours, const glm::vec3& origin,
  const glm::vec3& direction, int maximumSteps, bool& leftMesh)
{
  const auto load = [&](std::int32_t t, const glm::vec3& from) {
    glm::vec3 p[4];
    for (int k = 0; k < 4; ++k)
    {
      const std::size_t id = corners[4 * std::size_t(t) + k];
      p[k] = glm::vec3(positions[3 * id], positions[3 * id + 1], positions[3 * id + 2]);
    }
    return WalkedTetrahedron(p, from, direction);
  };
  std::vector<WalkSegment> segments;
  leftMesh = false;
  std::int32_t cell = record / 4;
  int entered = record % 4;
  const WalkedTetrahedron first = load(cell, origin);
  const float base = glm::dot(WalkedTetrahedron::Normalised(first.FaceWeights(entered)), first.Along);
  const glm::vec3 start = origin + base * direction;
  WalkedTetrahedron t = load(cell, start);
  glm::vec4 frontWeights = WalkedTetrahedron::Normalised(t.FaceWeights(entered));
  float front = glm::dot(frontWeights, t.Along);
  for (int step = 0; step < maximumSteps; ++step)
  {
    WalkSegment segment;
    segment.Tetrahedron = cell;
    segment.FrontWeights = frontWeights;
    segment.Front = base + front;
    const int exit = t.ExitFace(entered, segment.BackWeights);
    const float back = glm::dot(segment.BackWeights, t.Along);
    segment.Back = base + back;
    segments.push_back(segment);
    const std::int32_t next = packedNeighbours[4 * std::size_t(cell) + exit];
    if (next < 0)
    {
      leftMesh = true;
      break;
    }
    cell = next / 4;
    entered = next % 4;
    t = load(cell, start);
    frontWeights = WalkedTetrahedron::Normalised(t.FaceWeights(entered));
    front = back; // carried: the next segment begins exactly where this one ends
  }
  return segments;
}

} // namespace uv

#endif
