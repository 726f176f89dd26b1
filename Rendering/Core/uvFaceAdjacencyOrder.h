// Exact visibility order of a tetrahedral mesh from its face adjacency, free of VTK.
//
// Two tetrahedra sharing a face are ordered by the side of the face's plane the eye is on: the one
// on the eye's side is in front and is drawn after the other (Williams' MPVO). These constraints are
// exact wherever cells touch; centroid distance, which compositing by cells used before, gets them
// wrong for long or twisted cells and near the eye. The order here is the centroid order changed
// only where a constraint needs it: a sweep through the centroid order (back to front) draws a
// tetrahedron once every neighbour behind it is drawn, and one whose turn came too early is drawn
// the moment its last neighbour behind it is. Where cells do not touch (across a gap of a
// non-convex mesh) the centroid order stands, as in MPVONC. Tetrahedra that are not drawn (the
// transfer function makes them invisible) still pass the constraints on, so a ray through
// invisible cells keeps its order. A cycle (possible in perspective on non-Delaunay meshes) is broken
// by drawing its tetrahedron that comes first in centroid order; CyclesBroken counts those.
//
// Each face's constraint is decided once from the same numbers whichever side asks (the face's
// corners by ascending id, the side of its tetrahedron of lower index), so the two sides agree
// exactly and rounding cannot make a cycle of two.
#ifndef uvFaceAdjacencyOrder_h
#define uvFaceAdjacencyOrder_h

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace uv
{

/// Whether the tetrahedron with these 4 point ids repeats one: it has no volume, and two of its
/// faces are one face.
inline bool HasRepeatedCorner(const std::uint32_t* c)
{
  return c[0] == c[1] || c[0] == c[2] || c[0] == c[3] || c[1] == c[2] || c[1] == c[3] || c[2] == c[3];
}

/// Per tetrahedron the tetrahedron across the face opposite each corner, or -1 on the boundary.
/// `corners` holds 4 point ids per tetrahedron; two tetrahedra are neighbours where both hold the
/// same three ids. A face held by three or more (a non-manifold mesh) and a tetrahedron with a
/// repeated id (no volume) get no neighbour, so the relation stays symmetric. Faces are found
/// through the tetrahedra around each point, which needs 4 bytes per corner while it runs rather
/// than a sorted list of every face. `parallelFor(count, function(begin, end))` runs over
/// tetrahedra, in parallel if it likes.
template <typename ParallelFor>
std::vector<std::int32_t> MakeTetrahedronFaceAdjacency(const std::vector<std::uint32_t>& corners, ParallelFor&& parallelFor)
{
  const std::size_t count = corners.size() / 4;
  const auto degenerate = [&corners](std::size_t t) { return HasRepeatedCorner(&corners[4 * t]); };
  std::size_t pointCount = 0;
  for (std::uint32_t id : corners)
    pointCount = std::max<std::size_t>(pointCount, std::size_t(id) + 1);
  // The tetrahedra around each point: around[first[p] .. first[p + 1]).
  std::vector<std::uint32_t> first(pointCount + 1, 0);
  for (std::size_t t = 0; t < count; ++t)
    if (!degenerate(t))
      for (int k = 0; k < 4; ++k)
        ++first[corners[4 * t + k] + 1];
  for (std::size_t p = 0; p < pointCount; ++p)
    first[p + 1] += first[p];
  std::vector<std::uint32_t> around(first[pointCount]);
  {
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
    for (std::size_t t = 0; t < count; ++t)
      if (!degenerate(t))
        for (int k = 0; k < 4; ++k)
          around[next[corners[4 * t + k]]++] = static_cast<std::uint32_t>(t);
  }
  const auto holds = [&corners](std::uint32_t u, std::uint32_t id) {
    const std::uint32_t* c = &corners[4 * std::size_t(u)];
    return c[0] == id || c[1] == id || c[2] == id || c[3] == id;
  };
  std::vector<std::int32_t> neighbours(4 * count, -1);
  parallelFor(count, [&](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t)
    {
      if (degenerate(t))
        continue;
      for (int k = 0; k < 4; ++k)
      {
        std::uint32_t ids[3];
        for (int j = 0; j < 3; ++j)
          ids[j] = corners[4 * t + (k + 1 + j) % 4];
        // Search around the face's point with the fewest tetrahedra.
        int least = 0;
        for (int j = 1; j < 3; ++j)
          if (first[ids[j] + 1] - first[ids[j]] < first[ids[least] + 1] - first[ids[least]])
            least = j;
        const std::uint32_t other1 = ids[(least + 1) % 3], other2 = ids[(least + 2) % 3];
        std::int32_t found = -1;
        int sharing = 0;
        for (std::uint32_t i = first[ids[least]]; i < first[ids[least] + 1]; ++i)
        {
          const std::uint32_t u = around[i];
          if (u != t && holds(u, other1) && holds(u, other2))
          {
            found = static_cast<std::int32_t>(u);
            ++sharing;
          }
        }
        neighbours[4 * t + k] = sharing == 1 ? found : -1;
      }
    }
  });
  return neighbours;
}

class FaceAdjacencyOrder
{
public:
  std::size_t CyclesBroken = 0; ///< tetrahedra drawn before a neighbour behind them, last Sort

  /// Bytes kept between sorts: none, the state below lives only while sorting.
  std::size_t GetBytes() const
  {
    return this->Side.capacity() + this->State.capacity() +
      sizeof(std::uint32_t) * (this->Waiting.capacity() + this->AheadFirst.capacity() + this->AheadOf.capacity() +
                                this->NewOrder.capacity() + this->Stack.capacity());
  }

  /// Reorders `order` (the drawn tetrahedra back to front by centroid) so that every face
  /// constraint holds. `corners`: 4 point ids per tetrahedron of the whole mesh (faces' ids);
  /// `position(t, k)`: corner k of tetrahedron t; `neighbours` from MakeTetrahedronFaceAdjacency;
  /// `eye` the eye point, or with `parallel` the direction towards the eye. `parallelFor(count,
  /// function(begin, end))` runs the constraint test over tetrahedra, in parallel if it likes.
  /// `gaps`: further pairs (front, behind) that no face joins, e.g. across the gaps of a non-convex
  /// mesh (uvBoundaryGapOrder.h); behind is drawn first.
  template <typename Position, typename ParallelFor>
  void Sort(std::vector<std::uint32_t>& order, const std::vector<std::uint32_t>& corners, Position&& position,
    const std::vector<std::int32_t>& neighbours, const glm::dvec3& eye, bool parallel, ParallelFor&& parallelFor,
    const std::vector<std::pair<std::uint32_t, std::uint32_t>>& gaps = {})
  {
    const std::size_t count = corners.size() / 4;
    // Each shared face is decided once, by the lower-indexed tetrahedron, which writes the side of
    // both its slots (each slot has one writer, so the parallel loop needs no lock).
    this->Side.assign(4 * count, 0);
    parallelFor(count, [&](std::size_t begin, std::size_t end) {
      for (std::size_t t = begin; t < end; ++t)
        for (int k = 0; k < 4; ++k)
        {
          const std::int32_t u = neighbours[4 * t + k];
          if (u <= static_cast<std::int32_t>(t))
            continue; // no neighbour, or the lower one decides
          const std::size_t other = static_cast<std::size_t>(u);
          int j = 0;
          while (j < 3 && neighbours[4 * other + j] != static_cast<std::int32_t>(t))
            ++j;
          const int side = LowSide(corners, position, t, k, eye, parallel);
          this->Side[4 * t + k] = static_cast<std::int8_t>(side);
          this->Side[4 * other + j] = static_cast<std::int8_t>(-side);
        }
    });
    this->Waiting.assign(count, 0);
    parallelFor(count, [&](std::size_t begin, std::size_t end) {
      for (std::size_t t = begin; t < end; ++t)
      {
        std::uint32_t waiting = 0;
        for (int k = 0; k < 4; ++k)
          waiting += this->Side[4 * t + k] < 0 ? 1 : 0; // the neighbour is behind: drawn first
        this->Waiting[t] = waiting;
      }
    });
    this->IndexGaps(gaps, count);
    this->Sweep(order, neighbours);
    this->Release();
  }

private:
  enum : std::uint8_t
  {
    Drawn = 1,   // in the order being built
    Passed = 2,  // its turn in the centroid order came
    Placed = 4   // placed in the new order (or, not drawn, passed on)
  };

  /// For the face k of `low` shared with a higher-indexed neighbour: -1 where the neighbour is behind
  /// `low` (farther from the eye), 1 where in front, 0 where the eye is in the face's plane (either
  /// order).
  template <typename Position>
  static int LowSide(const std::vector<std::uint32_t>& corners, Position& position, std::size_t low, int lowCorner,
    const glm::dvec3& eye, bool parallel)
  {
    // The face's corners by ascending id: the plane of the same three numbers for every view.
    std::array<std::pair<std::uint32_t, int>, 3> face;
    for (int j = 0; j < 3; ++j)
    {
      const int corner = (lowCorner + 1 + j) % 4;
      face[j] = { corners[4 * low + corner], corner };
    }
    std::sort(face.begin(), face.end());
    const glm::dvec3 a = position(low, face[0].second), b = position(low, face[1].second),
                     c = position(low, face[2].second);
    const glm::dvec3 normal = glm::cross(b - a, c - a);
    const double eyeSide = parallel ? glm::dot(normal, eye) : glm::dot(normal, eye - a);
    const double lowSide = glm::dot(normal, position(low, lowCorner) - a);
    if (eyeSide == 0.0 || lowSide == 0.0)
      return 0;
    // The eye on the low tetrahedron's side: the low one is in front, its neighbour behind.
    return (eyeSide > 0.0) == (lowSide > 0.0) ? -1 : 1;
  }

  /// The tetrahedra in front of each across a gap, AheadOf[AheadFirst[t] .. AheadFirst[t + 1]), and
  /// each one's count of those behind it added to Waiting.
  void IndexGaps(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& gaps, std::size_t count)
  {
    this->AheadFirst.assign(gaps.empty() ? 0 : count + 1, 0);
    this->AheadOf.resize(gaps.size());
    if (gaps.empty())
      return;
    for (const auto& gap : gaps)
    {
      ++this->AheadFirst[gap.second + 1];
      ++this->Waiting[gap.first];
    }
    for (std::size_t t = 0; t < count; ++t)
      this->AheadFirst[t + 1] += this->AheadFirst[t];
    std::vector<std::uint32_t> next(this->AheadFirst.begin(), this->AheadFirst.end() - 1);
    for (const auto& gap : gaps)
      this->AheadOf[next[gap.second]++] = gap.first;
  }

  void Sweep(std::vector<std::uint32_t>& order, const std::vector<std::int32_t>& neighbours)
  {
    const std::size_t count = this->Waiting.size();
    this->State.assign(count, 0);
    for (std::uint32_t t : order)
      this->State[t] = Drawn;
    this->NewOrder.clear();
    this->NewOrder.reserve(order.size());
    this->CyclesBroken = 0;
    // Tetrahedra not drawn with nothing behind them pass their constraints on at once.
    for (std::size_t t = 0; t < count; ++t)
      if (!(this->State[t] & Drawn) && this->Waiting[t] == 0)
        this->Place(static_cast<std::uint32_t>(t), neighbours);
    for (std::uint32_t t : order)
    {
      this->State[t] |= Passed;
      if (this->Waiting[t] == 0 && !(this->State[t] & Placed))
        this->Place(t, neighbours);
    }
    // What is left waits on a cycle: draw it in centroid order regardless.
    for (std::uint32_t t : order)
      if (!(this->State[t] & Placed))
      {
        ++this->CyclesBroken;
        this->Place(t, neighbours);
      }
    order.swap(this->NewOrder);
  }

  /// Places t and, depth first, every tetrahedron that was waiting only for what gets placed and
  /// whose turn came (or that is not drawn).
  void Place(std::uint32_t first, const std::vector<std::int32_t>& neighbours)
  {
    this->Stack.clear();
    this->Stack.push_back(first);
    this->State[first] |= Placed;
    while (!this->Stack.empty())
    {
      const std::uint32_t t = this->Stack.back();
      this->Stack.pop_back();
      if (this->State[t] & Drawn)
        this->NewOrder.push_back(t);
      for (int k = 0; k < 4; ++k)
      {
        // Only a neighbour in front of t waits for it (the face's side, decided once for both).
        const std::int32_t u = neighbours[4 * t + k];
        if (u < 0 || this->Side[4 * t + k] <= 0 || (this->State[static_cast<std::size_t>(u)] & Placed))
          continue;
        this->OneBehindPlaced(static_cast<std::uint32_t>(u));
      }
      if (!this->AheadFirst.empty())
        for (std::uint32_t k = this->AheadFirst[t]; k < this->AheadFirst[t + 1]; ++k)
          if (!(this->State[this->AheadOf[k]] & Placed))
            this->OneBehindPlaced(this->AheadOf[k]);
    }
  }

  /// One tetrahedron behind u is placed: u goes on the stack once nothing behind it waits and its
  /// turn came (or it is not drawn).
  void OneBehindPlaced(std::uint32_t u)
  {
    std::uint8_t& state = this->State[u];
    if (--this->Waiting[u] == 0 && ((state & Passed) || !(state & Drawn)))
    {
      state |= Placed;
      this->Stack.push_back(u);
    }
  }

  void Release()
  {
    std::vector<std::int8_t>().swap(this->Side);
    std::vector<std::uint32_t>().swap(this->Waiting);
    std::vector<std::uint32_t>().swap(this->AheadFirst);
    std::vector<std::uint32_t>().swap(this->AheadOf);
    std::vector<std::uint8_t>().swap(this->State);
    std::vector<std::uint32_t>().swap(this->NewOrder);
    std::vector<std::uint32_t>().swap(this->Stack);
  }

  std::vector<std::int8_t> Side;     // per face slot 4t + k: -1 the neighbour is behind t, 1 in front, 0 either
  std::vector<std::uint32_t> Waiting; // neighbours (and tetrahedra across gaps) behind it not yet placed
  std::vector<std::uint32_t> AheadFirst, AheadOf; // IndexGaps
  std::vector<std::uint8_t> State;
  std::vector<std::uint32_t> NewOrder, Stack;
};

} // namespace uv

#endif
