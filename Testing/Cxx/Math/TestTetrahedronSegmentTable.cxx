// uvTetrahedronSegmentTable.h: the table holds the exact segments at its texels, its trilinear read
// converges on them between texels as it grows, the error it reports bounds what an independent
// sampling finds, and the extent helpers bound what they claim to.
#include "uvTetrahedronSegmentTable.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
using Node = uv::TransferFunction::Node;

/// A smooth ramp of colour and extinction, and a thin opaque spike in the middle.
std::vector<Node> Ramp()
{
  return { { 0.0, { 0.2, 0.3, 0.8 }, 0.0 }, { 0.3, { 0.5, 0.5, 0.6 }, 0.05 }, { 1.0, { 0.9, 0.1, 0.1 }, 0.4 } };
}
std::vector<Node> Spike()
{
  return { { 0.0, { 1, 1, 1 }, 0.0 }, { 0.49, { 1, 1, 1 }, 0.0 }, { 0.5, { 1, 0.5, 0 }, 50.0 }, { 0.51, { 1, 1, 1 }, 0.0 },
    { 1.0, { 1, 1, 1 }, 0.0 } };
}

uv::TetrahedronSegmentTable Table(const std::vector<Node>& nodes, double maxLength, int scalars, int lengths)
{
  return uv::MakeTetrahedronSegmentTable(uv::TransferFunction(nodes), maxLength, scalars, lengths,
    uv::SharedPsiTable(), [](int count, const auto& row) {
      for (int r = 0; r < count; ++r)
        row(r);
    });
}

/// The exact segment (exact Psi): premultiplied colour and opacity.
std::array<double, 4> Exact(const std::vector<Node>& nodes, double sf, double sb, double length)
{
  uv::RayAccumulator segment;
  uv::IntegrateLinearScalarSegment(uv::TransferFunction(nodes), sf, sb, length, segment);
  return { segment.Color.r, segment.Color.g, segment.Color.b, segment.Opacity() };
}
}

TEST(TetrahedronSegmentTable, TexelsHoldTheExactSegments)
{
  const auto table = Table(Ramp(), 3.0, 17, 9);
  for (int i : { 0, 5, 16 })
    for (int j : { 0, 9, 16 })
      for (int k : { 0, 4, 8 })
      {
        const auto read = table.Read(i / 16.0, j / 16.0, table.LengthAt(k));
        const auto exact = Exact(Ramp(), i / 16.0, j / 16.0, table.LengthAt(k));
        for (int c = 0; c < 4; ++c)
          EXPECT_NEAR(read[c], exact[c], 2e-5) << i << " " << j << " " << k << " channel " << c;
      }
  // A segment of no length adds nothing.
  const auto empty = table.Read(0.3, 0.9, 0.0);
  for (int c = 0; c < 4; ++c)
    EXPECT_EQ(empty[c], 0.0);
}

TEST(TetrahedronSegmentTable, ReportedErrorBoundsAnIndependentSampleAndShrinksWithSize)
{
  const uv::TransferFunction ramp(Ramp());
  double previous = 1.0;
  for (int size : { 16, 64, 128 })
  {
    const auto table = Table(Ramp(), 2.0, size, size / 4);
    const double reported = uv::TetrahedronSegmentTableError(ramp, table, 4096);
    EXPECT_LT(reported, previous);
    previous = reported;
    // Segments the report never saw (another seed, lengths and scalars everywhere): within twice it.
    std::mt19937 random(123);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int n = 0; n < 2000; ++n)
    {
      const double sf = unit(random), sb = unit(random), length = 2.0 * unit(random);
      const auto read = table.Read(sf, sb, length);
      const auto exact = Exact(Ramp(), sf, sb, length);
      for (int c = 0; c < 4; ++c)
        ASSERT_LE(std::abs(read[c] - exact[c]), 2.0 * reported + 1e-6) << size;
    }
  }
  EXPECT_LT(previous, 5e-4); // 128 x 32 on a smooth ramp: within the default tolerance, 1e-3
  // A spike narrower than a texel: the report says the table cannot stand in for the cuts.
  const auto spiky = Table(Spike(), 2.0, 128, 32);
  EXPECT_GT(uv::TetrahedronSegmentTableError(uv::TransferFunction(Spike()), spiky, 4096), 1e-2);
}

TEST(TetrahedronSegmentTable, DenseMediaCostTheLengthAxisLittle)
{
  // The ramp over lengths where its densest value reaches optical depth 3 and 10 (long cells against
  // a short unit distance, as Blunt Fin's): opacity changes fastest over the shortest lengths, which
  // get the length axis's texels, so the error stays near what the scalar axes leave (evenly spaced
  // lengths left depth 10 far worse than depth 3).
  const uv::TransferFunction ramp(Ramp());
  const auto error = [&](double depth) {
    return uv::TetrahedronSegmentTableError(ramp, Table(Ramp(), depth / 0.4, 128, 32), 4096);
  };
  const double moderate = error(3.0), dense = error(10.0);
  EXPECT_LT(dense, 2e-3);
  EXPECT_LT(dense, 2.0 * moderate);
  // Texel k along the length still holds the exact segment of its length.
  const auto table = Table(Ramp(), 10.0 / 0.4, 128, 32);
  for (int k : { 0, 1, 7, 31 })
  {
    const double length = table.LengthAt(k);
    EXPECT_NEAR(table.LengthCoordinate(length), (k + 0.5) / 32.0, 1e-12) << k;
    const auto read = table.Read(0.25, 0.75, length);
    const auto exact = Exact(Ramp(), 0.25, 0.75, length);
    for (int c = 0; c < 4; ++c)
      EXPECT_NEAR(read[c], exact[c], 2e-5) << k << " channel " << c;
  }
  EXPECT_DOUBLE_EQ(table.LengthAt(31), 10.0 / 0.4);
}

TEST(TetrahedronSegmentTable, LongestEdgeAndLargestStretch)
{
  const std::vector<float> points = { 0, 0, 0, 0, 3, 0, 0, 0, 0, 1, 0, 0, 0, 0, 2, 0, 10, 10, 10, 0 };
  const std::vector<std::uint32_t> tetrahedra = { 0, 1, 2, 3, 0, 1, 2, 4 };
  EXPECT_DOUBLE_EQ(uv::LongestSquaredEdge(points, tetrahedra, 0, 1), 13.0); // (3,0,0) to (0,0,2)
  EXPECT_DOUBLE_EQ(uv::LongestSquaredEdge(points, tetrahedra, 0, 2), 300.0);
  // A rotation of diag(1, 2, 3): stretches by 3 at most, whatever the rotation.
  const double c = std::cos(0.7), s = std::sin(0.7);
  const glm::dmat3 rotation(c, s, 0, -s, c, 0, 0, 0, 1);
  const glm::dmat3 scale(1, 0, 0, 0, 2, 0, 0, 0, 3);
  EXPECT_NEAR(uv::LargestStretch(rotation * scale * glm::transpose(rotation)), 3.0, 1e-9);
  EXPECT_NEAR(uv::LargestStretch(glm::dmat3(1.0) * 0.5), 0.5, 1e-12);
}
