// Which cells overlap where a mesh folds (uvOverlappingCells.h), on a row of unit cubes.
#include "uvOverlappingCells.h"
#include "uvTestHexahedralRow.h"

#include <gtest/gtest.h>

#include <vector>

namespace
{
std::vector<std::uint32_t> PartnersOf(const uv::OverlapPartners& partners, std::size_t cell)
{
  return std::vector<std::uint32_t>(
    partners.Cells.begin() + partners.Offsets[cell], partners.Cells.begin() + partners.Offsets[cell + 1]);
}

void Cube(const glm::dvec3& low, double size, glm::dvec3 p[8])
{
  for (int k = 0; k < 8; ++k)
    p[k] = low + size * glm::dvec3((k == 1 || k == 2 || k == 5 || k == 6) ? 1 : 0, (k & 2) ? 1 : 0, k >= 4 ? 1 : 0);
}
} // namespace

TEST(OverlappingCells, SharedFacesDoNotOverlapShiftedCubesDo)
{
  glm::dvec3 a[8], b[8], c[8];
  Cube(glm::dvec3(0.0), 1.0, a);
  Cube(glm::dvec3(1.0, 0.0, 0.0), 1.0, b);  // shares a's face x = 1
  Cube(glm::dvec3(0.8, 0.3, 0.1), 1.0, c);  // overlaps a by a fifth along x
  EXPECT_FALSE(uv::CellsOverlap(a, b, 6));
  EXPECT_TRUE(uv::CellsOverlap(a, c, 6));
  EXPECT_TRUE(uv::CellsOverlap(c, a, 6));
  // A sliver thinner than the lattice's spacing is missed (the documented limit).
  Cube(glm::dvec3(0.99, 0.0, 0.0), 1.0, c);
  EXPECT_FALSE(uv::CellsOverlap(a, c, 6));
}

TEST(OverlappingCells, AFoldedCellAndTheNeighbourItReachesArePartners)
{
  uvtest::HexahedralRow row(3);
  EXPECT_EQ(uv::FindOverlapPartners(row.CellPoints, row.PointData, uvtest::Serial).PairCount(), 0u);
  // The last cell's corner 6 (3, 1, 1) pushed into the middle cell folds the last cell over it.
  const std::uint32_t corner = row.CellPoints[8 * 2 + 6];
  row.PointData[4 * corner + 0] = 1.5f;
  row.PointData[4 * corner + 1] = 0.5f;
  row.PointData[4 * corner + 2] = 0.5f;
  ASSERT_EQ(uv::CountTangledHexahedra(row.CellPoints, row.PointData, uvtest::Serial), 1u);
  const uv::OverlapPartners partners = uv::FindOverlapPartners(row.CellPoints, row.PointData, uvtest::Serial);
  ASSERT_EQ(partners.Offsets.size(), 4u);
  EXPECT_EQ(partners.PairCount(), 1u);
  EXPECT_TRUE(PartnersOf(partners, 0).empty());
  EXPECT_EQ(PartnersOf(partners, 1), std::vector<std::uint32_t>{ 2 });
  EXPECT_EQ(PartnersOf(partners, 2), std::vector<std::uint32_t>{ 1 });
  // The GPU layout: offsets shifted past themselves, then the partners.
  EXPECT_EQ(partners.Packed(), (std::vector<std::int32_t>{ 4, 4, 5, 6, 2, 1 }));
}
