// Partial pre-integration (uvPreIntegration.h): the Psi function, its table, and the piecewise
// segment integral against the reference integrator of uvOpticalModel.h.
#include "uvPreIntegration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
/// Psi by a plain midpoint rule with a million steps: slow, simple, independent.
double PsiMidpoint(double a, double b)
{
  const int steps = 1000000;
  double sum = 0.0;
  for (int i = 0; i < steps; ++i)
  {
    const double u = (i + 0.5) / steps;
    sum += std::exp(-(a * u + 0.5 * (b - a) * u * u));
  }
  return sum / steps;
}

uv::TransferFunction Spiky()
{
  return uv::TransferFunction({ { 0.0, { 0.2, 0.2, 1.0 }, 0.0 }, { 0.30, { 0.2, 0.2, 1.0 }, 0.0 },
    { 0.31, { 1.0, 0.5, 0.0 }, 40.0 }, { 0.32, { 1.0, 0.5, 0.0 }, 0.0 }, { 0.60, { 0.0, 1.0, 0.0 }, 0.5 },
    { 0.70, { 0.0, 1.0, 0.0 }, 3.0 }, { 1.0, { 1.0, 1.0, 1.0 }, 0.2 } });
}
} // namespace

TEST(PreIntegration, PsiClosedForms)
{
  EXPECT_NEAR(uv::PsiExact(0.0, 0.0), 1.0, 1e-14);
  for (double x : { 1e-6, 0.01, 0.5, 3.0, 40.0, 1e3, 1e6 })
  {
    EXPECT_NEAR(uv::PsiExact(x, x), -std::expm1(-x) / x, 1e-9 * -std::expm1(-x) / x) << x;
  }
  // a = 0: integral of exp(-b u^2 / 2) is an error function.
  for (double b : { 0.1, 2.0, 50.0, 1e4 })
  {
    const double exact = std::sqrt(M_PI / (2.0 * b)) * std::erf(std::sqrt(b / 2.0));
    EXPECT_NEAR(uv::PsiExact(0.0, b), exact, 1e-9 * exact) << b;
  }
}

TEST(PreIntegration, PsiAgainstDirectIntegration)
{
  for (double a : { 0.0, 0.01, 0.7, 5.0, 60.0 })
  {
    for (double b : { 0.0, 0.02, 1.3, 9.0, 80.0 })
    {
      EXPECT_NEAR(uv::PsiExact(a, b), PsiMidpoint(a, b), 2e-9) << a << " " << b;
    }
  }
}

TEST(PreIntegration, SeriesForSmallDepths)
{
  std::mt19937 random(1);
  std::uniform_real_distribution<double> u(0.0, uv::PsiSeriesLimit);
  double worst = 0.0;
  for (int i = 0; i < 1000; ++i)
  {
    const double a = u(random), b = u(random) * (uv::PsiSeriesLimit - a) / uv::PsiSeriesLimit;
    worst = std::max(worst, std::abs(uv::PsiSeries(a, b) - uv::PsiExact(a, b)));
  }
  EXPECT_LT(worst, 5e-8);
}

TEST(PreIntegration, TableAccuracy)
{
  // Bilinear reads of the table against the exact Psi over depths from 1e-2 to 1e4, the range the
  // shader reads it for. The table is what the GPU uses; this bound is what its pieces inherit.
  static const uv::PsiTable table(uv::PsiTableSize);
  std::mt19937 random(2);
  std::uniform_real_distribution<double> exponent(-2.0, 4.0);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i)
  {
    const double a = std::pow(10.0, exponent(random)), b = std::pow(10.0, exponent(random));
    worst = std::max(worst, std::abs(table.Lookup(a, b) - uv::PsiExact(a, b)));
  }
  std::printf("Psi table %d^2: worst bilinear error %.3g\n", table.GetSize(), worst);
  EXPECT_LT(worst, 3e-5);
  EXPECT_EQ(table.GetValues().front(), 1.0f);
  EXPECT_EQ(table.GetValues().back(), 0.0f);
}

TEST(PreIntegration, LinearScalarSegmentMatchesTheReferenceIntegrator)
{
  // With the exact Psi, cutting at nodes makes the pre-integrated segment exact; with the table,
  // it is within the table's error.
  static const uv::PsiTable table(uv::PsiTableSize);
  const uv::TransferFunction tf = Spiky();
  std::mt19937 random(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worstExact = 0.0, worstTable = 0.0;
  for (int i = 0; i < 400; ++i)
  {
    const double sf = 1.2 * u(random) - 0.1, sb = 1.2 * u(random) - 0.1;
    const double length = std::pow(10.0, -3.0 + 3.5 * u(random));
    uv::RayAccumulator reference, exact, tabled;
    uv::IntegrateSegment(tf, [&](double t) { return sf + (sb - sf) * t / length; }, 0.0, length, 1e-11, reference);
    uv::IntegrateLinearScalarSegment(tf, sf, sb, length, exact);
    uv::IntegrateLinearScalarSegment(tf, sf, sb, length, tabled, &table);
    auto difference = [&](const uv::RayAccumulator& x) {
      return std::max({ std::abs(x.Transmittance - reference.Transmittance),
        glm::length(x.Color - reference.Color) });
    };
    worstExact = std::max(worstExact, difference(exact));
    worstTable = std::max(worstTable, difference(tabled));
  }
  std::printf("segment: worst difference exact-Psi %.3g, table %.3g\n", worstExact, worstTable);
  EXPECT_LT(worstExact, 1e-9);
  EXPECT_LT(worstTable, 1e-4);
}

TEST(PreIntegration, SegmentTableReadBilinearly)
{
  // The fixed-length table, read between its texels as a GPU's bilinear filter does, against the
  // exact segment: smooth transfer functions need few texels; sharp ones are why the mapper keeps
  // the exact walk as an option. Also exact at the texels themselves.
  auto worstError = [](const uv::TransferFunction& tf, double length, int size) {
    return uv::SegmentTableError(tf, length, uv::SegmentTable(tf, length, size), size, 2000);
  };
  const uv::TransferFunction ramp({ { 0.0, { 0.2, 0.3, 0.8 }, 0.0 }, { 0.5, { 0.9, 0.9, 0.9 }, 0.4 },
    { 1.0, { 0.7, 0.0, 0.1 }, 4.0 } });
  const double smooth = worstError(ramp, 0.05, 256), spiky = worstError(Spiky(), 0.05, 256);
  std::printf("segment table 256^2, length 0.05: worst bilinear error %.3g (ramp), %.3g (spiky)\n", smooth, spiky);
  EXPECT_LT(smooth, 5e-5);
  EXPECT_NEAR(uv::NarrowestNodeGap(Spiky().GetNodes()), 0.01, 1e-12);
  EXPECT_GT(spiky, smooth); // a sharp transfer function is what the table interpolates worst
  const std::vector<float> table = uv::SegmentTable(ramp, 0.05, 5);
  uv::RayAccumulator exact;
  uv::IntegrateLinearScalarSegment(ramp, 0.25, 0.75, 0.05, exact);
  EXPECT_NEAR(table[4 * (3 * 5 + 1) + 3], exact.Opacity(), 1e-7);
  EXPECT_NEAR(uv::ReadSegmentTable(table, 5, 0.25, 0.75)[3], exact.Opacity(), 1e-7); // a texel, read
}

TEST(PreIntegration, ConstantScalarAndZeroLength)
{
  const uv::TransferFunction tf = Spiky();
  uv::RayAccumulator none;
  uv::IntegrateLinearScalarSegment(tf, 0.65, 0.65, 0.0, none);
  EXPECT_EQ(none.Transmittance, 1.0);
  uv::RayAccumulator flat;
  uv::IntegrateLinearScalarSegment(tf, 0.65, 0.65, 2.0, flat);
  const auto node = tf.Evaluate(0.65);
  EXPECT_NEAR(flat.Transmittance, std::exp(-2.0 * node.Extinction), 1e-14);
  EXPECT_NEAR(flat.Color.y, (1.0 - std::exp(-2.0 * node.Extinction)) * node.Color.y, 1e-12);
}
