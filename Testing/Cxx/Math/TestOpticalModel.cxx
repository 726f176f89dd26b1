// The optical model's segment integral and the ray/cell geometry of the reference renderer.
#include "uvChebyshevSeries.h"
#include "uvImageErrorMetrics.h"
#include "uvOpticalModel.h"
#include "uvRayCellGeometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
uv::TransferFunction Constant(double extinction, const glm::dvec3& color)
{
  return uv::TransferFunction({ { 0.0, color, extinction }, { 1.0, color, extinction } });
}

/// A transfer function with thin spikes, the hardest case for splitting at nodes.
uv::TransferFunction Spiky()
{
  return uv::TransferFunction({ { 0.0, { 0.2, 0.2, 1.0 }, 0.0 }, { 0.30, { 0.2, 0.2, 1.0 }, 0.0 },
    { 0.31, { 1.0, 0.5, 0.0 }, 40.0 }, { 0.32, { 1.0, 0.5, 0.0 }, 0.0 }, { 0.60, { 0.0, 1.0, 0.0 }, 0.5 },
    { 0.70, { 0.0, 1.0, 0.0 }, 3.0 }, { 1.0, { 1.0, 1.0, 1.0 }, 0.2 } });
}

/// Independent check: many tiny steps, each exact for a constant sample at its midpoint.
template <typename ScalarAt>
uv::RayAccumulator FineSteps(const uv::TransferFunction& tf, const ScalarAt& s, double t0, double t1, int steps)
{
  uv::RayAccumulator accumulator;
  const double h = (t1 - t0) / steps;
  for (int i = 0; i < steps; ++i)
  {
    const uv::TransferFunction::Node n = tf.Evaluate(s(t0 + (i + 0.5) * h));
    const double alpha = 1.0 - std::exp(-n.Extinction * h);
    accumulator.Composite(alpha * n.Color, n.Extinction * h);
  }
  return accumulator;
}
} // namespace

TEST(OpticalModel, ExtinctionFromOpacity)
{
  EXPECT_DOUBLE_EQ(uv::ExtinctionFromOpacity(0.0, 2.0), 0.0);
  // Opacity alpha over the unit distance d means exp(-tau d) = 1 - alpha.
  EXPECT_NEAR(std::exp(-uv::ExtinctionFromOpacity(0.3, 2.0) * 2.0), 0.7, 1e-15);
  EXPECT_TRUE(std::isfinite(uv::ExtinctionFromOpacity(1.0, 1.0)));
}

TEST(OpticalModel, ConstantTransferFunctionIsClosedForm)
{
  const glm::dvec3 color(0.9, 0.4, 0.1);
  for (double tau : { 0.0, 0.3, 2.0, 25.0 })
  {
    for (double length : { 0.01, 0.7, 3.0 })
    {
      uv::RayAccumulator accumulator;
      uv::IntegrateSegment(Constant(tau, color), [](double t) { return 0.2 + 0.5 * t; }, 1.0, 1.0 + length,
        1e-9, accumulator);
      const double alpha = 1.0 - std::exp(-tau * length);
      EXPECT_NEAR(accumulator.Opacity(), alpha, 1e-12);
      EXPECT_NEAR(accumulator.Color.x, color.x * alpha, 1e-9);
      EXPECT_NEAR(accumulator.Color.z, color.z * alpha, 1e-9);
    }
  }
}

TEST(OpticalModel, DenseMediaShowTheColourOfTheirFrontLayer)
{
  // Optical depths up to 1e21 along a segment whose colour changes along it: all the light comes
  // from a front layer far thinner than the spacing of any fixed set of quadrature nodes, and it is
  // the colour at the front (the stress cases' unit distance of 1e-9 on a unit mesh drew black).
  const uv::TransferFunction tf({ { 0.0, { 1.0, 0.2, 0.0 }, 0.0 }, { 1.0, { 0.0, 0.2, 1.0 }, 0.0 } });
  for (double extinction : { 1e3, 1e9, 1e21 })
  {
    SCOPED_TRACE(extinction);
    const uv::TransferFunction dense({ { 0.0, { 1.0, 0.2, 0.0 }, extinction }, { 1.0, { 0.0, 0.2, 1.0 }, extinction } });
    for (double front : { 0.1, 0.7 })
    {
      uv::RayAccumulator accumulator;
      uv::IntegrateSegment(dense, [front](double t) { return front + 0.2 * t; }, 0.0, 1.0, 1e-7, accumulator);
      EXPECT_NEAR(accumulator.Opacity(), 1.0, 1e-9);
      EXPECT_NEAR(accumulator.Color.x, 1.0 - front, 1e-3 * (1.0 + 1e3 / extinction));
      EXPECT_NEAR(accumulator.Color.z, front, 1e-3 * (1.0 + 1e3 / extinction));
    }
  }
  // A transparent medium stays transparent.
  uv::RayAccumulator clear;
  uv::IntegrateSegment(tf, [](double t) { return t; }, 0.0, 1.0, 1e-7, clear);
  EXPECT_EQ(clear.Opacity(), 0.0);
}

TEST(OpticalModel, LinearExtinctionDepthIsExact)
{
  // tau linear in s, s linear in t: depth = length * mean(tau).
  const uv::TransferFunction tf({ { 0.0, { 1, 1, 1 }, 1.0 }, { 1.0, { 1, 1, 1 }, 5.0 } });
  uv::RayAccumulator accumulator;
  uv::IntegrateSegment(tf, [](double t) { return t / 2.0; }, 0.0, 2.0, 1e-10, accumulator);
  EXPECT_NEAR(accumulator.Transmittance, std::exp(-2.0 * 3.0), 1e-13);
  // With white colour, C = 1 - T.
  EXPECT_NEAR(accumulator.Color.y, 1.0 - std::exp(-6.0), 1e-10);
}

TEST(OpticalModel, SpikesMatchFineStepsForLinearAndCurvedScalars)
{
  const uv::TransferFunction tf = Spiky();
  const auto linear = [](double t) { return 0.05 + 0.9 * t; };
  const auto curved = [](double t) { return 0.5 + 0.45 * std::sin(5.0 * t); }; // rises, falls, rises
  for (int which = 0; which < 2; ++which)
  {
    SCOPED_TRACE(which == 0 ? "linear" : "curved");
    uv::RayAccumulator exact, fine;
    if (which == 0)
    {
      uv::IntegrateSegment(tf, linear, 0.0, 1.0, 1e-8, exact);
      fine = FineSteps(tf, linear, 0.0, 1.0, 400000);
    }
    else
    {
      uv::IntegrateSegment(tf, curved, 0.0, 1.5, 1e-8, exact);
      fine = FineSteps(tf, curved, 0.0, 1.5, 400000);
    }
    EXPECT_NEAR(exact.Opacity(), fine.Opacity(), 2e-7);
    EXPECT_NEAR(exact.Color.x, fine.Color.x, 2e-7);
    EXPECT_NEAR(exact.Color.y, fine.Color.y, 2e-7);
    EXPECT_GT(exact.Color.x, 0.05); // the spike at 0.31 was seen
  }
}

TEST(OpticalModel, HalvingTheToleranceChangesLittle)
{
  const uv::TransferFunction tf = Spiky();
  const auto curved = [](double t) { return 0.5 + 0.45 * std::sin(7.0 * t); };
  uv::RayAccumulator coarse, finer;
  uv::IntegrateSegment(tf, curved, 0.0, 2.0, 1e-7, coarse);
  uv::IntegrateSegment(tf, curved, 0.0, 2.0, 5e-8, finer);
  EXPECT_LT(std::abs(coarse.Opacity() - finer.Opacity()), 1e-6);
  EXPECT_LT(glm::length(coarse.Color - finer.Color), 1e-6);
}

TEST(RayCellGeometry, TetrahedronChord)
{
  const glm::dvec3 p[4] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  const std::int64_t ids[4] = { 3, 1, 4, 2 };
  uv::Interval span;
  ASSERT_TRUE(uv::IntersectTetrahedron({ { 0.1, 0.2, -5 }, { 0, 0, 1 } }, p, ids, span));
  EXPECT_NEAR(span.Enter, 5.0, 1e-14);
  EXPECT_NEAR(span.Exit, 5.7, 1e-14); // the face x + y + z = 1
  EXPECT_FALSE(uv::IntersectTetrahedron({ { 0.8, 0.8, -5 }, { 0, 0, 1 } }, p, ids, span));
  const double f[4] = { 1, 2, 3, 4 };
  EXPECT_NEAR(uv::TetrahedronScalar(p, f, { 0.1, 0.2, 0.3 }), 1 + 0.1 + 0.4 + 0.9, 1e-14);
}

TEST(RayCellGeometry, BilinearPatchAndCurvedHexahedron)
{
  // A saddle z = xy over the unit square: the ray down x = y = 0.5 meets it at z = 0.25.
  std::vector<double> hits;
  uv::IntersectBilinearPatch({ { 0.5, 0.5, 3 }, { 0, 0, -1 } }, { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 1 },
    { 0, 1, 0 }, hits);
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_NEAR(hits[0], 2.75, 1e-14);

  // A twisted hexahedron: the chord must match where the inverse map says the ray is inside.
  glm::dvec3 p[8];
  const std::int64_t ids[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  for (int k = 0; k < 8; ++k)
  {
    const auto& c = uv::HexahedronCorners[k];
    const double angle = 0.6 * c[2];
    const double x = c[0] - 0.5, y = c[1] - 0.5;
    p[k] = { std::cos(angle) * x - std::sin(angle) * y, std::sin(angle) * x + std::cos(angle) * y, c[2] };
  }
  std::vector<uv::Interval> parts;
  std::vector<double> scratch;
  const uv::Ray ray{ { -2.0, 0.1, 0.45 }, { 1, 0, 0 } };
  uv::IntersectHexahedron(ray, p, ids, parts, scratch);
  ASSERT_EQ(parts.size(), 1u);
  for (double t : { parts[0].Enter + 1e-7, parts[0].Exit - 1e-7 })
  {
    glm::dvec3 xi(0.5);
    ASSERT_TRUE(uv::InverseTrilinear(p, ray.Origin + t * ray.Direction, xi));
    EXPECT_GE(std::min({ xi.x, xi.y, xi.z }), -1e-6);
    EXPECT_LE(std::max({ xi.x, xi.y, xi.z }), 1 + 1e-6);
  }
  for (double t : { parts[0].Enter - 1e-4, parts[0].Exit + 1e-4 })
  {
    glm::dvec3 xi(0.5);
    uv::InverseTrilinear(p, ray.Origin + t * ray.Direction, xi);
    EXPECT_TRUE(std::min({ xi.x, xi.y, xi.z }) < 0 || std::max({ xi.x, xi.y, xi.z }) > 1);
  }
}

TEST(RayCellGeometry, InverseMapConvergesWhereRoundingLimitsTheStep)
{
  // Small sheared cells far from the origin: in absolute coordinates no Newton step gets below
  // 1e-14, and the reference lost such cells (on the office grid, solves reported failure).
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.05, 0.95);
  for (double offset : { 3.0, 1e6, 1e9 })
  {
    for (double size : { 1e-2, 1.0 })
    {
      glm::dvec3 p[8];
      for (int k = 0; k < 8; ++k)
      {
        const auto& c = uv::HexahedronCorners[k];
        p[k] = glm::dvec3(offset) + size * glm::dvec3(c[0] + 0.3 * c[2] + 0.05 * c[0] * c[1], c[1], c[2] * 0.7);
      }
      int failures = 0;
      double worst = 0.0;
      for (int sample = 0; sample < 200; ++sample)
      {
        const glm::dvec3 truth(unit(random), unit(random), unit(random));
        // The point relative to the cell (as the reference holds it, recentred) plus the offset.
        const glm::dvec3 x = p[0] + (uv::IsoparametricPoint(uv::HexahedronShape(), p, truth, nullptr) - p[0]);
        glm::dvec3 xi(0.5);
        failures += uv::InverseTrilinear(p, x, xi) ? 0 : 1;
        worst = std::max(worst, glm::length(xi - truth));
      }
      EXPECT_EQ(failures, 0) << "offset " << offset << ", size " << size;
      EXPECT_LT(worst, 1e-15 * offset / size * 64 + 1e-12) << "offset " << offset << ", size " << size;
    }
  }
}

TEST(RayCellGeometry, HierarchyFindsEveryCellTheRayCrosses)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<uv::BoundingVolumeHierarchy::Box> boxes;
  for (int i = 0; i < 500; ++i)
  {
    const glm::dvec3 c(uniform(random), uniform(random), uniform(random));
    boxes.push_back({ c - 0.05, c + 0.05 });
  }
  const uv::BoundingVolumeHierarchy hierarchy(boxes);
  for (int r = 0; r < 50; ++r)
  {
    const uv::Ray ray{ { uniform(random), uniform(random), -3.0 },
      glm::normalize(glm::dvec3(0.2 * uniform(random), 0.2 * uniform(random), 1.0)) };
    std::vector<bool> found(boxes.size(), false);
    hierarchy.Traverse(ray, [&](std::int64_t cell) { found[cell] = true; });
    for (std::size_t i = 0; i < boxes.size(); ++i)
    {
      // Brute-force slab test.
      double enter = 0.0, exit = 1e300;
      for (int d = 0; d < 3; ++d)
      {
        double t0 = (boxes[i].Low[d] - ray.Origin[d]) / ray.Direction[d];
        double t1 = (boxes[i].High[d] - ray.Origin[d]) / ray.Direction[d];
        enter = std::max(enter, std::min(t0, t1));
        exit = std::min(exit, std::max(t0, t1));
      }
      if (enter < exit)
      {
        ASSERT_TRUE(found[i]) << "missed box " << i;
      }
    }
  }
}

TEST(RayCellGeometry, RayInASharedFacePlaneBelongsToOneTet)
{
  // Two tets sharing the face (0,1,2) in the plane x = y; rays inside that plane.
  const glm::dvec3 shared[3] = { { 0, 0, 0 }, { 1, 1, 0 }, { 0, 0, 1 } };
  const glm::dvec3 first[4] = { shared[0], shared[1], shared[2], { 1, 0, 0 } };
  const glm::dvec3 second[4] = { shared[0], shared[1], shared[2], { 0, 1, 0 } };
  const std::int64_t firstIds[4] = { 10, 11, 12, 13 };
  const std::int64_t secondIds[4] = { 10, 11, 12, 14 };
  for (double height : { 0.1, 0.3, 0.45 })
  {
    const uv::Ray ray{ { 0.2, 0.2, -1.0 + height }, glm::normalize(glm::dvec3(0, 0, 1)) };
    uv::Interval a, b;
    const bool inFirst = uv::IntersectTetrahedron(ray, first, firstIds, a);
    const bool inSecond = uv::IntersectTetrahedron(ray, second, secondIds, b);
    EXPECT_NE(inFirst, inSecond) << "the shared face's matter must be counted exactly once";
  }
}

TEST(RayCellGeometry, RayInASharedFacePlaneOrEdgeBelongsToOneHexahedron)
{
  // 6 x 1 x 2 unit cubes on shared point ids (more than a leaf of the hierarchy holds); rays along x in the plane z = 1 between the layers,
  // and along y on the edge x = 1, z = 1 that four cells share, their directions off the plane by
  // rounding as a camera's unprojection gives them. The padded boxes offer each ray to every cell
  // around it; the lengths the cells claim must add up to the chord once.
  auto id = [](int i, int j, int k) { return std::int64_t((k * 2 + j) * 7 + i); };
  std::vector<std::array<std::int64_t, 8>> cells;
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 6; ++i)
      cells.push_back({ id(i, 0, k), id(i + 1, 0, k), id(i + 1, 1, k), id(i, 1, k), id(i, 0, k + 1),
        id(i + 1, 0, k + 1), id(i + 1, 1, k + 1), id(i, 1, k + 1) });
  auto point = [](std::int64_t n) { return glm::dvec3(double(n % 7), double((n / 7) % 2), double(n / 14)); };
  std::vector<uv::BoundingVolumeHierarchy::Box> boxes;
  for (const auto& cell : cells)
  {
    uv::BoundingVolumeHierarchy::Box box;
    for (std::int64_t n : cell)
      box.Add({ point(n), point(n) });
    boxes.push_back(uv::BoundingVolumeHierarchy::PaddedForRounding(box));
  }
  const uv::BoundingVolumeHierarchy hierarchy(boxes);
  struct Case
  {
    glm::dvec3 Origin, Direction;
    double Chord;
  };
  const double below = std::nextafter(1.0, 0.0), above = std::nextafter(1.0, 2.0); // 1 within rounding
  const Case cases[] = {
    { { -1.0, 0.3, below }, { 1.0, 0.0, -1e-17 }, 6.0 }, // in the plane between the layers
    { { -1.0, 0.7, above }, { 1.0, 0.0, 1e-17 }, 6.0 },
    { { -1.0, 0.3, 1.0 }, { 1.0, 0.0, 0.0 }, 6.0 },      // exactly in it
    { { below, -1.0, above }, { 0.0, 1.0, -1e-17 }, 1.0 }, // along the edge where four cells meet
    { { above, -1.0, below }, { 1e-17, 1.0, 1e-17 }, 1.0 },
    { { 0.5, 0.5, -1.0 }, { 0.0, 0.0, 1.0 }, 2.0 },      // across the plane: no tie
  };
  for (const Case& c : cases)
  {
    const uv::Ray ray{ c.Origin, glm::normalize(c.Direction) };
    double length = 0.0;
    int claimed = 0;
    hierarchy.Traverse(ray, [&](std::int64_t cell) {
      glm::dvec3 p[8];
      for (int k = 0; k < 8; ++k)
        p[k] = point(cells[cell][k]);
      std::vector<uv::Interval> parts;
      std::vector<double> scratch;
      uv::IntersectHexahedron(ray, p, cells[cell].data(), parts, scratch);
      for (const uv::Interval& part : parts)
        length += part.Exit - part.Enter;
      claimed += parts.empty() ? 0 : 1;
    });
    EXPECT_NEAR(length, c.Chord, 1e-9) << "origin " << c.Origin.x << " " << c.Origin.y << " " << c.Origin.z;
    EXPECT_EQ(claimed, int(c.Chord + 0.5)) << "one cell per unit of the chord";
  }
}

TEST(ChebyshevSeries, ResolvesSmoothFunctionsAndRejectsKinks)
{
  uv::ChebyshevSeries series;
  const auto smooth = [](double t) { return std::exp(0.7 * t) * std::sin(2.0 * t); };
  ASSERT_TRUE(series.Fit(smooth, 0.3, 1.1, 1e-12));
  for (double t = 0.3; t <= 1.1; t += 0.01)
  {
    EXPECT_NEAR(series(t), smooth(t), 1e-12);
  }
  const auto kinked = [](double t) { return std::abs(t - 0.5); };
  EXPECT_FALSE(series.Fit(kinked, 0.0, 1.0, 1e-12));
}

TEST(ImageErrorMetrics, KnownDifferences)
{
  // 4 pixels RGBA: identical, one channel off by 0.1, transparent both, all channels off by 0.2.
  const float candidate[16] = { 0.5f, 0.5f, 0.5f, 1.0f, 0.6f, 0.0f, 0.0f, 1.0f, 0, 0, 0, 0, 0.2f, 0.2f, 0.2f, 0.2f };
  const double reference[16] = { 0.5, 0.5, 0.5, 1.0, 0.5, 0.0, 0.0, 1.0, 0, 0, 0, 0, 0, 0, 0, 0 };
  const uv::ErrorMetrics m = uv::CompareImages(candidate, reference, 4, 4, 4);
  // Squared errors: 0.01 + 4 * 0.04 = 0.17 over 16 channels.
  EXPECT_NEAR(m.All.RMSE, std::sqrt(0.17 / 16), 1e-7);
  EXPECT_NEAR(m.All.PSNR, 20 * std::log10(1 / std::sqrt(0.17 / 16)), 1e-5);
  EXPECT_NEAR(m.All.Maximum, 0.2, 1e-7);
  EXPECT_NEAR(m.All.Percentile99, 0.2, 1e-7);
  EXPECT_EQ(m.Covered.Pixels, 3u); // the transparent pixel is left out
  EXPECT_NEAR(m.Covered.RMSE, std::sqrt(0.17 / 12), 1e-7);
  const uv::ErrorMetrics same = uv::CompareImages(reference, reference, 4, 4, 4);
  EXPECT_EQ(same.All.RMSE, 0.0);
  EXPECT_TRUE(std::isinf(same.All.PSNR));
  unsigned char rgb[3];
  uv::HeatColor(0.0, 0.1, rgb);
  EXPECT_EQ(rgb[0] + rgb[1] + rgb[2], 0);
  uv::HeatColor(1.0, 0.1, rgb);
  EXPECT_EQ(rgb[0] + rgb[1] + rgb[2], 3 * 255);
}
