// The mesh checks (uvMeshIntegrity.h): each fault is found in the cell that has it, the first broken
// cell and the count do not depend on how the cells are split among threads, and a sound mesh passes.
#include "uvMeshIntegrity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace
{
constexpr int Tetra = 10, Hexahedron = 12, Polygon = 7;

void Serial(std::size_t count, const std::function<void(std::size_t, std::size_t)>& function)
{
  function(0, count);
}

// One cell at a time, last first, as a thread pool might finish them.
void Reversed(std::size_t count, const std::function<void(std::size_t, std::size_t)>& function)
{
  for (std::size_t c = count; c-- > 0;)
    function(c, c + 1);
}

struct Cells
{
  std::vector<std::int64_t> Offsets{ 0 }, Ids;
  std::vector<int> Types;
  void Add(int type, std::vector<std::int64_t> ids)
  {
    this->Ids.insert(this->Ids.end(), ids.begin(), ids.end());
    this->Offsets.push_back(static_cast<std::int64_t>(this->Ids.size()));
    this->Types.push_back(type);
  }
  template <typename ParallelFor>
  uv::BrokenCells Check(std::int64_t points, ParallelFor parallelFor) const
  {
    uv::PointCountsByType expected{};
    expected[Tetra] = 4;
    expected[Hexahedron] = 8;
    return uv::FindBrokenCells(
      static_cast<std::int64_t>(this->Types.size()), points, static_cast<std::int64_t>(this->Ids.size()),
      [this](std::int64_t c) { return this->Offsets[c]; }, [this](std::int64_t k) { return this->Ids[k]; },
      [this](std::int64_t c) { return this->Types[c]; }, expected, parallelFor);
  }
};

Cells SoundMesh()
{
  Cells cells;
  cells.Add(Hexahedron, { 0, 1, 2, 3, 4, 5, 6, 7 });
  cells.Add(Tetra, { 4, 5, 6, 8 });
  cells.Add(Polygon, { 0, 1, 2, 3, 8 }); // any count for a polygon
  return cells;
}
} // namespace

TEST(MeshIntegrity, SoundMeshPasses)
{
  const uv::BrokenCells found = SoundMesh().Check(9, Serial);
  EXPECT_FALSE(found);
  EXPECT_EQ(found.Count, 0);
}

TEST(MeshIntegrity, IdsOutOfRangeAreFoundOnBothSides)
{
  Cells cells = SoundMesh();
  cells.Add(Tetra, { 0, 1, 2, 9 }); // one past the last point
  cells.Add(Tetra, { 0, -1, 2, 3 });
  const uv::BrokenCells found = cells.Check(9, Serial);
  EXPECT_EQ(found.Count, 2);
  EXPECT_EQ(found.FirstCell, 3);
  EXPECT_EQ(found.FirstFault, uv::BrokenCells::Fault::IdOutOfRange);
  EXPECT_EQ(found.FirstBadId, 9);
}

TEST(MeshIntegrity, WrongPointCountOfAFixedSizeType)
{
  Cells cells = SoundMesh();
  cells.Add(Hexahedron, { 0, 1, 2, 3 }); // a hexahedron of four ids: its readers would run on
  const uv::BrokenCells found = cells.Check(9, Serial);
  EXPECT_EQ(found.Count, 1);
  EXPECT_EQ(found.FirstCell, 3);
  EXPECT_EQ(found.FirstFault, uv::BrokenCells::Fault::PointCount);
  EXPECT_EQ(found.FirstIdCount, 4);
  EXPECT_EQ(found.FirstExpected, 8);
}

TEST(MeshIntegrity, OffsetsThatFallOrRunPastTheIdsAreFound)
{
  Cells cells = SoundMesh();
  cells.Offsets[2] = 20; // past the end of the ids
  uv::BrokenCells found = cells.Check(9, Serial);
  EXPECT_EQ(found.FirstCell, 1);
  EXPECT_EQ(found.FirstFault, uv::BrokenCells::Fault::Offsets);
  cells = SoundMesh();
  cells.Offsets[1] = 13; // the first cell ends after the second
  found = cells.Check(9, Serial);
  EXPECT_EQ(found.FirstCell, 0);
  EXPECT_EQ(found.Count, 2);
}

TEST(MeshIntegrity, FirstBrokenCellDoesNotDependOnTheSplit)
{
  Cells cells;
  for (int c = 0; c < 100; ++c)
    cells.Add(Tetra, { 0, 1, 2, (c % 7 == 3) ? 50 + c : 3 });
  const uv::BrokenCells serial = cells.Check(4, Serial), reversed = cells.Check(4, Reversed);
  EXPECT_EQ(serial.Count, 14);
  EXPECT_EQ(serial.FirstCell, 3);
  EXPECT_EQ(serial.FirstBadId, 53);
  EXPECT_EQ(reversed.Count, serial.Count);
  EXPECT_EQ(reversed.FirstCell, serial.FirstCell);
  EXPECT_EQ(reversed.FirstBadId, serial.FirstBadId);
}

TEST(MeshIntegrity, NonFinitePoints)
{
  std::vector<double> xyz(3 * 10, 1.0);
  EXPECT_FALSE(uv::FindNonFinitePoints(xyz.data(), 10, Reversed));
  xyz[3 * 7 + 2] = std::numeric_limits<double>::infinity();
  xyz[3 * 4 + 0] = std::nan("");
  for (auto parallelFor : { Serial, Reversed })
  {
    const uv::NonFinitePoints found = uv::FindNonFinitePoints(xyz.data(), 10, parallelFor);
    EXPECT_EQ(found.Count, 2);
    EXPECT_EQ(found.First, 4);
  }
  std::vector<float> large(3 * 2, std::numeric_limits<float>::max()); // large is finite
  EXPECT_FALSE(uv::FindNonFinitePoints(large.data(), 2, Serial));
}

TEST(MeshIntegrity, PolyhedronFaceStreams)
{
  const auto sound = [](std::vector<std::int64_t> stream, std::int64_t points) {
    return uv::FaceStreamSound([&stream](std::int64_t k) { return stream[k]; },
      static_cast<std::int64_t>(stream.size()), points);
  };
  const std::vector<std::int64_t> tetrahedron{ 4, 3, 0, 1, 2, 3, 0, 1, 3, 3, 1, 2, 3, 3, 0, 2, 3 };
  EXPECT_TRUE(sound(tetrahedron, 4));
  EXPECT_FALSE(sound(tetrahedron, 3)); // names point 3 of three
  EXPECT_FALSE(sound({ 5, 4, 0, 1, 2, 3, 4, 4, 5, 6, 7 }, 8)); // promises five faces, holds two
  EXPECT_FALSE(sound({ 1, 4, 0, 1, 2 }, 8));                    // a face cut short
  EXPECT_FALSE(sound({ 1, -1 }, 8));                            // a negative count
  EXPECT_FALSE(sound({}, 8));
  // Readable, though no solid: the split skips such polyhedra itself, with its own error.
  EXPECT_TRUE(sound({ 1, 2, 0, 1 }, 8)); // a face of two points
  EXPECT_TRUE(sound({ 0 }, 8));          // no face
}

TEST(MeshIntegrity, GPUIndicesStopAtTwoToThe31)
{
  constexpr std::int64_t limit = std::int64_t(1) << 31;
  EXPECT_TRUE(uv::IndicesFitGPU(limit, 1));
  EXPECT_FALSE(uv::IndicesFitGPU(limit + 1, 1));
  EXPECT_TRUE(uv::IndicesFitGPU(limit / 4, 4));       // the last tetrahedron's last corner is 2^31 - 1
  EXPECT_FALSE(uv::IndicesFitGPU(limit / 4 + 1, 4));
  EXPECT_TRUE(uv::IndicesFitGPU(limit / 8, 8));
  EXPECT_FALSE(uv::IndicesFitGPU(limit / 8 + 1, 8));
  EXPECT_TRUE(uv::IndicesFitGPU(0, 8));
  EXPECT_FALSE(uv::IndicesFitGPU(-1, 8));
  EXPECT_FALSE(uv::IndicesFitGPU(std::numeric_limits<std::int64_t>::max(), 4));
}
