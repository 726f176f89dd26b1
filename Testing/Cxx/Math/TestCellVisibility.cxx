// Which cells a transfer function makes invisible (uvCellVisibility.h): roles against a brute-force
// check of the definition, and lists rebuilt exactly when their inputs change; which faces between
// cells hold the isosurfaces of a cell scalar (uvIsosurfaceList.h).
#include "uvCellVisibility.h"
#include "uvIsosurfaceList.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

namespace
{
void Serial(std::size_t count, const std::function<void(std::size_t, std::size_t)>& function)
{
  function(0, count);
}

// The definition, by sampling: some scalar of [low, high] has extinction > 0 (linear between nodes,
// constant beyond the ends).
bool HasExtinction(double low, double high, const std::vector<uv::TransferFunction::Node>& nodes)
{
  auto tau = [&](double s) {
    if (s <= nodes.front().Scalar)
      return nodes.front().Extinction;
    if (s >= nodes.back().Scalar)
      return nodes.back().Extinction;
    std::size_t i = 1;
    while (nodes[i].Scalar < s)
      ++i;
    const double f = (s - nodes[i - 1].Scalar) / (nodes[i].Scalar - nodes[i - 1].Scalar);
    return (1 - f) * nodes[i - 1].Extinction + f * nodes[i].Extinction;
  };
  for (int k = 0; k <= 400; ++k)
    if (tau(low + (high - low) * k / 400.0) > 0.0)
      return true;
  for (const auto& node : nodes) // nodes strictly inside the range the samples may step over
    if (node.Scalar > low && node.Scalar < high && node.Extinction > 0.0)
      return true;
  return false;
}
}

TEST(CellVisibility, RolesMatchTheDefinition)
{
  const std::vector<uv::TransferFunction::Node> nodes = { { 0.0, glm::dvec3(1), 0.0 }, { 0.2, glm::dvec3(1), 0.0 },
    { 0.3, glm::dvec3(1), 2.0 }, { 0.5, glm::dvec3(1), 0.0 }, { 0.7, glm::dvec3(1), 0.0 },
    { 0.8, glm::dvec3(1), 1.0 } };
  const auto zeroSet = uv::ZeroExtinctionIntervals(nodes);
  const std::vector<double> isovalues = { 0.1, 0.6 };
  std::mt19937 random(7);
  std::uniform_real_distribution<double> scalar(-0.2, 1.2);
  for (int trial = 0; trial < 2000; ++trial)
  {
    double low = scalar(random), high = scalar(random);
    if (low > high)
      std::swap(low, high);
    if (trial % 5 == 0)
      high = low; // constant cells
    const unsigned char role = uv::RoleOf(low, high, zeroSet, isovalues);
    const bool holdsIsovalue = (low <= 0.1 && 0.1 <= high) || (low <= 0.6 && 0.6 <= high);
    EXPECT_EQ((role & uv::VolumeRole) != 0, HasExtinction(low, high, nodes)) << low << " " << high;
    EXPECT_EQ((role & uv::IsosurfaceRole) != 0, holdsIsovalue) << low << " " << high;
  }
}

TEST(CellVisibility, ListsRebuildOnlyWhenTheirInputsChange)
{
  const std::vector<float> low = { 0.0f, 0.4f, 0.6f }, high = { 0.1f, 0.5f, 0.9f };
  std::vector<std::pair<double, double>> zeroSet = { { -1e300, 0.45 } };
  uv::CellLists lists;
  EXPECT_TRUE(lists.Update(1, low, high, zeroSet, {}, Serial));
  EXPECT_EQ(lists.Volume(), (std::vector<std::uint32_t>{ 1, 2 }));
  EXPECT_TRUE(lists.Isosurface.empty());
  EXPECT_FALSE(lists.Update(1, low, high, zeroSet, {}, Serial));
  EXPECT_TRUE(lists.Update(1, low, high, zeroSet, { 0.05 }, Serial)); // an isovalue in cell 0
  EXPECT_EQ(lists.Isosurface, (std::vector<std::uint32_t>{ 0 }));
  EXPECT_EQ(lists.Drawn, (std::vector<std::uint32_t>{ 0, 1, 2 }));
  EXPECT_EQ(lists.Volume(), (std::vector<std::uint32_t>{ 1, 2 })); // not Drawn: cell 0 only has a surface
  // New ranges (a time step's values) are classified again, but lists that come out the same are
  // no change for what uses them.
  EXPECT_FALSE(lists.Update(2, low, high, zeroSet, { 0.05 }, Serial));
  EXPECT_EQ(lists.Version, 2u);
  const std::vector<float> lower = { 0.0f, 0.3f, 0.6f }, upper = { 0.1f, 0.4f, 0.9f }; // cell 1 invisible now
  EXPECT_TRUE(lists.Update(3, lower, upper, zeroSet, { 0.05 }, Serial));
  EXPECT_EQ(lists.Drawn, (std::vector<std::uint32_t>{ 0, 2 }));
  zeroSet.clear(); // skipping off: every cell is a volume cell
  EXPECT_TRUE(lists.Update(3, low, high, zeroSet, { 0.05 }, Serial));
  EXPECT_EQ(lists.Volume().size(), 3u);
  EXPECT_EQ(lists.Builds, 5);
  EXPECT_EQ(lists.Version, 4u);
}

TEST(CellDataIsosurfaces, FacesBetweenCellsOnEitherSideInTheRayOrder)
{
  uv::IsosurfaceList list;
  list.Add(0.5, 1, 0, 0, 1);
  list.Add(0.2, 0, 1, 0, 1);
  list.Add(0.8, 0, 0, 1, 1);
  const std::vector<uv::Isosurface> drawn = list.Drawn(0.0, 1.0);
  auto crossed = [&drawn](double from, double to) {
    std::vector<double> values;
    uv::ForEachSurfaceBetweenCells(drawn, from, to, [&](const uv::Isosurface& s) { values.push_back(s.Value); });
    return values;
  };
  EXPECT_EQ(crossed(0.1, 0.9), (std::vector<double>{ 0.2, 0.5, 0.8 }));
  EXPECT_EQ(crossed(0.9, 0.1), (std::vector<double>{ 0.8, 0.5, 0.2 }));
  EXPECT_EQ(crossed(0.3, 0.4), std::vector<double>{});
  // A cell at exactly the value counts as above it: the face below it holds the surface, the one
  // above not, so a run of cells at the value shows the surface once.
  EXPECT_EQ(crossed(0.4, 0.5), std::vector<double>{ 0.5 });
  EXPECT_EQ(crossed(0.5, 0.6), std::vector<double>{});
  EXPECT_EQ(crossed(0.5, 0.4), std::vector<double>{ 0.5 });
}
