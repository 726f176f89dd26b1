// The hexahedral mesh's connectivity (uvHexahedralMesh.h) and the scalar normalisation every mapper
// uploads with (uvScalarNormalisation.h), on a small block of cells.
#include "uvHexahedralMesh.h"
#include "uvScalarNormalisation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace
{
void Serial(std::size_t count, const std::function<void(std::size_t, std::size_t)>& function)
{
  function(0, count);
}

/// nx x 1 x 1 unit cubes along x: points (i, j, k) numbered i + (nx + 1) (j + 2 k).
struct Block
{
  std::vector<std::uint32_t> CellPoints;
  std::vector<float> PointData;

  explicit Block(int nx)
  {
    auto id = [nx](int i, int j, int k) { return static_cast<std::uint32_t>(i + (nx + 1) * (j + 2 * k)); };
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i <= nx; ++i)
          this->PointData.insert(this->PointData.end(), { float(i), float(j), float(k), float(i) });
    for (int i = 0; i < nx; ++i)
      this->CellPoints.insert(this->CellPoints.end(), { id(i, 0, 0), id(i + 1, 0, 0), id(i + 1, 1, 0),
        id(i, 1, 0), id(i, 0, 1), id(i + 1, 0, 1), id(i + 1, 1, 1), id(i, 1, 1) });
  }
};
} // namespace

TEST(HexahedronMesh, NeighboursAreMutualAndTheRestIsBoundary)
{
  const Block block(3);
  std::vector<double> progress;
  const uv::HexahedralFaces faces = uv::MakeHexahedralFaces(block.CellPoints, Serial,
    [](auto begin, auto end) { std::sort(begin, end); }, [&](double f) { progress.push_back(f); });
  EXPECT_EQ(progress, (std::vector<double>{ 0.5, 1.0 }));
  ASSERT_EQ(faces.Neighbours.size(), 8u * 3u);
  // Face 3 (r = 1) of cell c meets face 5 (r = 0) of cell c + 1, both ways.
  for (int c = 0; c < 2; ++c)
  {
    EXPECT_EQ(faces.Neighbours[8 * c + 3], 8 * (c + 1) + 5);
    EXPECT_EQ(faces.Neighbours[8 * (c + 1) + 5], 8 * c + 3);
  }
  EXPECT_EQ(faces.Neighbours[8 * 0 + 5], -1);
  EXPECT_EQ(faces.Neighbours[8 * 2 + 3], -1);
  ASSERT_EQ(faces.Boundary.size(), 4u * (6 * 3 - 2 * 2));
  for (std::size_t b = 0; b < faces.Boundary.size(); b += 4)
    EXPECT_EQ(faces.Neighbours[8 * faces.Boundary[b] + faces.Boundary[b + 1]], -1);
}

TEST(HexahedronMesh, CellHoldingAPointAndTangledCells)
{
  Block block(3);
  EXPECT_EQ(uv::HexahedronHolding(block.CellPoints, block.PointData, glm::dvec3(1.5, 0.5, 0.5)), 1);
  EXPECT_EQ(uv::HexahedronHolding(block.CellPoints, block.PointData, glm::dvec3(3.5, 0.5, 0.5)), -1);
  EXPECT_EQ(uv::CountTangledHexahedra(block.CellPoints, block.PointData, Serial), 0u);
  // Corner 6 of the last cell pushed through its opposite face folds it.
  const std::uint32_t corner = block.CellPoints[8 * 2 + 6];
  block.PointData[4 * corner + 0] = 2.2f;
  block.PointData[4 * corner + 1] = 0.2f;
  block.PointData[4 * corner + 2] = -1.0f;
  EXPECT_EQ(uv::CountTangledHexahedra(block.CellPoints, block.PointData, Serial), 1u);
}

TEST(HexahedronMesh, ScalarNormalisationIgnoresNaN)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> values = { 4.0, nan, -2.0, 1.0 };
  const auto n = uv::ScalarNormalisation::OfFiniteValues(values.size(), [&](std::size_t p) { return values[p]; });
  EXPECT_EQ(n.Offset, -2.0);
  EXPECT_DOUBLE_EQ(n.Scale, 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(n(4.0), 1.0);
  EXPECT_TRUE(std::isnan(n(nan)));
  const auto constant = uv::ScalarNormalisation::OfFiniteValues(2, [](std::size_t) { return 3.0; });
  EXPECT_EQ(constant.Scale, 1.0);
  const auto none = uv::ScalarNormalisation::OfFiniteValues(1, [nan](std::size_t) { return nan; });
  EXPECT_EQ(none.Offset, 0.0);
  const std::vector<float> points = { 0, 0, 0, 0.5f, 0, 0, 0, float(nan) };
  const int first[1] = { 0 }, both[2] = { 0, 1 };
  EXPECT_TRUE(uv::ScalarsFinite(points, first, 1));
  EXPECT_FALSE(uv::ScalarsFinite(points, both, 2));
}
