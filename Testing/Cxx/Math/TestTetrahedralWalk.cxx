// uvTetrahedralWalk.h (the CPU twin of the tetrahedra mapper's ray-casting walk): rays walked in float
// through meshes of tetrahedra cross the tetrahedra the brute-force intersection of the ray with
// every tetrahedron finds (double precision), over the same length, and leave the mesh where it
// ends; also rays through vertices and along edges and faces, where the exit face is a tie.
#include "uvCoincidentCells.h"
#include "uvFaceAdjacencyOrder.h"
#include "uvTestTetrahedralCubes.h"
#include "uvTetrahedralWalk.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>

namespace
{
using uvtest::Cubes;
using uvtest::Mesh;

const auto Serial = [](std::size_t count, const auto& run) { run(0, count); };

/// What the walk reads: float positions, the packed adjacency and the boundary faces.
struct WalkMesh
{
  std::vector<float> Positions;
  std::vector<std::int32_t> Neighbours, Boundary;

  explicit WalkMesh(const Mesh& mesh)
  {
    for (const glm::dvec3& p : mesh.Points)
      this->Positions.insert(this->Positions.end(), { float(p.x), float(p.y), float(p.z) });
    this->Neighbours = uv::PackedFaceNeighbours(uv::MakeTetrahedronFaceAdjacency(mesh.Corners, Serial), Serial);
    this->Boundary = uv::BoundaryFaceRecords(this->Neighbours, mesh.Corners);
  }
};

/// The nearest boundary face the ray enters by (brute force, double), or -1.
std::int32_t EntryFace(const Mesh& mesh, const WalkMesh& walk, const glm::dvec3& origin, const glm::dvec3& direction)
{
  std::int32_t best = -1;
  double nearest = 1e300;
  for (std::int32_t record : walk.Boundary)
  {
    const std::size_t t = record / 4;
    const int k = record % 4;
    const glm::dvec3 a = mesh.At(t, (k + 1) % 4), b = mesh.At(t, (k + 2) % 4), c = mesh.At(t, (k + 3) % 4);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const glm::dvec3 outward = glm::dot(n, mesh.At(t, k) - a) > 0.0 ? -n : n;
    const double along = glm::dot(outward, direction);
    if (!(along < 0.0))
      continue; // leaving here
    const double at = glm::dot(outward, a - origin) / along;
    const glm::dvec3 x = origin + at * direction;
    // Inside the triangle (edges included): the three sub-areas agree in sign with the face's.
    const double u = glm::dot(glm::cross(b - a, x - a), n), v = glm::dot(glm::cross(c - b, x - b), n),
                 w = glm::dot(glm::cross(a - c, x - c), n);
    const double tolerance = -1e-12 * glm::dot(n, n);
    if (u >= tolerance && v >= tolerance && w >= tolerance && at < nearest)
    {
      nearest = at;
      best = record;
    }
  }
  return best;
}

/// Every tetrahedron the ray crosses for longer than `shortest`, as (enter, leave, tetrahedron) in
/// order along the ray.
std::vector<std::tuple<double, double, std::int32_t>> BruteForcePath(
  const Mesh& mesh, const glm::dvec3& origin, const glm::dvec3& direction, double shortest)
{
  std::vector<std::tuple<double, double, std::int32_t>> path;
  for (std::size_t t = 0; t < mesh.Count(); ++t)
  {
    double enter = 0.0, leave = 0.0;
    if (uvtest::Crossing(mesh, t, origin, direction, enter, leave) && leave - enter > shortest)
      path.emplace_back(enter, leave, static_cast<std::int32_t>(t));
  }
  std::sort(path.begin(), path.end());
  return path;
}

/// Walks the ray from its entry face; checks it against the brute force on a convex mesh: the walk
/// leaves the mesh at its far side, its segments add up to the length the ray spends in the mesh
/// and, with `eachTetrahedron`, every tetrahedron crossed for longer than a thousandth of a cell is
/// walked, in order. Returns the steps taken.
std::size_t ExpectWalkAgrees(const Mesh& mesh, const WalkMesh& walk, const glm::dvec3& origin,
  const glm::dvec3& direction, double cell, bool eachTetrahedron)
{
  const std::int32_t entry = EntryFace(mesh, walk, origin, direction);
  const auto path = BruteForcePath(mesh, origin, direction, 0.0);
  if (entry < 0)
  {
    EXPECT_TRUE(path.empty() || std::get<1>(path.back()) - std::get<0>(path.front()) < 1e-3 * cell);
    return 0;
  }
  bool left = false;
  const std::vector<uv::WalkSegment> segments = uv::Walk(entry, mesh.Corners, walk.Positions, walk.Neighbours,
    glm::vec3(origin), glm::vec3(direction), static_cast<int>(mesh.Count()) + 8, left);
  EXPECT_TRUE(left) << "the walk did not reach the boundary";
  EXPECT_FALSE(segments.empty());
  if (segments.empty() || path.empty())
    return segments.size();
  // Ray parameters are relative to the origin, a few mesh sizes away: float resolves 1e-6 of them.
  const double tolerance = 1e-5 * (glm::length(origin) + 2.0);
  EXPECT_NEAR(segments.front().Front, std::get<0>(path.front()), tolerance);
  EXPECT_NEAR(segments.back().Back, std::get<1>(path.back()), tolerance);
  double walked = 0.0;
  for (const uv::WalkSegment& segment : segments)
  {
    EXPECT_GE(segment.Back, segment.Front - tolerance) << "the walk went backwards in " << segment.Tetrahedron;
    walked += segment.Back - segment.Front;
  }
  // A convex mesh: the ray is inside from its first entry to its last exit (the brute force finds
  // every tetrahedron around an edge the ray runs along, so its lengths are not added up).
  EXPECT_NEAR(walked, std::get<1>(path.back()) - std::get<0>(path.front()), tolerance);
  if (!eachTetrahedron)
    return segments.size();
  std::size_t next = 0;
  for (const auto& [enter, leave, t] : path)
  {
    if (leave - enter < 1e-3 * cell)
      continue; // a corner grazed: rounding may take the ray through a neighbour instead
    while (next < segments.size() && segments[next].Tetrahedron != t)
      ++next;
    EXPECT_LT(next, segments.size()) << "tetrahedron " << t << " (crossed over " << leave - enter
                                     << ") was not walked, or out of order";
  }
  return segments.size();
}
}

TEST(TetrahedralWalk, NeighboursAreMutualAndTheBoundaryIsTheSurface)
{
  const Mesh mesh = Cubes(3, [](glm::dvec3 p) { return p; });
  const WalkMesh walk(mesh);
  for (std::size_t i = 0; i < walk.Neighbours.size(); ++i)
  {
    const std::int32_t across = walk.Neighbours[i];
    if (across >= 0)
      EXPECT_EQ(walk.Neighbours[across], static_cast<std::int32_t>(i));
  }
  EXPECT_EQ(walk.Boundary.size(), 6u * 9u * 2u); // two triangles per square of the cube's surface
}

TEST(TetrahedralWalk, TetrahedraWithARepeatedCornerBoundNothing)
{
  // A collapsed layer, once its points are matched by position: tetrahedra on two coincident
  // points, lying on the surface. Their faces are no boundary a ray could enter by (entering by one
  // of the two coincident faces, it left by the other at once, peel after peel).
  Mesh mesh = Cubes(3, [](glm::dvec3 p) { return p; });
  const std::size_t before = WalkMesh(mesh).Boundary.size(), sound = mesh.Count();
  const std::vector<std::uint32_t> surface(mesh.Corners.begin(), mesh.Corners.begin() + 4);
  mesh.Corners.insert(mesh.Corners.end(), { surface[0], surface[1], surface[2], surface[2] });
  mesh.Corners.insert(mesh.Corners.end(), { surface[3], surface[3], surface[1], surface[0] });
  const WalkMesh walk(mesh);
  EXPECT_EQ(walk.Boundary.size(), before);
  for (std::int32_t record : walk.Boundary)
    EXPECT_LT(std::size_t(record / 4), sound);
  for (std::size_t i = 4 * sound; i < walk.Neighbours.size(); ++i)
    EXPECT_EQ(walk.Neighbours[i], -1);
}

TEST(TetrahedralWalk, CoincidentPointsShareOneId)
{
  const std::vector<float> positions = { 0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 1e-7f };
  const std::vector<std::uint32_t> same =
    uv::CoincidentPointIds(positions, 3, [](auto begin, auto end, auto less) { std::sort(begin, end, less); });
  EXPECT_EQ(same, (std::vector<std::uint32_t>{ 0, 1, 0, 1, 4 }));
}

TEST(TetrahedralWalk, CoincidentTetrahedraMergeByPositionAndField)
{
  // Two tetrahedra on five points; then the first again in another corner order, the second again on
  // copies of its points (an append), and the second once more with another value at one corner.
  std::vector<float> points = { 0, 0, 0, 0.1f, 1, 0, 0, 0.2f, 0, 1, 0, 0.3f, 0, 0, 1, 0.4f, 1, 1, 1, 0.5f };
  std::vector<std::uint32_t> cells = { 0, 1, 2, 3, 1, 2, 3, 4, 3, 0, 2, 1 };
  for (int copy = 0; copy < 2; ++copy)
    for (std::uint32_t id : { 1u, 2u, 3u, 4u })
    {
      points.insert(points.end(), points.begin() + 4 * id, points.begin() + 4 * id + 4);
      points.back() += copy == 1 && id == 4 ? 0.25f : 0.0f;
      cells.push_back(static_cast<std::uint32_t>(points.size() / 4 - 1));
    }
  const auto sort = [](auto begin, auto end, auto less) { std::sort(begin, end, less); };
  const std::vector<std::uint32_t> same = uv::CoincidentPointIds(points, 4, sort);
  EXPECT_EQ(uv::CoincidentCellDensities<4>(cells, same, points, {}, sort),
    (std::vector<float>{ 2, 2, 0, 0, 1 }));
  const std::vector<std::uint32_t> firstTwo(cells.begin(), cells.begin() + 8);
  EXPECT_TRUE(uv::CoincidentCellDensities<4>(firstTwo, same, points, {}, sort).empty());
  // By ids alone (what the face order joins): only the repeat of the first on its own ids.
  EXPECT_EQ(uv::FirstCopies<4>(cells, sort), (std::vector<std::uint32_t>{ 0, 1, 0, 3, 4 }));
  EXPECT_TRUE(uv::FirstCopies<4>(firstTwo, sort).empty());
}

TEST(TetrahedralWalk, RaysCrossTheTetrahedraTheBruteForceFinds)
{
  // A warped cube: interior points moved, the surface flat (a convex mesh: one walk per ray).
  const Mesh mesh = Cubes(5, [](glm::dvec3 p) {
    const double inside = p.x * (1 - p.x) * p.y * (1 - p.y) * p.z * (1 - p.z);
    return p + 2.0 * inside * glm::dvec3(std::sin(9 * p.y), std::cos(7 * p.z), std::sin(5 * p.x));
  });
  const WalkMesh walk(mesh);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t steps = 0;
  for (int ray = 0; ray < 300; ++ray)
  {
    const double theta = 2.0 * M_PI * unit(random), z = 2.0 * unit(random) - 1.0;
    const glm::dvec3 centre(0.5);
    const glm::dvec3 origin =
      centre + 3.0 * glm::dvec3(std::sqrt(1 - z * z) * std::cos(theta), std::sqrt(1 - z * z) * std::sin(theta), z);
    const glm::dvec3 target(0.05 + 0.9 * unit(random), 0.05 + 0.9 * unit(random), 0.05 + 0.9 * unit(random));
    steps += ExpectWalkAgrees(mesh, walk, origin, glm::normalize(target - origin), 0.2, true);
  }
  EXPECT_GT(steps, 300u * 10u); // the rays did cross the mesh
}

TEST(TetrahedralWalk, RaysThroughVerticesAndAlongEdgesAndFacesStillCrossTheMesh)
{
  // The unwarped grid: rays along its lines run along edges and through vertices, those in its
  // planes along faces; every exit is a tie the products must break alike on both sides.
  const Mesh mesh = Cubes(3, [](glm::dvec3 p) { return p; });
  const WalkMesh walk(mesh);
  const double third = 1.0 / 3.0;
  const glm::dvec3 origins[] = { { -1.0, third, third }, { third, -1.0, 2 * third }, { 2 * third, third, -1.0 },
    { -1.0, 0.5, third }, { -1.0, -1.0, -1.0 }, { -1.0, 0.5, 0.25 }, { 2.0, 2 * third, 0.5 } };
  const glm::dvec3 directions[] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 0 }, { 1, 1, 1 }, { 1, 0, 0 },
    { -1, 0, 0 } };
  for (int ray = 0; ray < 7; ++ray)
  {
    const glm::dvec3 direction = glm::normalize(directions[ray]);
    EXPECT_GT(ExpectWalkAgrees(mesh, walk, origins[ray], direction, third, false), 0u) << "ray " << ray;
  }
}

TEST(TetrahedralWalk, RaysEnterAgainOnlyByTheFacesOffTheHull)
{
  // A cube with a notch cut into its top (non-convex) and the whole cube (convex).
  const auto identity = [](glm::dvec3 p) { return p; };
  const Mesh notched = Cubes(4, identity, [](int i, int, int k) { return !(i >= 1 && i <= 2 && k >= 2); });
  const auto reentryFaces = [](const Mesh& mesh, WalkMesh& walk) {
    const auto position = [&mesh](std::size_t t, int k) { return mesh.At(t, k); };
    return uv::MoveReentryFacesFirst(walk.Boundary, mesh.Corners,
      uv::MakeTetrahedronFaceAdjacency(mesh.Corners, Serial), position, Serial, 100000);
  };
  WalkMesh whole(Cubes(4, identity));
  EXPECT_EQ(reentryFaces(Cubes(4, identity), whole), 0u);
  WalkMesh walk(notched);
  const std::vector<std::int32_t> before = walk.Boundary;
  const std::size_t reentry = reentryFaces(notched, walk);
  // The notch's floor (2 x 4 squares) and its two walls (4 x 2 each), two triangles a square.
  EXPECT_EQ(reentry, 2u * (8u + 2u * 8u));
  std::vector<std::int32_t> sorted = walk.Boundary;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, before) << "the boundary was not only reordered";
  const std::vector<std::int32_t> first(walk.Boundary.begin(), walk.Boundary.begin() + reentry);
  // Random rays through the notch: each time one enters the mesh again (brute force, double), the
  // face it enters by is among the first ones.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int reentries = 0;
  for (int ray = 0; ray < 400; ++ray)
  {
    const glm::dvec3 origin(-1.0, unit(random), 0.55 + 0.45 * unit(random));
    const glm::dvec3 target(2.0, unit(random), 0.5 + 0.5 * unit(random));
    const glm::dvec3 direction = glm::normalize(target - origin);
    double reach = -1e300;
    for (const auto& [enter, leave, t] : BruteForcePath(notched, origin, direction, 0.0))
    {
      if (reach > -1e300 && enter > reach + 1e-9)
      {
        // The face of t the ray enters by at `enter`: the entering plane crossed last.
        int face = -1;
        double last = -1e300;
        for (int k = 0; k < 4; ++k)
        {
          const glm::dvec3 a = notched.At(t, (k + 1) % 4), b = notched.At(t, (k + 2) % 4),
                           c = notched.At(t, (k + 3) % 4);
          glm::dvec3 n = glm::cross(b - a, c - a);
          if (glm::dot(n, notched.At(t, k) - a) > 0.0)
            n = -n;
          const double along = glm::dot(n, direction);
          if (along < 0.0 && -glm::dot(n, origin - a) / along > last)
          {
            last = -glm::dot(n, origin - a) / along;
            face = k;
          }
        }
        ++reentries;
        EXPECT_NE(std::find(first.begin(), first.end(), 4 * t + face), first.end())
          << "ray " << ray << " enters again by tetrahedron " << t << "'s face " << face;
      }
      reach = std::max(reach, leave);
    }
  }
  EXPECT_GT(reentries, 100); // the rays did cross the notch
}
