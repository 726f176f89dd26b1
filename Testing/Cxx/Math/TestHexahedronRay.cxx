// The hexahedral ray math (uvHexahedronRay.h): the cubic along a ray in the cell's frame, its
// extrema and node crossings, and the three integration modes against the reference integrator.
#include "uvHexahedronRay.h"
#include "uvRayCellGeometry.h"

#include <gtest/gtest.h>

#include <random>

namespace
{
glm::dvec3 Corner(int k)
{
  const auto& c = uv::HexahedronCorners[k];
  return glm::dvec3(c[0], c[1], c[2]);
}

/// A parallelepiped: a unit cube scaled, sheared and rotated, at an offset.
std::array<glm::dvec3, 8> Parallelepiped(std::mt19937& random)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  glm::dmat3 m(1.0);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      m[c][r] = (r == c ? 1.5 : 0.0) + 0.6 * u(random);
  const glm::dvec3 offset(10 * u(random), 10 * u(random), 10 * u(random));
  std::array<glm::dvec3, 8> p;
  for (int k = 0; k < 8; ++k)
    p[k] = offset + m * Corner(k);
  return p;
}

double TrueScalar(const std::array<glm::dvec3, 8>& p, const double f[8], const glm::dvec3& x)
{
  glm::dvec3 xi(0.5);
  EXPECT_TRUE(uv::InverseTrilinear(p.data(), x, xi));
  return uv::IsoparametricScalar(uv::HexahedronShape(), f, xi);
}

uv::TransferFunction Spiky()
{
  return uv::TransferFunction({ { 0.0, { 0.2, 0.2, 1.0 }, 0.0 }, { 0.30, { 0.2, 0.2, 1.0 }, 0.0 },
    { 0.31, { 1.0, 0.5, 0.0 }, 40.0 }, { 0.32, { 1.0, 0.5, 0.0 }, 0.0 }, { 0.60, { 0.0, 1.0, 0.0 }, 0.5 },
    { 0.70, { 0.0, 1.0, 0.0 }, 3.0 }, { 1.0, { 1.0, 1.0, 1.0 }, 0.2 } });
}
} // namespace

TEST(HexahedronRay, CubicIsExactOnParallelepipeds)
{
  std::mt19937 random(21);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0.0;
  for (int trial = 0; trial < 300; ++trial)
  {
    const auto p = Parallelepiped(random);
    double f[8];
    for (double& v : f)
      v = u(random);
    const uv::HexahedronFrame frame = uv::MakeHexahedronFrame(p.data());
    // A chord between two random points of the cell.
    auto inside = [&] { return frame.Origin + frame.Axes * glm::dvec3(u(random), u(random), u(random)); };
    const glm::dvec3 a = inside(), b = inside();
    const uv::Cubic cubic = uv::TrilinearAlongSegment(f, uv::FrameParametric(frame, a), uv::FrameParametric(frame, b));
    // The curved cells' route, the cubic through four exact samples, is the same cubic here.
    const uv::Cubic sampled = uv::CubicThroughSamples(TrueScalar(p, f, a),
      TrueScalar(p, f, a + uv::CurvedSampleNear * (b - a)), TrueScalar(p, f, a + uv::CurvedSampleFar * (b - a)),
      TrueScalar(p, f, b));
    for (double t : { 0.0, 0.1, 0.37, 0.5, 0.81, 1.0 })
    {
      worst = std::max(worst, std::abs(cubic(t) - TrueScalar(p, f, a + t * (b - a))));
      worst = std::max(worst, std::abs(sampled(t) - TrueScalar(p, f, a + t * (b - a))));
    }
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(HexahedronRay, RotatedCubeIsWellConditionedWhereTheWorldFitIsSingular)
{
  // The unit cube rotated 45 degrees about z: the paper's world-space basis
  // (1, x, y, z, xy, xz, yz, xyz) at the 8 corners is rank-deficient, the frame is not.
  const double c = std::sqrt(0.5);
  const glm::dmat3 rotation(glm::dvec3(c, c, 0), glm::dvec3(-c, c, 0), glm::dvec3(0, 0, 1));
  std::array<glm::dvec3, 8> p;
  for (int k = 0; k < 8; ++k)
    p[k] = rotation * (Corner(k) - glm::dvec3(0.5));
  // Rank of the 8x8 world-space system by Gaussian elimination with partial pivoting.
  double m[8][8];
  for (int k = 0; k < 8; ++k)
  {
    const glm::dvec3& x = p[k];
    const double row[8] = { 1, x.x, x.y, x.z, x.x * x.y, x.x * x.z, x.y * x.z, x.x * x.y * x.z };
    std::copy(row, row + 8, m[k]);
  }
  int rank = 0;
  for (int col = 0; col < 8 && rank < 8; ++col)
  {
    int pivot = rank;
    for (int r = rank; r < 8; ++r)
      if (std::abs(m[r][col]) > std::abs(m[pivot][col]))
        pivot = r;
    if (std::abs(m[pivot][col]) < 1e-12)
      continue;
    std::swap(m[pivot], m[rank]);
    for (int r = rank + 1; r < 8; ++r)
    {
      const double factor = m[r][col] / m[rank][col];
      for (int k = col; k < 8; ++k)
        m[r][k] -= factor * m[rank][k];
    }
    ++rank;
  }
  EXPECT_LT(rank, 8);
  const uv::HexahedronFrame frame = uv::MakeHexahedronFrame(p.data());
  const glm::dmat3 a = frame.Axes;
  const double norm = glm::length(a[0]) + glm::length(a[1]) + glm::length(a[2]);
  const double inverseNorm = glm::length(frame.Inverse[0]) + glm::length(frame.Inverse[1]) + glm::length(frame.Inverse[2]);
  EXPECT_LT(norm * inverseNorm, 10.0); // condition number of a rotation, up to the norm used
  const double f[8] = { 0.1, 0.9, 0.3, 0.7, 0.5, 0.2, 0.8, 0.4 };
  const glm::dvec3 x0(-0.3, -0.2, -0.4), x1(0.25, 0.3, 0.45);
  const uv::Cubic cubic = uv::TrilinearAlongSegment(f, uv::FrameParametric(frame, x0), uv::FrameParametric(frame, x1));
  for (double t : { 0.0, 0.3, 0.7, 1.0 })
    EXPECT_NEAR(cubic(t), TrueScalar(p, f, x0 + t * (x1 - x0)), 1e-13);
}

TEST(HexahedronRay, ExtremaAndNodeCrossings)
{
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 500; ++trial)
  {
    uv::Cubic f;
    for (double& c : f.c)
      c = u(random);
    // Extrema: f' changes sign exactly there (dense sampling finds the same count).
    const auto extrema = uv::CubicExtrema(f);
    int signChanges = 0;
    double previous = f.Derivative(0.0);
    for (int i = 1; i <= 20000; ++i)
    {
      const double d = f.Derivative(i / 20000.0);
      signChanges += (d > 0) != (previous > 0) ? 1 : 0;
      previous = d;
    }
    EXPECT_EQ(static_cast<int>(extrema.size()), signChanges);
    for (double e : extrema)
      EXPECT_NEAR(f.Derivative(e), 0.0, 1e-12);
    // Crossings: every split point between monotonic bounds hits its value.
    const std::vector<double> nodes = { -0.5, -0.1, 0.0, 0.2, 0.45, 0.9 };
    const auto cuts = uv::SplitPoints(f, nodes);
    EXPECT_TRUE(std::is_sorted(cuts.begin(), cuts.end()));
    for (double cut : cuts)
    {
      if (cut == 0.0 || cut == 1.0 || std::find(extrema.begin(), extrema.end(), cut) != extrema.end())
        continue;
      double nearest = 1e300;
      for (double v : nodes)
        nearest = std::min(nearest, std::abs(f(cut) - v));
      EXPECT_LT(nearest, 1e-13);
    }
    // And no crossing is missed: between consecutive cuts no node value is crossed.
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
    {
      const double fa = f(cuts[i]), fb = f(cuts[i + 1]);
      for (double v : nodes)
        EXPECT_FALSE(v > std::min(fa, fb) + 1e-12 && v < std::max(fa, fb) - 1e-12) << "missed " << v;
    }
  }
}

TEST(HexahedronRay, IntegrationModesAgainstTheReference)
{
  const uv::TransferFunction tf = Spiky();
  std::mt19937 random(8);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst[3] = { 0.0, 0.0, 0.0 };
  for (int trial = 0; trial < 300; ++trial)
  {
    uv::Cubic f;
    f.c = { 0.5 + 0.3 * (u(random) - 0.5), 1.2 * (u(random) - 0.5), 1.5 * (u(random) - 0.5), 1.5 * (u(random) - 0.5) };
    const double length = std::pow(10.0, -1.5 + 2.0 * u(random));
    uv::RayAccumulator reference;
    uv::IntegrateSegment(tf, [&](double t) { return f(t / length); }, 0.0, length, 1e-11, reference);
    const uv::HexahedronIntegration modes[3] = { uv::HexahedronIntegration::Accurate, uv::HexahedronIntegration::Fast,
      uv::HexahedronIntegration::FixedSteps };
    for (int m = 0; m < 3; ++m)
    {
      uv::RayAccumulator result;
      uv::IntegrateCubicSegment(tf, f, length, modes[m], result, 8);
      worst[m] = std::max({ worst[m], std::abs(result.Transmittance - reference.Transmittance),
        glm::length(result.Color - reference.Color) });
    }
  }
  std::printf("worst difference from the reference: accurate %.3g, fast %.3g, 8 fixed steps %.3g\n", worst[0],
    worst[1], worst[2]);
  EXPECT_LT(worst[0], 1e-9);
  EXPECT_GT(worst[1], 10.0 * worst[0]);
  EXPECT_GT(worst[2], worst[1]);
}

TEST(HexahedronRay, TwistedCellFrameErrorIsMeasured)
{
  // A cube whose top face is twisted by 10 degrees: the frame is no longer the cell's map; this
  // is the error the mapper's benchmark reports for curved cells.
  std::array<glm::dvec3, 8> p;
  const double angle = 10.0 * M_PI / 180.0;
  for (int k = 0; k < 8; ++k)
  {
    glm::dvec3 x = Corner(k) - glm::dvec3(0.5, 0.5, 0.0);
    const double a = x.z * angle;
    x = glm::dvec3(std::cos(a) * x.x - std::sin(a) * x.y, std::sin(a) * x.x + std::cos(a) * x.y, x.z);
    p[k] = x;
  }
  const double f[8] = { 0.0, 1.0, 0.5, 0.2, 0.8, 0.3, 0.9, 0.1 };
  const uv::HexahedronFrame frame = uv::MakeHexahedronFrame(p.data());
  const glm::dvec3 a(-0.3, -0.35, 0.02), b(0.3, 0.25, 0.97);
  const uv::Cubic cubic = uv::TrilinearAlongSegment(f, uv::FrameParametric(frame, a), uv::FrameParametric(frame, b));
  // The mapper's curved-cell route: the cubic through the exact field at the ends and at u = 1/4, 3/4.
  const uv::Cubic sampled = uv::CubicThroughSamples(TrueScalar(p, f, a),
    TrueScalar(p, f, a + uv::CurvedSampleNear * (b - a)), TrueScalar(p, f, a + uv::CurvedSampleFar * (b - a)),
    TrueScalar(p, f, b));
  double worst = 0.0, worstSampled = 0.0;
  for (int i = 0; i <= 20; ++i)
  {
    const double t = i / 20.0;
    const double exact = TrueScalar(p, f, a + t * (b - a));
    worst = std::max(worst, std::abs(cubic(t) - exact));
    worstSampled = std::max(worstSampled, std::abs(sampled(t) - exact));
  }
  std::printf("10-degree twisted cell: frame scalar off by at most %.3g, four exact samples' cubic by %.3g\n",
    worst, worstSampled);
  EXPECT_GT(worst, 1e-6); // not exact...
  EXPECT_LT(worst, 0.05); // ...but close for a mild twist
  EXPECT_LT(worstSampled, 0.1 * worst); // and the sampled cubic much closer
}

TEST(HexahedronRay, TangledCellsAreTold)
{
  std::mt19937 random(7);
  for (int trial = 0; trial < 50; ++trial)
  {
    std::array<glm::dvec3, 8> p = Parallelepiped(random);
    EXPECT_FALSE(uv::IsTangledHexahedron(p.data())); // valid, in either orientation
    std::swap(p[0], p[4]);
    std::swap(p[1], p[5]);
    std::swap(p[2], p[6]);
    std::swap(p[3], p[7]);
    EXPECT_FALSE(uv::IsTangledHexahedron(p.data())); // inverted as a whole: one sign
  }
  std::array<glm::dvec3, 8> cube;
  for (int k = 0; k < 8; ++k)
    cube[k] = Corner(k);
  // A corner pushed through the opposite face folds the cell.
  std::array<glm::dvec3, 8> folded = cube;
  folded[6] = glm::dvec3(0.3, 0.3, -0.5);
  EXPECT_TRUE(uv::IsTangledHexahedron(folded.data()));
  // A collapsed edge (a wedge as a hexahedron) has zero Jacobians, not both signs.
  std::array<glm::dvec3, 8> collapsed = cube;
  collapsed[5] = collapsed[4];
  collapsed[6] = collapsed[7];
  EXPECT_FALSE(uv::IsTangledHexahedron(collapsed.data()));
}
