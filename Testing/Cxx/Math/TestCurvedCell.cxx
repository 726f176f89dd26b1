// The curved-cell ray math (uvCurvedCell.h) against independent ground: with the trilinear basis a
// "curved" hexahedron is the linear one, whose exact bilinear-patch intersection
// (uvRayCellGeometry.h) gives the same parts; with a quadratic tetrahedron of straight edges, the
// parts are the linear tetrahedron's.
#include "uvCurvedCell.h"
#include "uvRayCellGeometry.h"

#include <gtest/gtest.h>

#include <random>

namespace
{
/// Trilinear shape functions in VTK's layout (weights, then all d/dr, all d/ds, all d/dt).
struct TrilinearBasis
{
  void operator()(const glm::dvec3& xi, double* w, double* d) const
  {
    double n[8];
    glm::dvec3 dn[8];
    uv::HexahedronBasis(xi, n, dn);
    for (int k = 0; k < 8; ++k)
    {
      w[k] = n[k];
      if (d)
      {
        d[k] = dn[k].x;
        d[8 + k] = dn[k].y;
        d[16 + k] = dn[k].z;
      }
    }
  }
};

/// VTK's quadratic tetrahedron: corners by barycentric l0..l3, then the edges 01, 12, 20, 03, 13, 23.
struct QuadraticTetraBasis
{
  void operator()(const glm::dvec3& xi, double* w, double* d) const
  {
    const double l[4] = { 1.0 - xi.x - xi.y - xi.z, xi.x, xi.y, xi.z };
    const glm::dvec3 dl[4] = { glm::dvec3(-1.0), { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
    glm::dvec3 dw[10];
    for (int k = 0; k < 4; ++k)
    {
      w[k] = l[k] * (2.0 * l[k] - 1.0);
      dw[k] = (4.0 * l[k] - 1.0) * dl[k];
    }
    for (int e = 0; e < 6; ++e)
    {
      const int a = edges[e][0], b = edges[e][1];
      w[4 + e] = 4.0 * l[a] * l[b];
      dw[4 + e] = 4.0 * (l[a] * dl[b] + l[b] * dl[a]);
    }
    for (int k = 0; d && k < 10; ++k)
    {
      d[k] = dw[k].x;
      d[10 + k] = dw[k].y;
      d[20 + k] = dw[k].z;
    }
  }
};

uv::Ray RandomRayThrough(std::mt19937& random, const glm::dvec3& centre, double size)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const glm::dvec3 direction = glm::normalize(glm::dvec3(u(random), u(random), u(random)));
  const glm::dvec3 aim = centre + 0.5 * size * glm::dvec3(u(random), u(random), u(random));
  return uv::Ray{ aim - 3.0 * size * direction, direction };
}

double TotalLength(const std::vector<uv::Interval>& parts)
{
  double length = 0.0;
  for (const uv::Interval& part : parts)
    length += part.Exit - part.Enter;
  return length;
}
} // namespace

TEST(CurvedCell, TrilinearHexahedronMatchesBilinearPatches)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  int crossed = 0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    glm::dvec3 p[8];
    std::int64_t ids[8];
    for (int k = 0; k < 8; ++k)
    {
      const auto& c = uv::HexahedronCorners[k];
      p[k] = glm::dvec3(c[0], c[1], c[2]) + glm::dvec3(jitter(random), jitter(random), jitter(random));
      ids[k] = k;
    }
    const uv::Ray ray = RandomRayThrough(random, glm::dvec3(0.5), 1.0);
    std::vector<uv::Interval> expected, parts;
    std::vector<double> scratch;
    uv::IntersectHexahedron(ray, p, ids, expected, scratch);
    const uv::CurvedCell<TrilinearBasis> cell(uv::CellFamily::Hexahedron, TrilinearBasis(), 8, p, nullptr);
    std::vector<std::array<glm::dvec3, 2>> xi;
    std::vector<uv::CurvedCell<TrilinearBasis>::Hit> hits;
    cell.Intersect(ray, parts, xi, hits);
    crossed += expected.empty() ? 0 : 1;
    ASSERT_NEAR(TotalLength(parts), TotalLength(expected), 1e-9) << "trial " << trial;
    ASSERT_EQ(parts.size(), xi.size());
    for (std::size_t i = 0; i < parts.size(); ++i)
    {
      // The ends' parametric coordinates map back to the ends' positions.
      EXPECT_LT(glm::length(cell.Point(xi[i][0]) - (ray.Origin + parts[i].Enter * ray.Direction)), 1e-9);
      EXPECT_LT(glm::length(cell.Point(xi[i][1]) - (ray.Origin + parts[i].Exit * ray.Direction)), 1e-9);
    }
  }
  EXPECT_GT(crossed, 1000); // most rays do cross the cell
}

TEST(CurvedCell, StraightQuadraticTetrahedronIsTheLinearOne)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
  for (int trial = 0; trial < 1000; ++trial)
  {
    glm::dvec3 p[10];
    p[0] = glm::dvec3(0.0);
    p[1] = glm::dvec3(1.0, 0.1 * u(random), 0.1 * u(random));
    p[2] = glm::dvec3(0.1 * u(random), 1.0, 0.1 * u(random));
    p[3] = glm::dvec3(0.1 * u(random), 0.1 * u(random), 1.0);
    for (int e = 0; e < 6; ++e)
      p[4 + e] = 0.5 * (p[edges[e][0]] + p[edges[e][1]]);
    double f[10];
    for (int k = 0; k < 10; ++k)
      f[k] = 0.3 * p[k].x - 0.7 * p[k].y + 0.2 * p[k].z;
    const uv::Ray ray = RandomRayThrough(random, glm::dvec3(0.25), 1.0);
    const std::int64_t ids[4] = { 0, 1, 2, 3 };
    uv::Interval expected;
    const bool crosses = uv::IntersectTetrahedron(ray, p, ids, expected);
    const uv::CurvedCell<QuadraticTetraBasis> cell(uv::CellFamily::Tetrahedron, QuadraticTetraBasis(), 10, p, f);
    std::vector<uv::Interval> parts;
    std::vector<std::array<glm::dvec3, 2>> xi;
    std::vector<uv::CurvedCell<QuadraticTetraBasis>::Hit> hits;
    cell.Intersect(ray, parts, xi, hits);
    ASSERT_NEAR(TotalLength(parts), crosses ? expected.Exit - expected.Enter : 0.0, 1e-9) << "trial " << trial;
    for (std::size_t i = 0; i < parts.size(); ++i)
    {
      // The field at the ends is the linear field there.
      const glm::dvec3 x = ray.Origin + parts[i].Enter * ray.Direction;
      EXPECT_NEAR(cell.Scalar(xi[i][0]), uv::TetrahedronScalar(p, f, x), 1e-9);
    }
  }
}

TEST(CurvedCell, CurvedTetrahedronAgainstSampledInsideTest)
{
  // Quadratic tetrahedra with edge nodes pushed off their edges (curved faces, some rays meet a
  // face twice): the parts' length against the length of the ray's samples the inverse map puts
  // inside the cell.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
  constexpr int Samples = 4000;
  int crossed = 0;
  for (int trial = 0; trial < 150; ++trial)
  {
    glm::dvec3 p[10] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    for (int e = 0; e < 6; ++e)
      p[4 + e] = 0.5 * (p[edges[e][0]] + p[edges[e][1]]) + 0.12 * glm::dvec3(u(random), u(random), u(random));
    const uv::CurvedCell<QuadraticTetraBasis> cell(uv::CellFamily::Tetrahedron, QuadraticTetraBasis(), 10, p, nullptr);
    const uv::Ray ray = RandomRayThrough(random, glm::dvec3(0.25), 1.0);
    std::vector<uv::Interval> parts;
    std::vector<std::array<glm::dvec3, 2>> xi;
    std::vector<uv::CurvedCell<QuadraticTetraBasis>::Hit> hits;
    cell.Intersect(ray, parts, xi, hits);
    const double span = 6.0, step = span / Samples; // the ray starts 3 sizes before the cell
    int inside = 0;
    for (int i = 0; i < Samples; ++i)
    {
      glm::dvec3 guess = uv::FamilyCentre(uv::CellFamily::Tetrahedron);
      inside += cell.Contains(ray.Origin + (i + 0.5) * step * ray.Direction, guess) ? 1 : 0;
    }
    crossed += inside > 0 ? 1 : 0;
    EXPECT_NEAR(TotalLength(parts), inside * step, 4 * step) << "trial " << trial;
  }
  EXPECT_GT(crossed, 75);
}
