// Projected-tetrahedron classification and thick vertex (uvProjectedTetrahedron.h), and the
// visibility sort (uvVisibilitySort.h).
#include "uvProjectedTetrahedron.h"
#include "uvRayCellGeometry.h"
#include "uvVisibilitySort.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>
#include <tuple>

namespace
{
using Points = std::array<glm::dvec2, 4>;

bool InTriangle(const glm::dvec2& q, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, double margin)
{
  const double area = uv::Orient2D(a, b, c);
  if (std::abs(area) == 0.0)
  {
    return false;
  }
  const double s = area > 0 ? 1.0 : -1.0;
  const double scale = margin * std::abs(area);
  return s * uv::Orient2D(a, b, q) > scale && s * uv::Orient2D(b, c, q) > scale && s * uv::Orient2D(c, a, q) > scale;
}

/// Within `margin` of an edge of the outline or of a fan triangle: sampling there says nothing.
bool NearAnyLine(const glm::dvec2& q, const std::vector<glm::dvec2>& points, double margin)
{
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    for (std::size_t j = i + 1; j < points.size(); ++j)
    {
      const glm::dvec2 d = points[j] - points[i];
      const double length = glm::length(d);
      if (length == 0.0)
        continue;
      const double t = glm::dot(q - points[i], d) / (length * length);
      if (t > -0.01 && t < 1.01 && std::abs(uv::Orient2D(points[i], points[j], q)) / length < margin)
        return true;
    }
  }
  return false;
}

/// Every sample point inside the outline (the convex hull of the 4 points) lies in exactly one fan
/// triangle, and no point outside lies in any.
void ExpectFanTilesOutline(const Points& p, std::mt19937& random)
{
  const uv::ProjectionClass c = uv::ClassifyProjection(p, 1e-12);
  ASSERT_GT(c.Class, 0);
  const glm::dvec2 t = uv::ThickVertex(c, p);
  std::vector<glm::dvec2> all(p.begin(), p.end());
  all.push_back(t);
  glm::dvec2 low = p[0], high = p[0];
  for (const auto& q : p)
  {
    low = glm::min(low, q);
    high = glm::max(high, q);
  }
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double margin = 1e-6 * glm::length(high - low);
  for (int sample = 0; sample < 400; ++sample)
  {
    const glm::dvec2 q = low + glm::dvec2(u(random), u(random)) * (high - low);
    if (NearAnyLine(q, all, margin))
      continue;
    bool inHull = false;
    for (int skip = 0; skip < 4; ++skip)
    {
      std::array<glm::dvec2, 3> tri;
      for (int k = 0, n = 0; k < 4; ++k)
        if (k != skip)
          tri[n++] = p[k];
      inHull = inHull || InTriangle(q, tri[0], tri[1], tri[2], 0.0);
    }
    int covering = 0;
    for (int f = 0; f < c.TriangleCount; ++f)
    {
      covering += InTriangle(q, t, p[c.Triangles[f][0]], p[c.Triangles[f][1]], 0.0) ? 1 : 0;
    }
    ASSERT_EQ(covering, inHull ? 1 : 0) << "class " << c.Class << " sample " << q.x << "," << q.y;
  }
}
} // namespace

TEST(ProjectedTetrahedron, ClassesOfExactConfigurations)
{
  const glm::dvec2 a(0, 0), b(4, 0), c(0, 4), inside(1, 1), onEdge(2, 0), far(4, 4);
  // Class 1: each vertex in turn inside the others' triangle.
  for (int k = 0; k < 4; ++k)
  {
    Points p;
    std::array<glm::dvec2, 3> outer = { a, b, c };
    for (int i = 0, n = 0; i < 4; ++i)
      p[i] = i == k ? inside : outer[n++];
    const uv::ProjectionClass pc = uv::ClassifyProjection(p);
    EXPECT_EQ(pc.Class, 1);
    EXPECT_EQ(pc.TriangleCount, 3);
    EXPECT_NE(pc.Side[k], 0);
    for (int i = 0; i < 4; ++i)
      if (i != k)
        EXPECT_EQ(pc.Side[i], -pc.Side[k]);
    const glm::dvec2 t = uv::ThickVertex(pc, p);
    EXPECT_NEAR(glm::length(t - inside), 0.0, 1e-15);
  }
  // Class 2: a convex quadrilateral, vertices in every order.
  std::array<int, 4> order = { 0, 1, 2, 3 };
  const Points quad = { a, b, far, c };
  do
  {
    Points p;
    for (int i = 0; i < 4; ++i)
      p[i] = quad[order[i]];
    const uv::ProjectionClass pc = uv::ClassifyProjection(p);
    EXPECT_EQ(pc.Class, 2);
    EXPECT_EQ(pc.TriangleCount, 4);
    EXPECT_NEAR(glm::length(uv::ThickVertex(pc, p) - glm::dvec2(2, 2)), 0.0, 1e-14); // the diagonals' crossing
  } while (std::next_permutation(order.begin(), order.end()));
  // Class 3: a vertex on an edge of the others' triangle; class 4: two vertices coincide; in every order.
  for (const auto& [fourth, expected, triangles] :
    { std::tuple<glm::dvec2, int, int>{ onEdge, 3, 2 }, { a, 4, 1 } })
  {
    order = { 0, 1, 2, 3 };
    const Points base = { a, b, c, fourth };
    do
    {
      Points p;
      for (int i = 0; i < 4; ++i)
        p[i] = base[order[i]];
      const uv::ProjectionClass pc = uv::ClassifyProjection(p);
      EXPECT_EQ(pc.Class, expected);
      EXPECT_EQ(pc.TriangleCount, triangles);
      EXPECT_NEAR(glm::length(uv::ThickVertex(pc, p) - fourth), 0.0, 1e-15);
    } while (std::next_permutation(order.begin(), order.end()));
  }
  // All on a line: nothing to draw.
  EXPECT_EQ(uv::ClassifyProjection({ a, b, onEdge, glm::dvec2(7, 0) }).Class, 0);
  EXPECT_EQ(uv::ClassifyProjection({ a, a, a, a }).Class, 0);
}

TEST(ProjectedTetrahedron, EverySignPatternIsOneClass)
{
  // Each of the 81 sign patterns of the dependency either cannot occur (the A_k sum to zero) or
  // maps to exactly one class; realise the possible ones from random points near a degenerate
  // configuration and check the fan of each.
  std::mt19937 random(7);
  std::normal_distribution<double> n(0.0, 1.0);
  std::set<std::array<int, 4>> seen;
  for (int trial = 0; trial < 20000; ++trial)
  {
    Points p;
    for (auto& q : p)
      q = glm::dvec2(std::round(4 * n(random)), std::round(4 * n(random))); // small integers: exact zeros happen
    const uv::ProjectionClass pc = uv::ClassifyProjection(p);
    const std::array<double, 4> a = uv::AffineDependency(p);
    EXPECT_DOUBLE_EQ(a[0] + a[1] + a[2] + a[3], 0.0);
    if (pc.Class == 0)
      continue;
    seen.insert(pc.Side);
    ExpectFanTilesOutline(p, random);
  }
  // 14 patterns of classes 1-2 (8 + 6), 24 of class 3, 12 of class 4.
  int byClass[5] = { 0, 0, 0, 0, 0 };
  for (const auto& s : seen)
  {
    const int zeros = static_cast<int>(std::count(s.begin(), s.end(), 0));
    const int positives = static_cast<int>(std::count(s.begin(), s.end(), 1));
    byClass[zeros == 2 ? 4 : zeros == 1 ? 3 : (positives == 2 ? 2 : 1)]++;
  }
  EXPECT_EQ(byClass[1], 8);
  EXPECT_EQ(byClass[2], 6);
  EXPECT_EQ(byClass[3], 24);
  EXPECT_EQ(byClass[4], 12);
}

TEST(ProjectedTetrahedron, NearDegenerateFansStillTile)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 300; ++trial)
  {
    // A vertex pushed 1e-9 off an edge, or off another vertex, or the projection nearly a line.
    Points p = { glm::dvec2(u(random), u(random)), glm::dvec2(u(random), u(random)),
      glm::dvec2(u(random), u(random)), glm::dvec2(0.0) };
    const double w = 0.5 + 0.4 * u(random);
    const glm::dvec2 jitter(1e-9 * u(random), 1e-9 * u(random));
    switch (trial % 3)
    {
      case 0: p[3] = w * p[0] + (1 - w) * p[1] + jitter; break;
      case 1: p[3] = p[2] + jitter; break;
      default: p[2] = w * p[0] + (1 - w) * p[1] + jitter; p[3] = 0.3 * p[0] + 0.7 * p[1] + 2.0 * jitter; break;
    }
    std::shuffle(p.begin(), p.end(), random);
    const uv::ProjectionClass pc = uv::ClassifyProjection(p, 1e-12);
    if (pc.Class == 0)
      continue;
    ExpectFanTilesOutline(p, random);
  }
}

TEST(ProjectedTetrahedron, ThickVertexIsTheExactChord)
{
  // Random tetrahedra before a perspective camera at the origin looking down -z: the two points
  // the thick vertex stands for are where the eye ray through it enters and leaves the tetrahedron.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    glm::dvec3 v[4];
    for (auto& x : v)
      x = glm::dvec3(u(random), u(random), -4.0 + u(random));
    if (trial % 4 == 3)
      v[3] = 0.25 * (v[0] + v[1] + v[2]) + 1e-4 * glm::dvec3(u(random), u(random), u(random)); // a sliver
    Points p;
    std::array<double, 4> w;
    for (int k = 0; k < 4; ++k)
    {
      w[k] = -v[k].z;
      p[k] = glm::dvec2(v[k].x, v[k].y) / w[k];
    }
    const uv::ProjectionClass pc = uv::ClassifyProjection(p, 1e-12);
    if (pc.Class == 0)
      continue;
    const glm::dvec2 t = uv::ThickVertex(pc, p);
    glm::dvec3 ends[2];
    for (int side = 0; side < 2; ++side)
    {
      const auto mu = uv::SideWeights3D(pc, side == 0 ? 1 : -1, w);
      ends[side] = mu[0] * v[0] + mu[1] * v[1] + mu[2] * v[2] + mu[3] * v[3];
      EXPECT_NEAR(ends[side].x / -ends[side].z, t.x, 1e-9);
      EXPECT_NEAR(ends[side].y / -ends[side].z, t.y, 1e-9);
    }
    uv::Ray ray{ glm::dvec3(0.0), glm::normalize(glm::dvec3(t, -1.0)) };
    const std::int64_t ids[4] = { 0, 1, 2, 3 };
    uv::Interval chord;
    if (!uv::IntersectTetrahedron(ray, v, ids, chord))
      continue; // the ray grazes an edge: the chord has no length to compare
    const double near = std::min(glm::length(ends[0]), glm::length(ends[1]));
    const double farther = std::max(glm::length(ends[0]), glm::length(ends[1]));
    EXPECT_NEAR(near, chord.Enter, 1e-7);
    EXPECT_NEAR(farther, chord.Exit, 1e-7);
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

TEST(VisibilitySort, OrderedKeysFollowFloats)
{
  const std::vector<float> values = { -1e30f, -2.5f, -0.0f, 0.0f, 1e-30f, 0.5f, 3.0f, 1e30f };
  for (std::size_t i = 0; i + 1 < values.size(); ++i)
  {
    EXPECT_LE(uv::OrderedKey(values[i]), uv::OrderedKey(values[i + 1]));
  }
}

TEST(VisibilitySort, RadixSortIsAStableSort)
{
  std::mt19937 random(5);
  for (std::size_t n : { 0, 1, 2, 100, 5000, 200001 })
  {
    std::uniform_real_distribution<float> u(-100.0f, 100.0f);
    std::vector<float> distance(n);
    for (auto& d : distance)
      d = std::round(u(random) * 10.0f) / 10.0f; // ties, to check stability
    std::vector<std::uint32_t> keys(n), cells(n), scratchKeys, scratchCells;
    for (std::size_t i = 0; i < n; ++i)
    {
      keys[i] = uv::OrderedKey(distance[i]);
      cells[i] = static_cast<std::uint32_t>(i);
    }
    std::vector<std::uint32_t> expected(cells);
    std::stable_sort(expected.begin(), expected.end(), [&](std::uint32_t x, std::uint32_t y) { return distance[x] < distance[y]; });
    // Seven chunks of any length, and the default chunking (one chunk for short lists).
    std::vector<std::uint32_t> defaultKeys(keys), defaultCells(cells);
    uv::RadixSortPairs(keys, cells, scratchKeys, scratchCells, uv::SerialChunks{}, 7, 1);
    EXPECT_EQ(cells, expected);
    EXPECT_TRUE(std::is_sorted(keys.begin(), keys.end()));
    uv::RadixSortPairs(defaultKeys, defaultCells, scratchKeys, scratchCells, uv::SerialChunks{});
    EXPECT_EQ(defaultCells, expected);
  }
}
