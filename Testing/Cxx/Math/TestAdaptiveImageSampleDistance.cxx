// The automatic image sample distance (uvAdaptiveImageSampleDistance.h): still frames keep the
// user's distance, interactive ones converge on the time allowed for a cost that goes with the
// pixels, stay within the limits, and hold still under noise within the tolerance.
#include "uvAdaptiveImageSampleDistance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
using Adaptive = uv::AdaptiveImageSampleDistance;

// A frame's cost: a fixed part and a part per pixel of a 512 x 512 tile drawn at `distance`.
double FrameSeconds(double distance, double fixedSeconds, double fullImageSeconds)
{
  return fixedSeconds + fullImageSeconds / (distance * distance);
}
}

TEST(AdaptiveImageSampleDistance, StillFramesKeepTheUsersDistance)
{
  Adaptive adaptive;
  Adaptive::Limits limits;
  limits.Still = 1.5;
  EXPECT_EQ(adaptive.Next(1e4, limits), 1.5); // VTK's still rate
  EXPECT_EQ(adaptive.Next(uv::StillFrameSeconds, limits), 1.5);
  EXPECT_EQ(adaptive.Next(std::numeric_limits<double>::infinity(), limits), 1.5);
  EXPECT_EQ(adaptive.Next(std::numeric_limits<double>::quiet_NaN(), limits), 1.5);
  EXPECT_EQ(adaptive.Next(0.0, limits), 1.5);
  adaptive.Record(4.0, 0.05, 0.1);
  EXPECT_EQ(adaptive.Next(1e4, limits), 1.5); // whatever the interactive frames did
}

TEST(AdaptiveImageSampleDistance, FirstInteractiveFrameWithoutHistoryIsTheFinest)
{
  Adaptive adaptive;
  Adaptive::Limits limits;
  limits.Still = 1.0;
  limits.Minimum = 2.0;
  EXPECT_EQ(adaptive.Next(0.1, limits), 2.0);
  limits.Minimum = 0.5; // never finer than the still frame
  EXPECT_EQ(adaptive.Next(0.1, limits), 1.0);
}

TEST(AdaptiveImageSampleDistance, ConvergesOnTheAllowedTimeForAPixelBoundCost)
{
  Adaptive adaptive;
  const Adaptive::Limits limits;
  const double allowed = 0.1, full = 0.4; // a still frame four times the time allowed
  adaptive.Record(1.0, FrameSeconds(1.0, 0.0, full), 1e4);
  double distance = 1.0;
  for (int frame = 0; frame < 6; ++frame)
  {
    distance = adaptive.Next(allowed, limits);
    adaptive.Record(distance, FrameSeconds(distance, 0.0, full), allowed);
  }
  EXPECT_NEAR(distance, 2.0, 1e-12); // pixels a quarter: a quarter of the time
}

TEST(AdaptiveImageSampleDistance, OneSlowFrameMovesItByTheMaximumStepAtMost)
{
  Adaptive adaptive;
  const Adaptive::Limits limits;
  adaptive.Record(2.0, 0.1, 0.1);
  adaptive.Record(2.0, 5.0, 0.1); // one-off work: fifty times the time allowed
  EXPECT_EQ(adaptive.Next(0.1, limits), 2.0 * Adaptive::MaximumStep);
  adaptive.Record(4.0, 0.001, 0.1); // and one far under it
  EXPECT_EQ(adaptive.Next(0.1, limits), 4.0 / Adaptive::MaximumStep);
}

TEST(AdaptiveImageSampleDistance, AFixedCostDrivesItToTheMaximumAndNoFurther)
{
  Adaptive adaptive;
  Adaptive::Limits limits;
  limits.Maximum = 6.0;
  const double allowed = 0.1;
  adaptive.Record(1.0, FrameSeconds(1.0, 0.15, 0.4), 1e4); // the fixed part alone is over the time
  double distance = 1.0;
  for (int frame = 0; frame < 20; ++frame)
  {
    distance = adaptive.Next(allowed, limits);
    EXPECT_LE(distance, 6.0);
    EXPECT_GE(distance, 1.0);
    adaptive.Record(distance, FrameSeconds(distance, 0.15, 0.4), allowed);
  }
  EXPECT_EQ(distance, 6.0);
}

TEST(AdaptiveImageSampleDistance, FasterFramesGoBackToFinerImages)
{
  Adaptive adaptive;
  const Adaptive::Limits limits;
  adaptive.Record(4.0, 0.05, 0.1); // under the time allowed
  const double next = adaptive.Next(0.1, limits);
  EXPECT_LT(next, 4.0);
  EXPECT_NEAR(next, 4.0 * std::sqrt(0.5), 1e-12);
  adaptive.Record(1.2, 0.001, 0.1);
  EXPECT_EQ(adaptive.Next(0.1, limits), 1.0); // clamped at the still distance
}

TEST(AdaptiveImageSampleDistance, NoiseWithinTheToleranceKeepsTheImageSize)
{
  Adaptive adaptive;
  const Adaptive::Limits limits;
  adaptive.Record(3.0, 0.1 * (1.0 + 0.9 * Adaptive::Tolerance), 0.1);
  EXPECT_EQ(adaptive.Next(0.1, limits), 3.0);
  adaptive.Record(3.0, 0.1 * (1.0 - 0.9 * Adaptive::Tolerance), 0.1);
  EXPECT_EQ(adaptive.Next(0.1, limits), 3.0);
  adaptive.Record(3.0, 0.1 * (1.0 + 2.0 * Adaptive::Tolerance), 0.1);
  EXPECT_GT(adaptive.Next(0.1, limits), 3.0);
  // After a still frame the tolerance does not hold: the still frame's time says little of the size.
  adaptive.Record(3.0, 0.105, 1e4);
  EXPECT_NE(adaptive.Next(0.1, limits), 3.0);
}
