// uvTransferFunctionSimplification.h: the kept nodes stay within the stated tolerances at every
// scalar, sampled densely and independently of the nodes, and ray segments stay within the bound
// that follows.
#include "uvPreIntegration.h"
#include "uvTransferFunctionSimplification.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace
{
using Node = uv::TransferFunction::Node;

/// A sampled colour map as ParaView's presets are: 256 nodes of a smooth curve through colour space,
/// with an opacity ramp that is zero over the first fifth (extinction from opacity at unit distance).
std::vector<Node> SampledColorMap(int count = 256)
{
  std::vector<Node> nodes;
  for (int k = 0; k < count; ++k)
  {
    const double s = static_cast<double>(k) / (count - 1);
    const glm::dvec3 color(0.27 + 0.7 * s * s, 0.5 + 0.4 * std::sin(3.0 * s), 0.33 + 0.3 * std::cos(5.0 * s));
    const double opacity = std::max(0.0, (s - 0.2) / 0.8) * 0.8;
    nodes.push_back({ s, color, uv::ExtinctionFromOpacity(opacity, 1.0) });
  }
  return nodes;
}

void ExpectWithin(const std::vector<Node>& original, const std::vector<Node>& kept, double colorTolerance,
  double extinctionTolerance)
{
  const uv::TransferFunction exact(original), simplified(kept);
  for (int i = 0; i <= 20000; ++i)
  {
    const double s = original.front().Scalar +
      (original.back().Scalar - original.front().Scalar) * static_cast<double>(i) / 20000.0;
    const Node a = exact.Evaluate(s), b = simplified.Evaluate(s);
    for (int channel = 0; channel < 3; ++channel)
      ASSERT_LE(std::abs(a.Color[channel] - b.Color[channel]), colorTolerance + 1e-12) << "at " << s;
    ASSERT_LE(std::abs(a.Extinction - b.Extinction), extinctionTolerance * a.Extinction + 1e-12) << "at " << s;
  }
}
} // namespace

TEST(TransferFunctionSimplification, SampledColorMapKeepsFewNodesWithinTheTolerances)
{
  const std::vector<Node> nodes = SampledColorMap();
  std::size_t previous = 0;
  for (double tolerance : { 1e-2, 1e-3, 1e-4 })
  {
    const std::vector<Node> kept = uv::SimplifyTransferFunction(nodes, tolerance, tolerance);
    EXPECT_GT(kept.size(), previous) << tolerance; // a tighter tolerance keeps more
    previous = kept.size();
    if (tolerance >= 1e-3)
      EXPECT_LT(kept.size(), nodes.size() / 4) << tolerance;
    EXPECT_EQ(kept.front(), nodes.front());
    EXPECT_EQ(kept.back(), nodes.back());
    ExpectWithin(nodes, kept, tolerance, tolerance);
  }
}

TEST(TransferFunctionSimplification, CollinearNodesGoEvenAtZeroTolerance)
{
  std::vector<Node> nodes;
  for (int k = 0; k <= 8; ++k)
    nodes.push_back({ k / 8.0, glm::dvec3(k / 8.0, 0.5, 1.0 - k / 8.0), 2.0 * k });
  EXPECT_EQ(uv::SimplifyTransferFunction(nodes, 0.0, 0.0).size(), 2u);
  nodes[4].Color.g = 0.5 + 1e-6;
  const std::vector<Node> kept = uv::SimplifyTransferFunction(nodes, 0.0, 0.0);
  EXPECT_NE(std::find(kept.begin(), kept.end(), nodes[4]), kept.end());
  EXPECT_EQ(uv::SimplifyTransferFunction(nodes, 1e-5, 0.0).size(), 2u);
}

TEST(TransferFunctionSimplification, StepsSpikesAndTransparentRangesStay)
{
  // A step (two nodes at one scalar), a thin spike and a transparent run between collinear colours.
  const std::vector<Node> nodes = { { 0.0, { 0, 0, 1 }, 0.0 }, { 0.2, { 0, 0, 1 }, 0.0 }, { 0.3, { 0, 0, 1 }, 0.0 },
    { 0.3, { 1, 0, 0 }, 5.0 }, { 0.5, { 1, 0, 0 }, 5.0 }, { 0.60, { 1, 1, 0 }, 0.0 }, { 0.61, { 1, 1, 0 }, 40.0 },
    { 0.62, { 1, 1, 0 }, 0.0 }, { 1.0, { 1, 1, 0 }, 0.0 } };
  const std::vector<Node> kept = uv::SimplifyTransferFunction(nodes, 1e-3, 1e-3);
  ExpectWithin(nodes, kept, 1e-3, 1e-3);
  const uv::TransferFunction simplified(kept), exact(nodes);
  for (double s : { 0.3, 0.61 })
    EXPECT_EQ(simplified.Evaluate(s).Extinction, exact.Evaluate(s).Extinction) << s;
  for (double s : { 0.1, 0.25, 0.58, 0.605, 0.615, 0.8 })
    EXPECT_EQ(simplified.Evaluate(s).Extinction == 0.0, exact.Evaluate(s).Extinction == 0.0) << s;
  EXPECT_LT(kept.size(), nodes.size()); // the transparent run's middle node and the flat top's
}

TEST(TransferFunctionSimplification, SegmentsStayWithinTwiceTheTolerance)
{
  // Colour within e of the original at every scalar changes a segment's premultiplied colour by at
  // most e times its opacity; optical depth within e relative changes its transmittance T by at most
  // T (exp(e depth) - 1), under e / e^1 for e small: together under 2 e.
  const std::vector<Node> nodes = SampledColorMap();
  const double tolerance = 1e-3;
  const uv::TransferFunction exact(nodes), simplified(uv::SimplifyTransferFunction(nodes, tolerance, tolerance));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> scalar(0.0, 1.0), length(0.0, 6.0);
  double largest = 0.0;
  for (int i = 0; i < 2000; ++i)
  {
    const double front = scalar(random), back = scalar(random), l = length(random);
    uv::RayAccumulator a, b;
    uv::IntegrateLinearScalarSegment(exact, front, back, l, a);
    uv::IntegrateLinearScalarSegment(simplified, front, back, l, b);
    for (int channel = 0; channel < 3; ++channel)
      largest = std::max(largest, std::abs(a.Color[channel] - b.Color[channel]));
    largest = std::max(largest, std::abs(a.Opacity() - b.Opacity()));
  }
  EXPECT_LE(largest, 2.0 * tolerance);
  EXPECT_GT(largest, 0.0); // something was dropped
}
