// The visible region the hexahedral ray caster walks when skipping (uvVisibleRegion.h): cell ranges,
// visibility and the region's neighbours and entry faces, on a row of unit cubes.
#include "uvTestHexahedralRow.h"
#include "uvVisibleRegion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <limits>
#include <set>
#include <vector>

namespace
{
using uvtest::Serial;

/// The test row with its faces.
struct Row : uvtest::HexahedralRow
{
  uv::HexahedralFaces Faces;

  explicit Row(int nx)
    : uvtest::HexahedralRow(nx)
  {
    this->Faces = uv::MakeHexahedralFaces(
      this->CellPoints, {}, Serial, [](auto begin, auto end) { std::sort(begin, end); }, [](double) {});
  }
};

std::set<std::pair<int, int>> FaceSet(const std::vector<std::int32_t>& boundary)
{
  std::set<std::pair<int, int>> faces;
  for (std::size_t b = 0; b < boundary.size(); b += 4)
    faces.insert({ boundary[b], boundary[b + 1] });
  return faces;
}

const double Infinity = std::numeric_limits<double>::infinity();
} // namespace

TEST(VisibleRegion, PointScalarRangesAreTheCorners)
{
  const Row row(4);
  std::vector<float> low, high;
  uv::HexahedralCellRanges(row.CellPoints, row.PointData, {}, row.Faces.Neighbours, true, low, high, Serial);
  for (int c = 0; c < 4; ++c)
  {
    EXPECT_EQ(low[c], float(c));
    EXPECT_EQ(high[c], float(c + 1));
  }
}

TEST(VisibleRegion, CellScalarRangesWidenToNeighboursForFaceIsosurfaces)
{
  const Row row(5);
  const std::vector<float> cells = { 0, 10, 0, 0, 0 };
  std::vector<float> low, high;
  uv::HexahedralCellRanges(row.CellPoints, row.PointData, cells, row.Faces.Neighbours, false, low, high, Serial);
  EXPECT_EQ(high, cells);
  EXPECT_EQ(low, cells);
  uv::HexahedralCellRanges(row.CellPoints, row.PointData, cells, row.Faces.Neighbours, true, low, high, Serial);
  EXPECT_EQ(high, (std::vector<float>{ 10, 10, 10, 0, 0 }));
  EXPECT_EQ(low, (std::vector<float>{ 0, 0, 0, 0, 0 }));
}

TEST(VisibleRegion, VisibleWhereTheRangeMeetsExtinctionOrHoldsAnIsovalue)
{
  const std::vector<float> low = { 0, 1, 2, 3, 4 }, high = { 1, 2, 3, 4, 5 };
  const std::vector<std::pair<double, double>> zero = { { -Infinity, 2.5 }, { 4.5, Infinity } };
  EXPECT_EQ(uv::VisibleCells(low, high, zero, {}, Serial), (std::vector<unsigned char>{ 0, 0, 1, 1, 1 }));
  EXPECT_EQ(uv::VisibleCells(low, high, zero, { 0.5 }, Serial), (std::vector<unsigned char>{ 1, 0, 1, 1, 1 }));
  const std::vector<std::pair<double, double>> nothing = { { -Infinity, Infinity } };
  EXPECT_EQ(uv::VisibleCells(low, high, nothing, {}, Serial), (std::vector<unsigned char>(5, 0)));
}

TEST(VisibleRegion, FacesTowardsInvisibleCellsBecomeEntryFaces)
{
  const Row row(5);
  const uv::VisibleRegion region = uv::MakeVisibleRegion(row.Faces, { 0, 0, 1, 1, 0 });
  EXPECT_EQ(region.VisibleCells, 2u);
  // The mesh's own boundary faces of cells 2 and 3 (four sides each) and the two faces towards
  // cells 1 and 4; not the face between cells 2 and 3.
  const std::set<std::pair<int, int>> entries = FaceSet(region.Boundary);
  EXPECT_EQ(region.BoundaryCount(), 10u);
  EXPECT_EQ(entries.size(), 10u);
  EXPECT_TRUE(entries.count({ 2, 5 }));
  EXPECT_TRUE(entries.count({ 3, 3 }));
  EXPECT_FALSE(entries.count({ 2, 3 }));
  EXPECT_FALSE(entries.count({ 3, 5 }));
  for (const auto& face : entries)
    EXPECT_TRUE(face.first == 2 || face.first == 3);
}

TEST(VisibleRegion, EverythingVisibleIsTheMeshAndNothingVisibleIsEmpty)
{
  const Row row(4);
  const uv::VisibleRegion all = uv::MakeVisibleRegion(row.Faces, std::vector<unsigned char>(4, 1));
  EXPECT_EQ(FaceSet(all.Boundary), FaceSet(row.Faces.Boundary));
  const uv::VisibleRegion none = uv::MakeVisibleRegion(row.Faces, std::vector<unsigned char>(4, 0));
  EXPECT_EQ(none.BoundaryCount(), 0u);
  EXPECT_EQ(none.VisibleCells, 0u);
}

TEST(VisibleRegion, TheBoxHoldsTheVisibleCellsAndLittleMore)
{
  const Row row(5); // unit cubes along x from 0 to 5
  const std::array<float, 6> box = uv::BoxOfCells(row.CellPoints, row.PointData, { 0, 1, 1, 0, 0 });
  const std::array<float, 6> cells = { 1, 0, 0, 3, 1, 1 };
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_LT(box[i], cells[i]);
    EXPECT_GT(box[3 + i], cells[3 + i]);
    EXPECT_NEAR(box[i], cells[i], 1e-4);
    EXPECT_NEAR(box[3 + i], cells[3 + i], 1e-4);
  }
  // Nothing visible: a point, which any ray passes at once.
  EXPECT_EQ(uv::BoxOfCells(row.CellPoints, row.PointData, std::vector<unsigned char>(5, 0)),
    (std::array<float, 6>{}));
}
