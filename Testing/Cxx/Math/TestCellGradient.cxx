// The VTK-free cell gradients, vertex-cell links and analytic fields.
#include "uvAnalyticMesh.h"
#include "uvCellGradient.h"
#include "uvVertexCellLinks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{
const glm::dvec3 Slope(0.7, -1.3, 2.1);
double LinearField(const glm::dvec3& p)
{
  return 4.0 + glm::dot(Slope, p);
}

/// Random-looking but deterministic perturbation, small enough to keep cells valid.
glm::dvec3 Perturb(const glm::dvec3& p, int index, double amount)
{
  return p +
    amount *
    glm::dvec3(uv::HashToSymmetricUnit(3 * index, 7), uv::HashToSymmetricUnit(3 * index + 1, 7),
      uv::HashToSymmetricUnit(3 * index + 2, 7));
}

template <int N, typename Gradient>
void ExpectExactOnLinear(const glm::dvec3 (&reference)[N], Gradient gradient, double referenceWeight)
{
  for (int trial = 0; trial < 50; ++trial)
  {
    glm::dvec3 p[N];
    double f[N];
    for (int k = 0; k < N; ++k)
    {
      p[k] = Perturb(reference[k] * (1.0 + 0.1 * trial), trial * N + k, trial == 0 ? 0.0 : 0.12);
      f[k] = LinearField(p[k]);
    }
    const uv::CellGradient result = gradient(p, f);
    ASSERT_GT(result.Weight, 0.0);
    EXPECT_NEAR(result.Gradient.x, Slope.x, 1e-12);
    EXPECT_NEAR(result.Gradient.y, Slope.y, 1e-12);
    EXPECT_NEAR(result.Gradient.z, Slope.z, 1e-12);
    if (trial == 0)
    {
      EXPECT_NEAR(result.Weight, referenceWeight, 1e-14);
    }
  }
}

const glm::dvec3 Tet[4] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
const glm::dvec3 Hex[8] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
  { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
const glm::dvec3 Wedge[6] = { { 0, 0, 0 }, { 0, 1, 0 }, { 1, 0, 0 }, { 0, 0, 1 }, { 0, 1, 1 },
  { 1, 0, 1 } };
const glm::dvec3 Pyramid[5] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0.5, 0.5, 1 } };
} // namespace

TEST(CellGradient, ExactForLinearFieldsOnDistortedCells)
{
  ExpectExactOnLinear(Tet, uv::TetrahedronGradient, 1.0 / 6.0);
  ExpectExactOnLinear(Hex, uv::HexahedronGradient, 1.0);
  ExpectExactOnLinear(Wedge, uv::WedgeGradient, 0.5);
  ExpectExactOnLinear(Pyramid, uv::PyramidGradient, 1.0 / 3.0);
}

TEST(CellGradient, DegenerateCellsHaveNoWeightMirroredOnesCount)
{
  glm::dvec3 flat[4] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 1e-15 } };
  const double f[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  EXPECT_EQ(uv::TetrahedronGradient(flat, f).Weight, 0.0);
  // A mirrored cell (points listed left-handed) has the same gradient and volume.
  glm::dvec3 mirrored[4] = { Tet[0], Tet[2], Tet[1], Tet[3] };
  const double mirroredValues[4] = { f[0], f[2], f[1], f[3] };
  const uv::CellGradient mirroredResult = uv::TetrahedronGradient(mirrored, mirroredValues);
  const uv::CellGradient result = uv::TetrahedronGradient(Tet, f);
  EXPECT_NEAR(mirroredResult.Weight, 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(glm::length(mirroredResult.Gradient - result.Gradient), 0.0, 1e-14);
  glm::dvec3 collapsed[8];
  for (int k = 0; k < 8; ++k)
  {
    collapsed[k] = glm::dvec3(Hex[k].x, Hex[k].y, 0.0);
  }
  EXPECT_EQ(uv::HexahedronGradient(collapsed, f).Weight, 0.0);
}

TEST(CellGradient, HexahedronCentreGradientOfTrilinearTerm)
{
  // f = xyz on the unit cube: the gradient at the centre is (1/4, 1/4, 1/4).
  double f[8];
  for (int k = 0; k < 8; ++k)
  {
    f[k] = Hex[k].x * Hex[k].y * Hex[k].z;
  }
  const uv::CellGradient result = uv::HexahedronGradient(Hex, f);
  EXPECT_NEAR(result.Gradient.x, 0.25, 1e-15);
  EXPECT_NEAR(result.Gradient.y, 0.25, 1e-15);
  EXPECT_NEAR(result.Gradient.z, 0.25, 1e-15);
}

TEST(VertexCellLinks, RowsListCellsInOrder)
{
  // Two tets sharing the face (1,2,3), and a vertex (5) that no cell uses.
  const std::vector<long long> offsets = { 0, 4, 8 };
  const std::vector<long long> connectivity = { 0, 1, 2, 3, 1, 2, 3, 4 };
  const uv::VertexCellLinks links = uv::BuildVertexCellLinks(6, offsets, connectivity);
  ASSERT_EQ(links.Offsets.size(), 7u);
  EXPECT_EQ(links.Degree(0), 1);
  EXPECT_EQ(links.Degree(1), 2);
  EXPECT_EQ(links.Degree(4), 1);
  EXPECT_EQ(links.Degree(5), 0);
  EXPECT_EQ(links.Cells[links.Offsets[2]], 0);
  EXPECT_EQ(links.Cells[links.Offsets[2] + 1], 1);
  EXPECT_EQ(links.Cells[links.Offsets[4]], 1);
}

TEST(AnalyticMesh, FieldsMatchTheirDefinitions)
{
  EXPECT_DOUBLE_EQ(uv::EvaluateSteiner({ 1, 1, 1 }), 4.0);
  EXPECT_DOUBLE_EQ(uv::EvaluateSteiner({ 0.5, -1, 2 }), 0.25 + 4.0 + 1.0 - 1.0);
  EXPECT_DOUBLE_EQ(uv::EvaluateLinear({ 0, 0, 0 }), 0.5);
  // Marschner-Lobb: at the origin rho_r(0) = cos(2 pi 6) = 1, so f = (1 + 0.25 * 2) / 2.5 = 0.6.
  EXPECT_NEAR(uv::EvaluateMarschnerLobb({ 0, 0, 0 }), 0.6, 1e-15);
  double lowest = 1.0, highest = 0.0;
  for (int i = 0; i < 2000; ++i)
  {
    const glm::dvec3 p(uv::HashToSymmetricUnit(3 * i, 1), uv::HashToSymmetricUnit(3 * i + 1, 1),
      uv::HashToSymmetricUnit(3 * i + 2, 1));
    const double f = uv::EvaluateMarschnerLobb(p);
    lowest = std::min(lowest, f);
    highest = std::max(highest, f);
  }
  EXPECT_GE(lowest, 0.0);
  EXPECT_LE(highest, 1.0);
  EXPECT_LT(lowest, 0.1);
  EXPECT_GT(highest, 0.9);
}

TEST(AnalyticMesh, DistortionsAndHash)
{
  const glm::dvec3 r = uv::Rotate45({ 1, 0, 0.5 });
  EXPECT_NEAR(r.x, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(r.y, std::sqrt(0.5), 1e-15);
  EXPECT_EQ(r.z, 0.5);
  const glm::dvec3 bottom = uv::Twist({ 1, 0, -1 }, 1.0);
  EXPECT_EQ(bottom, glm::dvec3(1, 0, -1));
  const glm::dvec3 top = uv::Twist({ 1, 0, 1 }, 1.0);
  EXPECT_NEAR(top.x, std::cos(1.0), 1e-15);
  EXPECT_NEAR(top.y, std::sin(1.0), 1e-15);
  // The hash is a fixed function: same input, same output; outputs spread over [-1, 1].
  EXPECT_EQ(uv::HashToSymmetricUnit(12345, 3), uv::HashToSymmetricUnit(12345, 3));
  EXPECT_NE(uv::HashToSymmetricUnit(12345, 3), uv::HashToSymmetricUnit(12345, 4));
  double sum = 0.0;
  for (int i = 0; i < 10000; ++i)
  {
    const double h = uv::HashToSymmetricUnit(i, 9);
    ASSERT_GE(h, -1.0);
    ASSERT_LT(h, 1.0);
    sum += h;
  }
  EXPECT_LT(std::abs(sum / 10000), 0.03);
  const bool interior[3] = { false, false, false };
  const bool boundary[3] = { true, true, true };
  EXPECT_EQ(uv::Jitter({ 1, 1, 1 }, { 0.1, 0.1, 0.1 }, 5, 1, 0.15, boundary), glm::dvec3(1, 1, 1));
  const glm::dvec3 moved = uv::Jitter({ 0, 0, 0 }, { 0.1, 0.1, 0.1 }, 5, 1, 0.15, interior);
  EXPECT_LE(glm::length(moved), 0.015 * std::sqrt(3.0) + 1e-15);
  EXPECT_GT(glm::length(moved), 0.0);
}
