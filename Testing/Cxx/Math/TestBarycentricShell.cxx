// The barycentric shell mapper's math (uvBarycentricShell.h) against direct computations: signed
// volumes in long double for the coordinates and the inside test, bisection for isovalue crossings;
// in double, then in float (what a shader computes), on random and nearly flat tetrahedra. Then its
// per-frame bucketing (uvShellBuckets.h): distance ranges against points inside the tetrahedra, and
// which cells each shell holds against a brute-force assignment.
#include "uvBarycentricShell.h"
#include "uvShellBuckets.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

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

namespace
{
/// Random ranges [low, high] for `count` cells with ids id0, id0 + 2, ... (not their places), between
/// `near` and `far`, some of them of zero length.
uv::RangedCells RandomRanges(std::mt19937& random, std::vector<std::uint32_t>& ids, std::size_t count,
  std::uint32_t id0, float near, float far)
{
  std::uniform_real_distribution<float> where(near, far), length(0.0f, 0.2f * (far - near));
  uv::RangedCells cells;
  ids.clear();
  for (std::size_t i = 0; i < count; ++i)
  {
    ids.push_back(id0 + 2 * static_cast<std::uint32_t>(i));
    const float low = where(random);
    cells.Low.push_back(low);
    cells.High.push_back(i % 7 == 0 ? low : low + length(random));
  }
  cells.Ids = &ids;
  return cells;
}

/// A deterministic box per cell id, so the expected shell boxes can be built independently.
uv::ScreenBox BoxOf(std::uint32_t id)
{
  const double x = std::fmod(0.37 * id, 1.7) - 0.9, y = std::fmod(0.61 * id, 1.5) - 0.8;
  return uv::ScreenBox(x, y, x + 0.05 * (id % 5), y + 0.03 * (id % 3));
}

/// True when the padded range [low - slack, high + slack] reaches into shell s, whose extent is
/// [Start, Start + Thickness) (the first and last extended to infinity: ranges are clamped there).
bool Overlaps(const uv::ShellLayout& layout, float low, float high, int s)
{
  const double begin = s == 0 ? -std::numeric_limits<double>::infinity() : layout.First + s * layout.Thickness;
  const double end =
    s + 1 == layout.Count ? std::numeric_limits<double>::infinity() : layout.First + (s + 1) * layout.Thickness;
  return static_cast<double>(low - layout.Slack()) < end && static_cast<double>(high + layout.Slack()) >= begin;
}

/// Buckets against a brute-force assignment of every cell to every shell: the same cells in list
/// order, the same isosurface flags and boxes, every range covered by the shells.
void CheckAgainstBruteForce(const uv::ShellLayout& layout, const uv::RangedCells& volume,
  const uv::RangedCells& isosurface, const uv::ShellBuckets& buckets)
{
  ASSERT_EQ(buckets.Count(), layout.Count);
  ASSERT_EQ(buckets.Offsets.size(), static_cast<std::size_t>(layout.Count + 1));
  int skipped = 0;
  for (int s = 0; s < layout.Count; ++s)
  {
    std::vector<std::uint32_t> expected;
    uv::ScreenBox box = uv::EmptyScreenBox();
    for (std::size_t i = 0; i < volume.Size(); ++i)
      if (Overlaps(layout, volume.Low[i], volume.High[i], s))
      {
        expected.push_back((*volume.Ids)[i]);
        box = uv::UniteScreenBoxes(box, BoxOf((*volume.Ids)[i]));
      }
    bool iso = false;
    for (std::size_t i = 0; i < isosurface.Size(); ++i)
      if (Overlaps(layout, isosurface.Low[i], isosurface.High[i], s))
      {
        iso = true;
        box = uv::UniteScreenBoxes(box, BoxOf((*isosurface.Ids)[i]));
      }
    const std::vector<std::uint32_t> got(
      buckets.Cells.begin() + buckets.Offsets[s], buckets.Cells.begin() + buckets.Offsets[s + 1]);
    EXPECT_EQ(got, expected) << "shell " << s;
    EXPECT_EQ(buckets.HasIsosurface[s] != 0, iso) << "shell " << s;
    EXPECT_EQ(buckets.Screen[s], box) << "shell " << s;
    EXPECT_EQ(buckets.IsEmpty(s), expected.empty() && !iso);
    skipped += expected.empty() && !iso ? 1 : 0;
  }
  EXPECT_EQ(buckets.SkippedShells(), skipped);
  // The shells start at a whole multiple of the sample distance before the nearest range and reach
  // past the farthest.
  for (const uv::RangedCells* cells : { &volume, &isosurface })
    for (std::size_t i = 0; i < cells->Size(); ++i)
    {
      EXPECT_GE(cells->Low[i], layout.First);
      EXPECT_LE(cells->High[i], layout.First + layout.Count * layout.Thickness + 1e-6 * layout.Thickness);
    }
  const double multiple = layout.First / layout.SampleDistance;
  EXPECT_NEAR(multiple, std::round(multiple), 1e-6 * std::max(1.0, std::abs(multiple)));
}
} // namespace

TEST(ShellBuckets, DistanceRangesHoldEveryPointOfTheTetrahedron)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int trial = 0; trial < 300; ++trial)
  {
    const bool parallel = trial % 2 == 1;
    // Most in front of the eye; a few around it (the eye inside, or beside, the tetrahedron).
    const bool aroundEye = trial % 10 == 0;
    const std::array<glm::dvec3, 4> d = RandomTetrahedron(random, aroundEye ? 2.0 : 0.5, 1.0);
    std::array<glm::vec3, 4> v;
    for (int k = 0; k < 4; ++k)
      v[k] = glm::vec3(aroundEye ? d[k] - glm::dvec3(0.0, 0.0, -8.0) : d[k]);
    float low = 0.0f, high = 0.0f;
    uv::TetrahedronDistanceRange(v, parallel, low, high);
    float nearestVertex = std::numeric_limits<float>::infinity(), farthestVertex = -nearestVertex;
    for (const glm::vec3& p : v)
    {
      nearestVertex = std::min(nearestVertex, parallel ? -p.z : glm::length(p));
      farthestVertex = std::max(farthestVertex, parallel ? -p.z : glm::length(p));
    }
    EXPECT_FLOAT_EQ(high, farthestVertex); // the maximum, attained at a vertex
    if (parallel)
      EXPECT_FLOAT_EQ(low, nearestVertex); // depth is linear: exact at a vertex too
    for (int sample = 0; sample < 54; ++sample)
    {
      // The vertices first, then random points inside.
      glm::vec4 w(sample == 0, sample == 1, sample == 2, sample == 3);
      if (sample >= 4)
        w = glm::vec4(u(random), u(random), u(random), u(random));
      w /= w.x + w.y + w.z + w.w;
      const glm::vec3 x = w.x * v[0] + w.y * v[1] + w.z * v[2] + w.w * v[3];
      const float distance = parallel ? -x.z : glm::length(x);
      const float tolerance = 1e-5f * std::max(1.0f, high);
      EXPECT_LE(low, distance + tolerance);
      EXPECT_LE(distance, high + tolerance);
    }
  }
}

TEST(ShellBuckets, MatchBruteForceOnRandomRanges)
{
  std::mt19937 random(11);
  std::uniform_int_distribution<int> slices(3, 31), counts(0, 400);
  std::uniform_real_distribution<double> distances(0.001, 0.2);
  int checked = 0;
  for (int trial = 0; trial < 60; ++trial)
  {
    std::vector<std::uint32_t> volumeIds, isoIds;
    const float near = trial % 3 == 0 ? 0.0f : 0.5f + trial;
    const uv::RangedCells volume = RandomRanges(random, volumeIds, counts(random), 0, near, near + 3.0f);
    const uv::RangedCells isosurface =
      RandomRanges(random, isoIds, trial % 4 == 0 ? 0 : counts(random) / 4, 1, near, near + 3.0f);
    uv::ShellLayout layout;
    const bool any = uv::LayoutShells(volume, isosurface, distances(random), slices(random), 4096, layout);
    ASSERT_EQ(any, volume.Size() + isosurface.Size() > 0);
    if (!any)
      continue;
    EXPECT_FALSE(layout.Widened);
    uv::ShellBuckets buckets;
    buckets.Update(layout, volume, isosurface, BoxOf);
    CheckAgainstBruteForce(layout, volume, isosurface, buckets);
    EXPECT_EQ(buckets.Version, 1u);
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

TEST(ShellBuckets, ShellsBetweenClustersAreEmptyAndSkipped)
{
  // Volume cells near 1 and far at 20, an isosurface cell alone at 10: only the shells between the
  // clusters and away from the isosurface hold nothing.
  std::vector<std::uint32_t> volumeIds = { 3, 4, 5, 6 }, isoIds = { 9 };
  uv::RangedCells volume, isosurface;
  volume.Ids = &volumeIds;
  volume.Low = { 1.0f, 1.1f, 20.0f, 20.2f };
  volume.High = { 1.3f, 1.2f, 20.4f, 20.3f };
  isosurface.Ids = &isoIds;
  isosurface.Low = { 10.0f };
  isosurface.High = { 10.05f };
  uv::ShellLayout layout;
  ASSERT_TRUE(uv::LayoutShells(volume, isosurface, 0.1, 5, 4096, layout));
  EXPECT_DOUBLE_EQ(layout.First, 1.0);
  uv::ShellBuckets buckets;
  buckets.Update(layout, volume, isosurface, BoxOf);
  CheckAgainstBruteForce(layout, volume, isosurface, buckets);
  const int isoShell = layout.ShellOf(10.0f);
  EXPECT_FALSE(buckets.IsEmpty(isoShell)); // an isosurface alone keeps its shell
  EXPECT_EQ(buckets.CellCount(isoShell), 0u);
  EXPECT_TRUE(buckets.IsEmpty(isoShell - 2));
  EXPECT_TRUE(buckets.IsEmpty(isoShell + 2));
  EXPECT_GT(buckets.SkippedShells(), buckets.Count() / 2);
  EXPECT_EQ(buckets.Screen[isoShell], BoxOf(9));
  EXPECT_EQ(buckets.Screen[isoShell - 2], uv::EmptyScreenBox());
}

TEST(ShellBuckets, EdgeCases)
{
  std::vector<std::uint32_t> none, one = { 42 };
  uv::RangedCells empty, single;
  empty.Ids = &none;
  uv::ShellLayout layout;
  EXPECT_FALSE(uv::LayoutShells(empty, empty, 0.1, 7, 4096, layout)); // nothing to draw
  EXPECT_EQ(layout.Count, 0);

  // A point-like range on a whole multiple of the sample distance: one shell starting there.
  single.Ids = &one;
  single.Low = single.High = { 0.5f };
  ASSERT_TRUE(uv::LayoutShells(single, empty, 0.25, 7, 4096, layout));
  EXPECT_DOUBLE_EQ(layout.First, 0.5);
  EXPECT_EQ(layout.Count, 1);
  uv::ShellBuckets buckets;
  buckets.Update(layout, single, empty, BoxOf);
  CheckAgainstBruteForce(layout, single, empty, buckets);
  EXPECT_EQ(buckets.Cells, one);

  // At the eye (distance 0) and on a shell boundary: the slack puts it into both shells it touches.
  single.Low = { 0.0f };
  single.High = { 0.7f };
  ASSERT_TRUE(uv::LayoutShells(single, empty, 0.1, 7, 4096, layout));
  EXPECT_EQ(layout.First, 0.0);
  EXPECT_EQ(layout.Count, 1);
  single.High = { 1.5f };
  ASSERT_TRUE(uv::LayoutShells(single, empty, 0.1, 5, 4096, layout));
  EXPECT_EQ(layout.Count, 3);
  single.Low = { 0.5f };
  single.High = { 0.5f }; // exactly where shell 1 begins
  buckets.Update(layout, single, empty, BoxOf);
  EXPECT_EQ(buckets.CellCount(0), 1u);
  EXPECT_EQ(buckets.CellCount(1), 1u);
  EXPECT_EQ(buckets.CellCount(2), 0u);
  EXPECT_EQ(buckets.Version, 2u);

  // More shells than allowed: the sample distance is widened and the count capped.
  std::vector<std::uint32_t> two = { 1, 2 };
  uv::RangedCells wide;
  wide.Ids = &two;
  wide.Low = { 1.0f, 500.0f };
  wide.High = { 2.0f, 1000.0f };
  ASSERT_TRUE(uv::LayoutShells(wide, empty, 1e-3, 7, 64, layout));
  EXPECT_TRUE(layout.Widened);
  EXPECT_GT(layout.SampleDistance, 1e-3);
  EXPECT_LE(layout.Count, 64);
  EXPECT_NEAR(layout.Thickness, 7 * layout.SampleDistance, 1e-9 * layout.Thickness);
  buckets.Update(layout, wide, empty, BoxOf);
  CheckAgainstBruteForce(layout, wide, empty, buckets);
}

TEST(ShellBuckets, ScreenBoxesAndPixelRectangles)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<glm::vec2> points = { { -0.5f, -0.25f }, { 0.5f, 0.0f }, { 0.0f, 0.75f }, { 0.1f, 0.1f },
    { nan, nan } };
  const std::vector<std::uint32_t> tetrahedra = { 0, 1, 2, 3, 0, 1, 2, 4 };
  EXPECT_EQ(uv::TetrahedronScreenBox(tetrahedra, 0, points), uv::ScreenBox(-0.5, -0.25, 0.5, 0.75));
  EXPECT_EQ(uv::TetrahedronScreenBox(tetrahedra, 1, points), uv::WholeScreenBox()); // a point behind the eye

  // A pixel of margin, clamped to the viewport; an empty box covers nothing.
  EXPECT_EQ(uv::ScreenBoxPixels(uv::WholeScreenBox(), 100, 50), (uv::PixelRectangle{ 0, 0, 100, 50 }));
  EXPECT_EQ(uv::ScreenBoxPixels(uv::ScreenBox(-3.0, -3.0, 5.0, 5.0), 100, 50), (uv::PixelRectangle{ 0, 0, 100, 50 }));
  EXPECT_EQ(uv::ScreenBoxPixels(uv::ScreenBox(0.0, 0.0, 0.5, 0.5), 100, 50), (uv::PixelRectangle{ 49, 24, 27, 15 }));
  const uv::PixelRectangle none = uv::ScreenBoxPixels(uv::EmptyScreenBox(), 100, 50);
  EXPECT_EQ(none[2] * none[3], 0);
  const uv::PixelRectangle outside = uv::ScreenBoxPixels(uv::ScreenBox(2.0, 2.0, 3.0, 3.0), 100, 50);
  EXPECT_EQ(outside[2] * outside[3], 0);

  EXPECT_EQ(uv::IntersectPixels({ 0, 0, 10, 10 }, { 5, 2, 10, 3 }), (uv::PixelRectangle{ 5, 2, 5, 3 }));
  const uv::PixelRectangle apart = uv::IntersectPixels({ 0, 0, 10, 10 }, { 20, 20, 5, 5 });
  EXPECT_EQ(apart[2], 0);
  EXPECT_EQ(apart[3], 0);

  // A box in front of a perspective eye covers part of the screen; one the eye is inside covers all.
  const glm::dmat4 clip = glm::dmat4(1.0 / std::tan(0.25), 0, 0, 0, 0, 1.0 / std::tan(0.25), 0, 0, 0, 0, -1.0, -1.0,
    0, 0, -0.2, 0.0); // columns: a perspective projection, eye looking down -z
  const double front[6] = { -0.1, 0.1, -0.1, 0.1, -5.0, -4.0 }, around[6] = { -1.0, 1.0, -1.0, 1.0, -1.0, 1.0 };
  const uv::PixelRectangle part = uv::BoundsPixels(front, clip, 200, 200);
  EXPECT_GT(part[2], 0);
  EXPECT_LT(part[2], 200);
  EXPECT_EQ(uv::BoundsPixels(around, clip, 200, 200), (uv::PixelRectangle{ 0, 0, 200, 200 }));
}
