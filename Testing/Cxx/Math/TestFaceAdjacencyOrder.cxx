// uvFaceAdjacencyOrder.h: on a convex mesh of tetrahedra the order is a true visibility order, checked
// independently by rays (along every sampled ray the tetrahedra it crosses come back to front), from
// eyes outside, inside and at infinity; a centroid order fails the same check; every face constraint
// holds on a twisted mesh; tetrahedra left out of the order still pass constraints on.
#include "uvBoundaryGapOrder.h"
#include "uvFaceAdjacencyOrder.h"
#include "uvTestTetrahedralCubes.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>

namespace
{
using uvtest::Mesh;
using uvtest::Cubes;
using uvtest::Crossing;

const auto Serial = [](std::size_t count, const auto& run) { run(0, count); };

std::vector<std::int32_t> Adjacency(const Mesh& mesh)
{
  return uv::MakeTetrahedronFaceAdjacency(mesh.Corners, Serial);
}

/// Back to front by centroid distance from `eye` (or along `towardsEye` for parallel projection).
std::vector<std::uint32_t> CentroidOrder(const Mesh& mesh, const std::vector<std::uint32_t>& cells,
  const glm::dvec3& eye, bool parallel)
{
  std::vector<std::uint32_t> order = cells;
  auto key = [&](std::uint32_t t) {
    glm::dvec3 c(0.0);
    for (int k = 0; k < 4; ++k)
      c += 0.25 * mesh.At(t, k);
    return parallel ? -glm::dot(c, eye) : glm::distance(c, eye);
  };
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) > key(b); });
  return order;
}

std::vector<std::uint32_t> ExactOrder(const Mesh& mesh, const std::vector<std::uint32_t>& cells, const glm::dvec3& eye,
  bool parallel, std::size_t* cycles = nullptr)
{
  std::vector<std::uint32_t> order = CentroidOrder(mesh, cells, eye, parallel);
  uv::FaceAdjacencyOrder sorter;
  sorter.Sort(order, mesh.Corners, [&](std::size_t t, int k) { return mesh.At(t, k); }, Adjacency(mesh), eye,
    parallel, Serial);
  if (cycles)
    *cycles = sorter.CyclesBroken;
  return order;
}

/// Each tetrahedron's place in `order`.
std::vector<std::size_t> Places(const Mesh& mesh, const std::vector<std::uint32_t>& order)
{
  std::vector<std::size_t> place(mesh.Count(), 0);
  for (std::size_t p = 0; p < order.size(); ++p)
    place[order[p]] = p;
  return place;
}

/// Pairs of consecutive tetrahedra along the ray origin + s direction (s >= 0) drawn in the wrong
/// order (the nearer first); `place` from Places.
int WrongOrderAlongRay(const Mesh& mesh, const std::vector<std::uint32_t>& order, const std::vector<std::size_t>& place,
  const glm::dvec3& origin, const glm::dvec3& direction)
{
  std::vector<std::pair<double, std::uint32_t>> met; // (mid parameter, tetrahedron)
  for (std::uint32_t t : order)
  {
    double enter, leave;
    if (Crossing(mesh, t, origin, direction, enter, leave) && leave - enter > 1e-9)
      met.emplace_back(0.5 * (enter + leave), t);
  }
  std::sort(met.begin(), met.end());
  int wrong = 0;
  for (std::size_t m = 1; m < met.size(); ++m)
    if (place[met[m].second] > place[met[m - 1].second]) // farther drawn after nearer
      ++wrong;
  return wrong;
}

/// Pairs of tetrahedra met by one of `rays` rays in the wrong order (the nearer drawn first), the
/// rays from the eye (or parallel to `towardsEye`) through random points of the unit box.
int WrongOrderAlongRays(const Mesh& mesh, const std::vector<std::uint32_t>& order, const glm::dvec3& eye, bool parallel,
  int rays)
{
  const std::vector<std::size_t> place = Places(mesh, order);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.02, 0.98);
  int wrong = 0;
  for (int r = 0; r < rays; ++r)
  {
    const glm::dvec3 target(unit(random), unit(random), unit(random));
    const glm::dvec3 direction = parallel ? -eye : glm::normalize(target - eye);
    const glm::dvec3 origin = parallel ? target - 10.0 * direction : eye;
    wrong += WrongOrderAlongRay(mesh, order, place, origin, direction);
  }
  return wrong;
}

std::vector<std::uint32_t> All(const Mesh& mesh)
{
  std::vector<std::uint32_t> cells(mesh.Count());
  std::iota(cells.begin(), cells.end(), 0u);
  return cells;
}
}

TEST(FaceAdjacencyOrder, AdjacencyOfCubes)
{
  const Mesh mesh = Cubes(3, [](glm::dvec3 p) { return p; });
  const auto neighbours = Adjacency(mesh);
  // 6 n^2 boundary triangles per side pair... every tetrahedron face is shared except the 2 * 6 n^2
  // triangles on the cube's surface.
  const auto boundary = std::count(neighbours.begin(), neighbours.end(), -1);
  EXPECT_EQ(boundary, 2 * 6 * 9);
  for (std::size_t t = 0; t < mesh.Count(); ++t)
    for (int k = 0; k < 4; ++k)
      if (neighbours[4 * t + k] >= 0)
      {
        const auto u = static_cast<std::size_t>(neighbours[4 * t + k]);
        EXPECT_EQ(std::count(neighbours.begin() + 4 * u, neighbours.begin() + 4 * u + 4, static_cast<std::int32_t>(t)), 1);
      }
}

TEST(FaceAdjacencyOrder, NoNeighbourAcrossAFaceOfThreeOrOnAFlatTetrahedron)
{
  // Points 0, 1, 2 make a face held by tetrahedra 0, 1 and 2; 3 and 4 share face 5 6 7; 5 has a
  // repeated id and would otherwise match 3 and 4 there.
  const std::vector<std::uint32_t> corners = { 0, 1, 2, 3, /**/ 0, 1, 2, 4, /**/ 2, 1, 0, 8, /**/
    5, 6, 7, 9, /**/ 7, 6, 5, 10, /**/ 5, 6, 7, 7 };
  const auto neighbours = uv::MakeTetrahedronFaceAdjacency(corners, Serial);
  const auto neighbour = [&](int t, int k) { return neighbours[4 * t + k]; };
  for (int t = 0; t < 3; ++t)
    EXPECT_EQ(neighbour(t, 3), -1) << t; // opposite corner 3: the face of three
  EXPECT_EQ(neighbour(3, 3), 4);
  EXPECT_EQ(neighbour(4, 3), 3);
  for (int k = 0; k < 4; ++k)
    EXPECT_EQ(neighbour(5, k), -1) << k;
  EXPECT_EQ(std::count(neighbours.begin(), neighbours.end(), -1), static_cast<long>(neighbours.size()) - 2);
}

TEST(FaceAdjacencyOrder, RaysMeetTheOrderBackToFrontOnAConvexMesh)
{
  // Sheared cubes: long thin tetrahedra whose centroids mislead.
  const Mesh mesh = Cubes(4, [](glm::dvec3 p) { return glm::dvec3(p.x + 0.8 * p.z, p.y, p.z * 0.3); });
  const std::vector<std::pair<glm::dvec3, bool>> eyes = { { { 3.0, -2.0, 1.5 }, false }, { { 0.6, 0.5, 0.16 }, false },
    { { -0.5, 2.5, -1.0 }, false }, { glm::normalize(glm::dvec3(0.3, -1.0, 0.8)), true } };
  int centroidWrong = 0;
  for (const auto& [eye, parallel] : eyes)
  {
    std::size_t cycles = 0;
    const auto order = ExactOrder(mesh, All(mesh), eye, parallel, &cycles);
    ASSERT_EQ(order.size(), mesh.Count());
    auto sorted = order;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, All(mesh));
    EXPECT_EQ(cycles, 0u);
    EXPECT_EQ(WrongOrderAlongRays(mesh, order, eye, parallel, 400), 0) << eye.x << " " << eye.y << " " << eye.z;
    centroidWrong += WrongOrderAlongRays(mesh, CentroidOrder(mesh, All(mesh), eye, parallel), eye, parallel, 400);
  }
  EXPECT_GT(centroidWrong, 0); // the check can fail: centroid order does
}

TEST(FaceAdjacencyOrder, ConstraintsHoldOnATwistedMeshAndThroughCellsLeftOut)
{
  const Mesh mesh = Cubes(5, [](glm::dvec3 p) {
    const double angle = 1.2 * p.z, c = std::cos(angle), s = std::sin(angle);
    const glm::dvec2 q(p.x - 0.5, p.y - 0.5);
    return glm::dvec3(c * q.x - s * q.y + 0.5, s * q.x + c * q.y + 0.5, p.z);
  });
  const auto neighbours = Adjacency(mesh);
  const glm::dvec3 eye(0.45, 0.55, -0.7);
  // Every other tetrahedron left out of the drawing: the rest must still respect each chain of
  // constraints through the left-out ones, which rays check.
  std::vector<std::uint32_t> drawn;
  for (std::uint32_t t = 0; t < mesh.Count(); t += 2)
    drawn.push_back(t);
  const auto order = ExactOrder(mesh, drawn, eye, false);
  EXPECT_EQ(order.size(), drawn.size());
  EXPECT_EQ(WrongOrderAlongRays(mesh, order, eye, false, 400), 0);
  const auto every = ExactOrder(mesh, All(mesh), eye, false);
  const std::vector<std::size_t> place = Places(mesh, every);
  int violated = 0;
  for (std::size_t t = 0; t < mesh.Count(); ++t)
    for (int k = 0; k < 4; ++k)
    {
      const std::int32_t u = neighbours[4 * t + k];
      if (u < 0)
        continue;
      // The face's plane, oriented away from t: the eye beyond it means u is in front of t.
      const glm::dvec3 a = mesh.At(t, (k + 1) % 4), b = mesh.At(t, (k + 2) % 4), c = mesh.At(t, (k + 3) % 4);
      glm::dvec3 n = glm::cross(b - a, c - a);
      if (glm::dot(n, mesh.At(t, k) - a) > 0.0)
        n = -n;
      const double side = glm::dot(n, eye - a);
      if (side > 0.0 && place[static_cast<std::size_t>(u)] < place[t])
        ++violated;
    }
  EXPECT_EQ(violated, 0);
}

namespace
{
/// Pairs of tetrahedra met in the wrong order (the nearer drawn first) by the rays of `grid`'s pixels.
int WrongOrderAlongPixelRays(const Mesh& mesh, const std::vector<std::uint32_t>& order, const uv::PixelGrid& grid)
{
  const std::vector<std::size_t> place = Places(mesh, order);
  const glm::dmat4 clipToModel = glm::inverse(grid.ModelToClip);
  int wrong = 0;
  for (int y = 0; y < grid.Height; ++y)
    for (int x = 0; x < grid.Width; ++x)
    {
      glm::dvec3 origin, step;
      grid.Ray(x, y, clipToModel, origin, step);
      wrong += WrongOrderAlongRay(mesh, order, place, origin, step);
    }
  return wrong;
}

/// The face order of every tetrahedron for the pixels of `grid` seen from `eye` (or along it,
/// parallel), with the gap constraints or without.
std::vector<std::uint32_t> OrderForPixels(const Mesh& mesh, const uv::PixelGrid& grid, const glm::dvec3& eye,
  bool parallel, bool gaps, std::size_t& constraints, std::size_t& cycles)
{
  const auto neighbours = Adjacency(mesh);
  const auto position = [&](std::size_t t, int k) { return mesh.At(t, k); };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  if (gaps)
    pairs = uv::GapConstraints(uv::BoundaryFaces(neighbours), position, grid, Serial);
  constraints = pairs.size();
  std::vector<std::uint32_t> order = CentroidOrder(mesh, All(mesh), eye, parallel);
  uv::FaceAdjacencyOrder sorter;
  sorter.Sort(order, mesh.Corners, position, neighbours, eye, parallel, Serial, pairs);
  cycles = sorter.CyclesBroken;
  return order;
}

/// A long plate and a block floating above its near end: each one cube of 6 tetrahedra. From above
/// the plate's far end, rays through the block go on to the plate, whose long tetrahedra have
/// their centroids nearer the eye than the block's.
Mesh PlateAndBlock()
{
  const auto box = [](glm::dvec3 low, glm::dvec3 high) {
    return Cubes(1, [=](glm::dvec3 p) { return low + (high - low) * p; });
  };
  Mesh mesh = box({ -2.0, 0.0, 0.0 }, { 10.0, 1.0, 0.3 });
  const Mesh block = box({ 1.0, 0.0, 1.0 }, { 2.0, 1.0, 1.5 });
  const auto offset = static_cast<std::uint32_t>(mesh.Points.size());
  mesh.Points.insert(mesh.Points.end(), block.Points.begin(), block.Points.end());
  for (std::uint32_t id : block.Corners)
    mesh.Corners.push_back(id + offset);
  return mesh;
}

const glm::dvec3 Target(1.5, 0.5, 0.7);

uv::PixelGrid Perspective(const glm::dvec3& eye, int size)
{
  uv::PixelGrid grid;
  grid.ModelToClip =
    glm::perspective(glm::radians(40.0), 1.0, 0.05, 30.0) * glm::lookAt(eye, Target, glm::dvec3(0.0, 0.0, 1.0));
  grid.Width = grid.Height = size;
  return grid;
}
}

TEST(BoundaryGapOrder, ConvexityOfTheBoundary)
{
  const auto identity = [](glm::dvec3 p) { return p; };
  const auto convex = [](const Mesh& mesh) {
    return uv::BoundaryIsConvex(mesh.Corners, [&](std::size_t t, int k) { return mesh.At(t, k); }, Adjacency(mesh));
  };
  EXPECT_TRUE(convex(Cubes(3, identity)));
  EXPECT_TRUE(convex(Cubes(3, [](glm::dvec3 p) { return glm::dvec3(p.x + 0.8 * p.z, p.y, 0.3 * p.z); })));
  EXPECT_FALSE(convex(PlateAndBlock()));
  // Two separate cubes: each convex, their union not.
  EXPECT_FALSE(convex(Cubes(3, identity, [](int i, int, int) { return i != 1; })));
  // A dent: one corner cube left out.
  EXPECT_FALSE(convex(Cubes(3, identity, [](int i, int j, int k) { return i + j + k > 0; })));
}

TEST(BoundaryGapOrder, PixelRaysMeetTheOrderBackToFrontAcrossGaps)
{
  const Mesh mesh = PlateAndBlock();
  const std::vector<glm::dvec3> eyes = { { 6.0, 0.5, 4.0 }, { 8.0, 0.2, 2.5 }, { 4.0, 1.5, 3.0 } };
  int withoutGaps = 0;
  for (const glm::dvec3& eye : eyes)
  {
    const uv::PixelGrid grid = Perspective(eye, 40);
    std::size_t constraints = 0, cycles = 0;
    const auto order = OrderForPixels(mesh, grid, eye, false, true, constraints, cycles);
    auto sorted = order;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, All(mesh));
    EXPECT_GT(constraints, 0u);
    EXPECT_EQ(cycles, 0u);
    EXPECT_EQ(WrongOrderAlongPixelRays(mesh, order, grid), 0) << eye.x << " " << eye.y << " " << eye.z;
    withoutGaps += WrongOrderAlongPixelRays(mesh, OrderForPixels(mesh, grid, eye, false, false, constraints, cycles), grid);
  }
  EXPECT_GT(withoutGaps, 0); // the check can fail: the face order alone does across the gap
}

TEST(BoundaryGapOrder, ParallelProjection)
{
  const Mesh mesh = PlateAndBlock();
  const glm::dvec3 towardsEye = glm::normalize(glm::dvec3(4.5, 0.0, 2.75));
  uv::PixelGrid grid;
  grid.ModelToClip = glm::ortho(-2.0, 2.0, -2.0, 2.0, 0.1, 30.0) *
    glm::lookAt(Target + 8.0 * towardsEye, Target, glm::dvec3(0.0, 0.0, 1.0));
  grid.Width = grid.Height = 40;
  std::size_t constraints = 0, cycles = 0;
  const auto order = OrderForPixels(mesh, grid, towardsEye, true, true, constraints, cycles);
  EXPECT_GT(constraints, 0u);
  EXPECT_EQ(WrongOrderAlongPixelRays(mesh, order, grid), 0);
  const auto faceOnly = OrderForPixels(mesh, grid, towardsEye, true, false, constraints, cycles);
  EXPECT_GT(WrongOrderAlongPixelRays(mesh, faceOnly, grid), 0);
}

TEST(BoundaryGapOrder, AConvexMeshHasNoGapConstraint)
{
  const Mesh mesh = Cubes(4, [](glm::dvec3 p) { return glm::dvec3(p.x + 0.8 * p.z, p.y, p.z * 0.3); });
  const auto neighbours = Adjacency(mesh);
  const auto pairs = uv::GapConstraints(uv::BoundaryFaces(neighbours),
    [&](std::size_t t, int k) { return mesh.At(t, k); }, Perspective(glm::dvec3(3.0, -2.0, 1.5), 40), Serial);
  EXPECT_TRUE(pairs.empty());
}

TEST(BoundaryGapOrder, FacesOnTheHullAddNoPair)
{
  // The rays of the faces off the hull alone find the very pairs all boundary faces find.
  const Mesh mesh = PlateAndBlock();
  const auto position = [&](std::size_t t, int k) { return mesh.At(t, k); };
  const auto boundary = uv::BoundaryFaces(Adjacency(mesh));
  const auto off = uv::FacesOffTheHull(boundary, position, Serial);
  // The plate's top and the block's bottom and two ends (2 triangles each) are off the hull.
  EXPECT_EQ(off.size(), 8u);
  EXPECT_EQ(boundary.size(), 24u);
  for (const glm::dvec3& eye : { glm::dvec3(6.0, 0.5, 4.0), glm::dvec3(-3.0, 0.2, 1.2), glm::dvec3(1.5, 0.5, 0.6) })
  {
    const auto all = uv::GapConstraints(boundary, position, Perspective(eye, 40), Serial);
    EXPECT_EQ(uv::GapConstraints(off, position, Perspective(eye, 40), Serial), all);
  }
}

TEST(BoundaryGapOrder, ScreenBoundsStayOnTheImage)
{
  const uv::PixelGrid grid = Perspective(glm::dvec3(6.0, 0.5, 4.0), 40);
  const glm::dmat4 clipToModel = glm::inverse(grid.ModelToClip);
  // Model points at normalised device coordinates (x, y), halfway in depth.
  const auto at = [&](double x, double y) {
    const glm::dvec4 p = clipToModel * glm::dvec4(x, y, 0.0, 1.0);
    return glm::dvec3(p) / p.w;
  };
  int x0, x1, y0, y1;
  // A few pixels around pixel (10, 20), whose centre is at ((10.5 / 40) * 2 - 1, (20.5 / 40) * 2 - 1).
  const glm::dvec3 small[3] = { at(-0.5, 0.0), at(-0.45, 0.05), at(-0.5, 0.05) };
  ASSERT_TRUE(uv::ScreenBounds(grid, small, x0, x1, y0, y1));
  EXPECT_TRUE(x0 <= 10 && 10 <= x1 && y0 <= 20 && 20 <= y1) << x0 << " " << x1 << " " << y0 << " " << y1;
  // Billions of pixels to the side: no pixel (not an int overflow and a loop over billions).
  const glm::dvec3 aside[3] = { at(1e9, 0.0), at(2e9, 0.0), at(1e9, 1e9) };
  EXPECT_FALSE(uv::ScreenBounds(grid, aside, x0, x1, y0, y1));
  // Across the whole image from billions of pixels on either side: the whole image.
  const glm::dvec3 across[3] = { at(-1e9, -1e9), at(1e9, -1e9), at(0.0, 1e9) };
  ASSERT_TRUE(uv::ScreenBounds(grid, across, x0, x1, y0, y1));
  EXPECT_EQ(x0, 0);
  EXPECT_EQ(x1, 39);
  EXPECT_EQ(y0, 0);
  EXPECT_EQ(y1, 39);
}

TEST(BoundaryGapOrder, PixelsOutsideAProjectedTriangleMissIt)
{
  // Random triangles, some crossing the near plane or seen nearly edge-on: wherever a pixel's ray
  // meets one exactly, its centre is not outside the triangle's projection (the prefilter that
  // spares GapConstraints the exact test loses no crossing), and most pixels of the bounds are.
  const uv::PixelGrid grid = Perspective(glm::dvec3(6.0, 0.5, 4.0), 40);
  const glm::dmat4 clipToModel = glm::inverse(grid.ModelToClip);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::size_t met = 0, bounded = 0, passedOver = 0, projected = 0;
  for (int n = 0; n < 400; ++n)
  {
    const glm::dvec3 centre = Target + 1.5 * glm::dvec3(unit(random), unit(random), unit(random));
    const double size = n % 4 == 0 ? 3.0 : 0.15;
    glm::dvec3 p[3] = { centre + size * glm::dvec3(unit(random), unit(random), unit(random)),
      centre + size * glm::dvec3(unit(random), unit(random), unit(random)), centre };
    if (n % 7 == 0)
      p[2] = 0.5 * (p[0] + p[1]) + 1e-7 * glm::dvec3(unit(random), unit(random), unit(random)); // edge-on
    int x0, x1, y0, y1;
    uv::ScreenTriangle screen;
    if (!uv::ScreenBounds(grid, p, x0, x1, y0, y1) || !uv::ProjectTriangle(grid, p, screen))
      continue;
    ++projected;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
      {
        glm::dvec3 origin, step;
        grid.Ray(x, y, clipToModel, origin, step);
        double at;
        const bool outside = screen.Outside(x + 0.5, y + 0.5, 0.01);
        ++bounded;
        passedOver += outside ? 1 : 0;
        if (uv::RayMeetsTriangle(origin, step, p, at))
        {
          ++met;
          EXPECT_FALSE(outside) << "triangle " << n << ", pixel " << x << " " << y;
        }
      }
  }
  EXPECT_GT(projected, 200u);
  EXPECT_GT(met, 1000u);
  EXPECT_GT(passedOver, bounded / 3);
}

namespace
{
/// GapConstraints the slow way: every face against the ray of every pixel, no bounds, no bands.
std::vector<std::pair<std::uint32_t, std::uint32_t>> GapPairsOfEveryPixel(
  const Mesh& mesh, const std::vector<std::pair<std::uint32_t, int>>& faces, const uv::PixelGrid& grid)
{
  const uv::PixelRays rays(grid);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  std::vector<uv::GapCrossing> crossings;
  std::vector<std::uint32_t> left;
  for (int y = 0; y < grid.Height; ++y)
    for (int x = 0; x < grid.Width; ++x)
    {
      glm::dvec3 origin, step;
      rays.At(x, y, origin, step);
      crossings.clear();
      for (const auto& face : faces)
      {
        const glm::dvec3 p[3] = { mesh.At(face.first, (face.second + 1) % 4), mesh.At(face.first, (face.second + 2) % 4),
          mesh.At(face.first, (face.second + 3) % 4) };
        glm::dvec3 outward = glm::cross(p[1] - p[0], p[2] - p[0]);
        if (glm::dot(outward, mesh.At(face.first, face.second) - p[0]) > 0.0)
          outward = -outward;
        double at;
        if (uv::RayMeetsTriangle(origin, step, p, at))
          crossings.push_back({ 0, face.first, at, glm::dot(outward, step) > 0.0 });
      }
      uv::PairsAlongRay(crossings.begin(), crossings.end(), left, pairs);
    }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}
}

TEST(BoundaryGapOrder, BandsOfRowsFindThePairsOfEveryPixel)
{
  // A warped block of cubes with tunnels and a notch: gaps seen from outside, from inside a tunnel
  // (faces crossing the near plane) and along parallel rays, on images whose rows make one band
  // each or several, cut by a parallel loop into uneven pieces.
  const Mesh mesh = Cubes(5,
    [](glm::dvec3 p) { return glm::dvec3(p.x + 0.3 * p.z * p.z, p.y + 0.1 * std::sin(3.0 * p.x), p.z); },
    [](int i, int j, int k) { return !(j == 2 && k % 2 == 1) && !(i == 4 && k == 4) && !(i == 1 && j == 3); });
  const auto boundary = uv::BoundaryFaces(Adjacency(mesh));
  const auto position = [&](std::size_t t, int k) { return mesh.At(t, k); };
  const auto uneven = [](std::size_t count, const auto& run) {
    for (std::size_t begin = 0; begin < count; begin += 3)
      run(begin, std::min(count, begin + 3));
  };
  const glm::dvec3 centre(0.6, 0.5, 0.5);
  std::vector<uv::PixelGrid> grids;
  for (const glm::dvec3& eye : { glm::dvec3(3.0, -2.0, 1.5), glm::dvec3(0.5, 2.6, 0.9), glm::dvec3(0.2, 0.5, 0.7) })
    for (int height : { 9, 13, 29, 150 })
    {
      uv::PixelGrid grid;
      grid.ModelToClip = glm::perspective(glm::radians(50.0), 1.3, 0.05, 30.0) *
        glm::lookAt(eye, centre, glm::dvec3(0.0, 0.0, 1.0));
      grid.Width = height * 4 / 3;
      grid.Height = height;
      grids.push_back(grid);
    }
  uv::PixelGrid parallel;
  parallel.ModelToClip = glm::ortho(-1.2, 1.2, -1.0, 1.0, 0.1, 30.0) *
    glm::lookAt(centre + glm::dvec3(3.0, 1.0, 2.0), centre, glm::dvec3(0.0, 0.0, 1.0));
  parallel.Width = 90;
  parallel.Height = 70;
  grids.push_back(parallel);
  std::size_t found = 0;
  for (const uv::PixelGrid& grid : grids)
  {
    const auto expected = GapPairsOfEveryPixel(mesh, boundary, grid);
    found += expected.size();
    EXPECT_EQ(uv::GapConstraints(boundary, position, grid, Serial), expected) << grid.Width << "x" << grid.Height;
    EXPECT_EQ(uv::GapConstraints(boundary, position, grid, uneven), expected) << grid.Width << "x" << grid.Height;
  }
  EXPECT_GT(found, 100u); // the views see gaps
}
