// uvLatticeBasis.h: the Lagrange and Bernstein bases of tetrahedra (order 1 to 4), wedges and
// hexahedra (order 1 to 3) on the equispaced lattice, checked by their defining properties (VTK's
// own cells are compared with the reference's use of them in Testing/Python/test_higher_order.py).
#include "uvLatticeBasis.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace
{
/// Every lattice index of `order`, in an arbitrary order (the basis must not care which).
std::vector<uv::SimplexIndex> Lattice(int order)
{
  std::vector<uv::SimplexIndex> nodes;
  for (int a = order; a >= 0; --a)
    for (int b = 0; a + b <= order; ++b)
      for (int c = order - a - b; c >= 0; --c)
        nodes.push_back({ a, b, c, order - a - b - c });
  return nodes;
}

glm::dvec3 NodePosition(int order, const uv::SimplexIndex& index)
{
  return glm::dvec3(index[0], index[1], index[2]) / double(order);
}

std::vector<glm::dvec3> InsidePoints(int count)
{
  std::mt19937 random(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<glm::dvec3> points;
  while (static_cast<int>(points.size()) < count)
  {
    const glm::dvec3 xi(unit(random), unit(random), unit(random));
    if (xi.x + xi.y + xi.z <= 1.0)
      points.push_back(xi);
  }
  return points;
}

constexpr uv::SimplexBasisKind Kinds[] = { uv::SimplexBasisKind::Lagrange, uv::SimplexBasisKind::Bernstein };
}

TEST(LatticeBasis, LatticeSizesAndIndicesOfVtkParametricCoordinates)
{
  for (int order = 1; order <= 4; ++order)
  {
    const std::vector<uv::SimplexIndex> nodes = Lattice(order);
    EXPECT_EQ(static_cast<int>(nodes.size()), (order + 1) * (order + 2) * (order + 3) / 6);
    for (const uv::SimplexIndex& index : nodes)
      EXPECT_EQ(uv::SimplexIndexAt(order, NodePosition(order, index) + glm::dvec3(1e-9, -1e-9, 0.0)), index);
  }
}

TEST(LatticeBasis, PartitionOfUnityAndLinearPrecision)
{
  // Both bases sum to one and reproduce x = xi from nodes at their lattice positions (the Bernstein
  // basis from control points there), so a straight cell's map is the identity.
  for (const uv::SimplexBasisKind kind : Kinds)
    for (int order = 1; order <= 4; ++order)
    {
      const std::vector<uv::SimplexIndex> nodes = Lattice(order);
      std::vector<double> w(nodes.size());
      for (const glm::dvec3& xi : InsidePoints(50))
      {
        uv::EvaluateSimplexBasis(kind, order, nodes, xi, w.data(), nullptr);
        double sum = 0.0;
        glm::dvec3 mapped(0.0);
        for (std::size_t k = 0; k < nodes.size(); ++k)
        {
          sum += w[k];
          mapped += w[k] * NodePosition(order, nodes[k]);
        }
        EXPECT_NEAR(sum, 1.0, 1e-12);
        EXPECT_NEAR(glm::length(mapped - xi), 0.0, 1e-12);
      }
    }
}

TEST(LatticeBasis, LagrangeInterpolatesAtItsNodes)
{
  for (int order = 1; order <= 4; ++order)
  {
    const std::vector<uv::SimplexIndex> nodes = Lattice(order);
    std::vector<double> w(nodes.size());
    for (std::size_t j = 0; j < nodes.size(); ++j)
    {
      uv::EvaluateSimplexBasis(uv::SimplexBasisKind::Lagrange, order, nodes, NodePosition(order, nodes[j]), w.data(), nullptr);
      for (std::size_t k = 0; k < nodes.size(); ++k)
        EXPECT_NEAR(w[k], j == k ? 1.0 : 0.0, 1e-12) << "order " << order << " node " << j << " weight " << k;
    }
  }
}

TEST(LatticeBasis, BernsteinIsNonNegativeAndInterpolatesOnlyAtCorners)
{
  const int order = 3;
  const std::vector<uv::SimplexIndex> nodes = Lattice(order);
  std::vector<double> w(nodes.size());
  for (const glm::dvec3& xi : InsidePoints(50))
  {
    uv::EvaluateSimplexBasis(uv::SimplexBasisKind::Bernstein, order, nodes, xi, w.data(), nullptr);
    for (double weight : w)
      EXPECT_GE(weight, 0.0);
  }
  // At an edge's interior lattice point a Bernstein basis is not a delta (control points, not nodes).
  const uv::SimplexIndex edge = { 1, 2, 0, 0 };
  uv::EvaluateSimplexBasis(uv::SimplexBasisKind::Bernstein, order, nodes, NodePosition(order, edge), w.data(), nullptr);
  EXPECT_LT(*std::max_element(w.begin(), w.end()), 0.5);
  const uv::SimplexIndex corner = { 0, 0, 3, 0 };
  uv::EvaluateSimplexBasis(uv::SimplexBasisKind::Bernstein, order, nodes, NodePosition(order, corner), w.data(), nullptr);
  EXPECT_NEAR(*std::max_element(w.begin(), w.end()), 1.0, 1e-12);
}

TEST(LatticeBasis, DerivativesMatchCentralDifferences)
{
  const double h = 1e-6;
  for (const uv::SimplexBasisKind kind : Kinds)
    for (int order = 1; order <= 4; ++order)
    {
      const std::vector<uv::SimplexIndex> nodes = Lattice(order);
      const std::size_t n = nodes.size();
      std::vector<double> w(n), d(3 * n), plus(n), minus(n);
      for (const glm::dvec3& xi : InsidePoints(10))
      {
        uv::EvaluateSimplexBasis(kind, order, nodes, xi, w.data(), d.data());
        for (int axis = 0; axis < 3; ++axis)
        {
          glm::dvec3 step(0.0);
          step[axis] = h;
          uv::EvaluateSimplexBasis(kind, order, nodes, xi + step, plus.data(), nullptr);
          uv::EvaluateSimplexBasis(kind, order, nodes, xi - step, minus.data(), nullptr);
          for (std::size_t k = 0; k < n; ++k)
            EXPECT_NEAR(d[axis * n + k], (plus[k] - minus[k]) / (2 * h), 1e-6);
        }
      }
    }
}

/// A wedge's or hexahedron's basis: sums to one, reproduces the parametric position from nodes at
/// their lattice positions, is a delta at the nodes when Lagrange, and its derivatives match central
/// differences.
template <typename Evaluate, typename Position>
void CheckPrismBasis(uv::SimplexBasisKind kind, int order, const std::vector<uv::SimplexIndex>& nodes,
  const Evaluate& evaluate, const Position& position)
{
  const std::size_t n = nodes.size();
  std::vector<double> w(n), d(3 * n), plus(n), minus(n);
  for (const glm::dvec3& sample : InsidePoints(20))
  {
    const glm::dvec3 xi(sample.x, sample.y, 2.0 * sample.z); // any height in [0, 1]
    evaluate(kind, order, nodes, xi, w.data(), d.data());
    double sum = 0.0;
    glm::dvec3 mapped(0.0);
    for (std::size_t k = 0; k < n; ++k)
    {
      sum += w[k];
      mapped += w[k] * position(nodes[k]) / double(order);
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
    EXPECT_NEAR(glm::length(mapped - xi), 0.0, 1e-12);
    for (int axis = 0; axis < 3; ++axis)
    {
      glm::dvec3 step(0.0);
      step[axis] = 1e-6;
      evaluate(kind, order, nodes, xi + step, plus.data(), nullptr);
      evaluate(kind, order, nodes, xi - step, minus.data(), nullptr);
      for (std::size_t k = 0; k < n; ++k)
        EXPECT_NEAR(d[axis * n + k], (plus[k] - minus[k]) / 2e-6, 1e-6);
    }
  }
  for (std::size_t node = 0; kind == uv::SimplexBasisKind::Lagrange && node < n; ++node)
  {
    evaluate(kind, order, nodes, position(nodes[node]) / double(order), w.data(), nullptr);
    for (std::size_t k = 0; k < n; ++k)
      EXPECT_NEAR(w[k], k == node ? 1.0 : 0.0, 1e-12);
  }
}

TEST(LatticeBasis, WedgesSumToOneReproducePositionsInterpolateAndDifferentiate)
{
  for (uv::SimplexBasisKind kind : Kinds)
    for (int order = 1; order <= 3; ++order)
    {
      std::vector<uv::SimplexIndex> nodes; // (triangle index, layer)
      for (int a = 0; a <= order; ++a)
        for (int b = 0; a + b <= order; ++b)
          for (int k = 0; k <= order; ++k)
            nodes.push_back({ a, b, order - a - b, k });
      EXPECT_EQ(static_cast<int>(nodes.size()), (order + 1) * (order + 2) / 2 * (order + 1));
      CheckPrismBasis(kind, order, nodes, uv::EvaluateWedgeBasis,
        [](const uv::SimplexIndex& i) { return glm::dvec3(i[0], i[1], i[3]); });
    }
}

TEST(LatticeBasis, HexahedraSumToOneReproducePositionsInterpolateAndDifferentiate)
{
  for (uv::SimplexBasisKind kind : Kinds)
    for (int order = 1; order <= 3; ++order)
    {
      std::vector<uv::SimplexIndex> nodes;
      for (int k = order; k >= 0; --k) // any node order
        for (int j = 0; j <= order; ++j)
          for (int i = 0; i <= order; ++i)
            nodes.push_back({ i, j, k, 0 });
      CheckPrismBasis(kind, order, nodes, uv::EvaluateHexahedronBasis,
        [](const uv::SimplexIndex& i) { return glm::dvec3(i[0], i[1], i[2]); });
      EXPECT_EQ(uv::HexahedronIndexAt(order, glm::dvec3(order, 0.0, 1.0) / double(order)),
        (uv::SimplexIndex{ order, 0, 1, 0 }));
    }
}
