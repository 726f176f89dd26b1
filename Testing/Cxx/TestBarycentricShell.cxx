// The barycentric shell mapper's math (uvBarycentricShell.h) against direct computations: signed
// volumes in long double for the coordinates and the inside test, bisection for isovalue crossings;
// in double, then in float (what a shader computes), on random and nearly flat tetrahedra.
#include "uvBarycentricShell.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <limits>
#include <random>

namespace
{
using LongVec = std::array<long double, 3>;

long double Det3(const LongVec& a, const LongVec& b, const LongVec& c)
{
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/// Barycentric coordinates by signed volumes: b_i is the volume with x in place of v_i over the whole.
std::array<long double, 4> DirectBarycentric(const glm::dvec3 v[4], const glm::dvec3& x)
{
  auto diff = [](const glm::dvec3& p, const glm::dvec3& q) {
    return LongVec{ static_cast<long double>(p.x) - q.x, static_cast<long double>(p.y) - q.y,
      static_cast<long double>(p.z) - q.z };
  };
  auto volume = [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
    return Det3(diff(b, a), diff(c, a), diff(d, a));
  };
  const long double whole = volume(v[0], v[1], v[2], v[3]);
  return { volume(x, v[1], v[2], v[3]) / whole, volume(v[0], x, v[2], v[3]) / whole,
    volume(v[0], v[1], x, v[3]) / whole, volume(v[0], v[1], v[2], x) / whole };
}

/// A tetrahedron in front of the eye (eye space: looking down -z), about `size` across; `flatness`
/// is the fourth vertex's height over the others' plane relative to `size` (1: a regular shape).
std::array<glm::dvec3, 4> RandomTetrahedron(std::mt19937& random, double size, double flatness)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const glm::dvec3 centre(3.0 * u(random), 3.0 * u(random), -8.0 + 2.0 * u(random));
  std::array<glm::dvec3, 4> v;
  for (int k = 0; k < 3; ++k)
  {
    v[k] = centre + size * glm::dvec3(u(random), u(random), 0.3 * u(random));
  }
  const glm::dvec3 normal = glm::normalize(glm::cross(v[1] - v[0], v[2] - v[0]));
  const glm::dvec3 middle = (v[0] + v[1] + v[2]) / 3.0;
  glm::dvec3 offset = 0.3 * size * glm::dvec3(u(random), u(random), u(random));
  offset -= glm::dot(offset, normal) * normal; // in the base's plane
  v[3] = middle + offset + flatness * size * normal;
  return v;
}

/// How many units of rounding the coordinates may lose: the edge matrix's condition number times
/// the eye's distance in edge lengths (the coordinates of the eye and of far points grow with it).
double Conditioning(const std::array<glm::dvec3, 4>& v)
{
  const glm::dmat3 edges(v[1] - v[0], v[2] - v[0], v[3] - v[0]);
  const glm::dmat3 inverse = glm::inverse(edges);
  auto norm = [](const glm::dmat3& m) {
    return std::sqrt(glm::dot(m[0], m[0]) + glm::dot(m[1], m[1]) + glm::dot(m[2], m[2]));
  };
  const double scale = std::max({ glm::length(edges[0]), glm::length(edges[1]), glm::length(edges[2]) });
  return norm(edges) * norm(inverse) * (1.0 + glm::length(v[0]) / scale);
}

uv::BarycentricTetrahedron<float> AsFloat(const std::array<glm::dvec3, 4>& v)
{
  const glm::vec3 f[4] = { glm::vec3(v[0]), glm::vec3(v[1]), glm::vec3(v[2]), glm::vec3(v[3]) };
  return uv::MakeBarycentricTetrahedron(f);
}

/// The largest coordinate error, relative to the coordinates' size where they exceed 1 (far outside
/// a flat tetrahedron they are huge, and so is any rounding of them).
double MaxDifference(const glm::dvec4& b, const std::array<long double, 4>& direct)
{
  double worst = 0.0, size = 1.0;
  for (int i = 0; i < 4; ++i)
  {
    worst = std::max(worst, static_cast<double>(std::abs(b[i] - direct[i])));
    size = std::max(size, static_cast<double>(std::abs(direct[i])));
  }
  return worst / size;
}
} // namespace

TEST(BarycentricShell, CoordinatesMatchSignedVolumes)
{
  // Bound: the error in units of the precision's epsilon, over the tetrahedron's conditioning
  // (Conditioning above), stays below a constant, for regular, flat and nearly degenerate
  // tetrahedra alike: the formulation is backward stable in double and in float.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double epsilonDouble = std::numeric_limits<double>::epsilon();
  const double epsilonFloat = std::numeric_limits<float>::epsilon();
  for (double flatness : { 1.0, 1e-3, 1e-6 })
  {
    double worstDouble = 0.0, worstFloat = 0.0, relativeDouble = 0.0, relativeFloat = 0.0;
    for (int trial = 0; trial < 200; ++trial)
    {
      const auto v = RandomTetrahedron(random, 1.0, flatness);
      const auto tet = uv::MakeBarycentricTetrahedron(v.data());
      ASSERT_TRUE(tet.Valid);
      const auto tetFloat = AsFloat(v);
      const double conditioning = Conditioning(v);
      for (int k = 0; k < 10; ++k)
      {
        const glm::dvec3 x = 0.25 * (v[0] + v[1] + v[2] + v[3]) + 0.8 * glm::dvec3(u(random), u(random), u(random));
        const auto direct = DirectBarycentric(v.data(), x);
        const double error = MaxDifference(uv::BarycentricOf(tet, x), direct);
        worstDouble = std::max(worstDouble, error);
        relativeDouble = std::max(relativeDouble, error / (conditioning * epsilonDouble));
        if (tetFloat.Valid) // a tetrahedron flat to float precision is told, not used
        {
          const double errorFloat = MaxDifference(glm::dvec4(uv::BarycentricOf(tetFloat, glm::vec3(x))), direct);
          worstFloat = std::max(worstFloat, errorFloat);
          relativeFloat = std::max(relativeFloat, errorFloat / (conditioning * epsilonFloat));
        }
      }
    }
    std::printf("flatness %.0e: largest coordinate error %.2e (double, %.2f conditioning epsilons), "
                "%.2e (float, %.2f)\n", flatness, worstDouble, relativeDouble, worstFloat, relativeFloat);
    EXPECT_LT(relativeDouble, 8.0);
    EXPECT_LT(relativeFloat, 8.0);
  }
  // A flat tetrahedron has no inverse and says so.
  const glm::dvec3 flat[4] = { { 0, 0, -5 }, { 1, 0, -5 }, { 0, 1, -5 }, { 1, 1, -5 } };
  EXPECT_FALSE(uv::MakeBarycentricTetrahedron(flat).Valid);
}

TEST(BarycentricShell, InsideTestAgreesWithSignedVolumes)
{
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0, checkedFloat = 0;
  for (int trial = 0; trial < 300; ++trial)
  {
    const auto v = RandomTetrahedron(random, 1.0, trial % 3 == 0 ? 1e-2 : 1.0);
    const auto tet = uv::MakeBarycentricTetrahedron(v.data());
    const auto tetFloat = AsFloat(v);
    for (int k = 0; k < 20; ++k)
    {
      const glm::dvec3 x = 0.25 * (v[0] + v[1] + v[2] + v[3]) + 0.6 * glm::dvec3(u(random), u(random), u(random));
      const auto direct = DirectBarycentric(v.data(), x);
      const long double margin = std::min({ direct[0], direct[1], direct[2], direct[3] });
      const bool inside = margin >= 0;
      // Points within rounding of a face may go either way; everything else must agree.
      if (std::abs(margin) > 1e-10)
      {
        EXPECT_EQ(uv::InsideBarycentric(uv::BarycentricOf(tet, x)), inside);
        ++checked;
      }
      if (std::abs(margin) > 1e-3)
      {
        EXPECT_EQ(uv::InsideBarycentric(uv::BarycentricOf(tetFloat, glm::vec3(x))), inside);
        ++checkedFloat;
      }
    }
  }
  EXPECT_GT(checked, 5000);
  EXPECT_GT(checkedFloat, 4000);
}

TEST(BarycentricShell, ShellSamplesFollowTheRay)
{
  // The vertex attributes e_i - b_eye interpolate across a face to the fragment's direction
  // attribute; with l = |x| the shell samples b_eye + z b / l are the coordinates of the ray's point
  // at distance z, inside exactly where the ray is in the tetrahedron.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0, worstFloat = 0.0, relativeFloat = 0.0, worstFace = 0.0, relativeFace = 0.0;
  for (int trial = 0; trial < 200; ++trial)
  {
    const auto v = RandomTetrahedron(random, 1.0, 1.0);
    const auto tet = uv::MakeBarycentricTetrahedron(v.data());
    const auto tetFloat = AsFloat(v);
    const double conditioning = Conditioning(v);
    for (int i = 0; i < 4; ++i)
    {
      glm::dvec4 expected = -tet.Eye;
      expected[i] += 1.0;
      EXPECT_LT(glm::length(uv::BarycentricDirection(tet, v[i]) - expected), 1e-12);
    }
    // A point on face (0, 1, 2) and its attribute interpolated from the vertices' (the weights of a
    // perspective-correct interpolation are the point's own weights).
    double w0 = unit(random), w1 = unit(random) * (1.0 - w0);
    const double w2 = 1.0 - w0 - w1;
    const glm::dvec3 x = w0 * v[0] + w1 * v[1] + w2 * v[2];
    const glm::dvec4 direction = w0 * uv::BarycentricDirection(tet, v[0]) + w1 * uv::BarycentricDirection(tet, v[1]) +
      w2 * uv::BarycentricDirection(tet, v[2]);
    const double length = glm::length(x);
    const glm::vec4 directionFloat(direction);
    const glm::vec4 faceFloat(static_cast<float>(w0), static_cast<float>(w1), static_cast<float>(w2), 0.0f);
    for (int k = 0; k <= 16; ++k)
    {
      const double z = length + 0.2 * k;
      const auto direct = DirectBarycentric(v.data(), x * (z / length));
      worst = std::max(worst, MaxDifference(uv::ShellSample(tet.Eye, direction, length, z), direct));
      const double errorFloat = MaxDifference(glm::dvec4(uv::ShellSample(tetFloat.Eye, directionFloat,
                                                static_cast<float>(length), static_cast<float>(z))),
        direct);
      worstFloat = std::max(worstFloat, errorFloat);
      relativeFloat = std::max(relativeFloat, errorFloat / (conditioning * std::numeric_limits<float>::epsilon()));
      const double errorFace = MaxDifference(glm::dvec4(uv::ShellSampleFromFace(faceFloat, directionFloat,
                                               static_cast<float>(length), static_cast<float>(z))),
        direct);
      worstFace = std::max(worstFace, errorFace);
      relativeFace = std::max(relativeFace, errorFace / (conditioning * std::numeric_limits<float>::epsilon()));
    }
  }
  std::printf("shell samples: largest coordinate error %.2e (double); float: %.2e from the eye's coordinates "
              "(%.2f conditioning epsilons), %.2e from the face's (%.2f)\n",
    worst, worstFloat, relativeFloat, worstFace, relativeFace);
  EXPECT_LT(worst, 1e-11);
  EXPECT_LT(relativeFloat, 32.0);
  EXPECT_LT(relativeFace, 4.0);
  EXPECT_LT(worstFace, 0.25 * worstFloat); // the face's form is the one for float
}

TEST(BarycentricShell, IsovalueDistanceAgainstRootFinding)
{
  std::mt19937 random(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0, worstFloat = 0.0, worstFace = 0.0;
  int found = 0;
  for (int trial = 0; trial < 300; ++trial)
  {
    const auto v = RandomTetrahedron(random, 1.0, 1.0);
    const auto tet = uv::MakeBarycentricTetrahedron(v.data());
    const auto tetFloat = AsFloat(v);
    const glm::dvec4 scalars(unit(random), unit(random), unit(random), unit(random));
    // The ray through the centroid: inside between where it enters and leaves.
    const glm::dvec3 centre = 0.25 * (v[0] + v[1] + v[2] + v[3]);
    const double length = glm::length(centre);
    auto field = [&](double z) {
      const auto b = DirectBarycentric(v.data(), centre * (z / length));
      long double f = 0;
      for (int i = 0; i < 4; ++i)
        f += b[i] * scalars[i];
      return f;
    };
    const double isovalue = static_cast<double>(field(length)) + 0.05 * (unit(random) - 0.5);
    // Bisection in long double over a bracket around the centroid.
    double low = length - 0.5, high = length + 0.5;
    if ((field(low) - isovalue) * (field(high) - isovalue) > 0)
      continue;
    for (int iteration = 0; iteration < 200; ++iteration)
    {
      const double middle = 0.5 * (low + high);
      if ((field(low) - isovalue) * (field(middle) - isovalue) <= 0)
        high = middle;
      else
        low = middle;
    }
    const double root = 0.5 * (low + high);
    const glm::dvec4 perUnit = uv::BarycentricDirection(tet, centre) / length;
    const double z = uv::IsovalueDistance(tet.Eye, perUnit, scalars, isovalue);
    const glm::vec4 perUnitFloat = glm::vec4(uv::BarycentricDirection(tetFloat, glm::vec3(centre))) / static_cast<float>(length);
    const float zFloat = uv::IsovalueDistance(tetFloat.Eye, perUnitFloat, glm::vec4(scalars), static_cast<float>(isovalue));
    // From the face: the centroid ray's entry is not needed; any point on the ray with its exact
    // coordinates serves, here the centroid itself (coordinates 1/4).
    const float zFace = uv::IsovalueDistanceFromFace(glm::vec4(0.25f), perUnitFloat, static_cast<float>(length),
      glm::vec4(scalars), static_cast<float>(isovalue));
    worst = std::max(worst, std::abs(z - root));
    worstFloat = std::max(worstFloat, std::abs(static_cast<double>(zFloat) - root));
    worstFace = std::max(worstFace, std::abs(static_cast<double>(zFace) - root));
    ++found;
  }
  std::printf("isovalue distance: %d crossings, largest error %.2e (double); float %.2e from the eye's "
              "coordinates, %.2e from the face's\n", found, worst, worstFloat, worstFace);
  EXPECT_GT(found, 100);
  EXPECT_LT(worst, 1e-10);
  EXPECT_LT(worstFloat, 1e-4);
  EXPECT_LT(worstFace, 1e-5);
  // A field constant along the ray has no crossing.
  EXPECT_TRUE(std::isnan(uv::IsovalueDistance(glm::dvec4(0.25), glm::dvec4(0.1, -0.1, 0.0, 0.0), glm::dvec4(1.0), 0.5)));
}
