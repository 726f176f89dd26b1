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

#include <glm/glm.hpp>

#include <cstdint>
#include <tuple>
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

/// The boundary faces, tetrahedron * 4 + the corner opposite the face, in tetrahedron order.
inline std::vector<std::int32_t> BoundaryFaceRecords(const std::vector<std::int32_t>& packedNeighbours)
{
  std::vector<std::int32_t> faces;
  for (std::size_t i = 0; i < packedNeighbours.size(); ++i)
    if (packedNeighbours[i] < 0)
      faces.push_back(static_cast<std::int32_t>(i));
  return faces;
}

/// One tetrahedron as the walk sees it, for a ray from `origin` along `direction`.
struct WalkedTetrahedron
{
  glm::vec4 Along{ 0.0f };   // the corners' ray parameters (their projections on the ray)
  float Edges[6] = {};       // products with edges 01, 02, 03, 12, 13, 23 (local corners)
  float Orientation = 1.0f;  // the sign of the volume

  WalkedTetrahedron(const glm::vec3 corners[4], const std::uint32_t ids[4], const glm::vec3& origin,
    const glm::vec3& direction)
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
      const int a = pairs[e][0], b = pairs[e][1];
      const bool flip = ids[a] > ids[b];
      const float product = glm::dot(direction, glm::cross(flip ? p[b] : p[a], flip ? p[a] : p[b]));
      this->Edges[e] = flip ? -product : product;
    }
    this->Orientation = glm::dot(p[1] - p[0], glm::cross(p[2] - p[0], p[3] - p[0])) < 0.0f ? -1.0f : 1.0f;
  }

  /// The products around the face opposite `corner`, each standing at the corner it does not touch
  /// (0 at `corner`): unnormalised barycentric weights of the crossing, all >= 0 times Orientation
  /// where the ray leaves through the face.
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
  /// largest, so rounding at an edge still picks a face. `weights`: its normalised weights.
  int ExitFace(int entered, glm::vec4& weights) const
  {
    int best = -1;
    float bestLeast = -3.0e38f;
    for (int k = 0; k < 4; ++k)
    {
      if (k == entered)
        continue;
      glm::vec4 w = this->FaceWeights(k) * this->Orientation;
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

/// One segment of a walked ray: the tetrahedron and the ray parameters and barycentric weights of
/// where the ray enters and leaves it.
struct WalkSegment
{
  std::int32_t Tetrahedron = -1;
  float Front = 0.0f, Back = 0.0f;
  glm::vec4 FrontWeights{ 0.0f }, BackWeights{ 0.0f };
};

/// The walk from boundary face `record` (tetrahedron * 4 + corner) to where the ray leaves the mesh
/// (or `maximumSteps` tetrahedra). `corners` holds 4 point ids per tetrahedron, `positions` 3 floats
/// per point, `packedNeighbours` is PackedFaceNeighbours'.
inline std::vector<WalkSegment> Walk(std::int32_t record, const std::vector<std::uint32_t>& corners,
  const std::vector<float>& positions, const std::vector<std::int32_t>& packedNeighbours, const glm::vec3& origin,
  const glm::vec3& direction, int maximumSteps)
{
  const auto load = [&](std::int32_t t) {
    glm::vec3 p[4];
    std::uint32_t ids[4];
    for (int k = 0; k < 4; ++k)
    {
      ids[k] = corners[4 * std::size_t(t) + k];
      p[k] = glm::vec3(positions[3 * ids[k]], positions[3 * ids[k] + 1], positions[3 * ids[k] + 2]);
    }
    return WalkedTetrahedron(p, ids, origin, direction);
  };
  std::vector<WalkSegment> segments;
  std::int32_t cell = record / 4;
  int entered = record % 4;
  WalkedTetrahedron t = load(cell);
  glm::vec4 front = WalkedTetrahedron::Normalised(t.FaceWeights(entered));
  for (int step = 0; step < maximumSteps; ++step)
  {
    WalkSegment segment;
    segment.Tetrahedron = cell;
    segment.FrontWeights = front;
    segment.Front = glm::dot(front, t.Along);
    const int exit = t.ExitFace(entered, segment.BackWeights);
    segment.Back = glm::dot(segment.BackWeights, t.Along);
    segments.push_back(segment);
    const std::int32_t next = packedNeighbours[4 * std::size_t(cell) + exit];
    if (next < 0)
      break;
    // The next tetrahedron's entry weights are these exit weights, moved to its own corners.
    const std::int32_t previous = cell;
    cell = next / 4;
    entered = next % 4;
    glm::vec4 moved(0.0f);
    for (int k = 0; k < 4; ++k)
      for (int m = 0; m < 4; ++m)
        if (corners[4 * std::size_t(cell) + m] == corners[4 * std::size_t(previous) + k])
          moved[m] = segment.BackWeights[k];
    front = moved;
    t = load(cell);
  }
  return segments;
}

} // namespace uv

#endif
