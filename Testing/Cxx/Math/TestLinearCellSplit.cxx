// The VTK-free split rules: orientation, volume and face conformity for every ordering of global ids.
#include "uvLinearCellSplit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <set>
#include <vector>

namespace
{
using Point = std::array<double, 3>;

const std::array<Point, 8> UnitHexahedron = { { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
  { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } } };
// A valid VTK wedge: (0,1,2) faces away from (3,4,5).
const std::array<Point, 6> UnitWedge = { { { 0, 0, 0 }, { 0, 1, 0 }, { 1, 0, 0 }, { 0, 0, 1 },
  { 0, 1, 1 }, { 1, 0, 1 } } };
const std::array<Point, 5> UnitPyramid = { { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
  { 0.5, 0.5, 1 } } };

/// A regular n-gonal prism of unit circumradius and height, numbered as VTK's prisms.
template <std::size_t N>
std::array<Point, 2 * N> RegularPrism()
{
  std::array<Point, 2 * N> points;
  for (std::size_t i = 0; i < N; ++i)
  {
    const double angle = 2.0 * std::acos(-1.0) * i / N;
    points[i] = { std::cos(angle), std::sin(angle), 0.0 };
    points[N + i] = { std::cos(angle), std::sin(angle), 1.0 };
  }
  return points;
}

template <std::size_t N>
double RegularPrismVolume()
{
  return 0.5 * N * std::sin(2.0 * std::acos(-1.0) / N);
}

/// A sheared, scaled, rotated copy: splits must stay positive under any affine map of positive
/// determinant.
template <std::size_t N>
std::array<Point, N> Affine(const std::array<Point, N>& points)
{
  const double m[3][3] = { { 1.3, 0.4, -0.2 }, { -0.3, 0.9, 0.5 }, { 0.2, -0.1, 1.7 } };
  std::array<Point, N> out;
  for (std::size_t i = 0; i < N; ++i)
  {
    for (int r = 0; r < 3; ++r)
    {
      out[i][r] = 5.0 + m[r][0] * points[i][0] + m[r][1] * points[i][1] + m[r][2] * points[i][2];
    }
  }
  return out;
}

double Determinant()
{
  const double m[3][3] = { { 1.3, 0.4, -0.2 }, { -0.3, 0.9, 0.5 }, { 0.2, -0.1, 1.7 } };
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
    m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

/// Every polygonal face must appear in the tets as its fan from its smallest id, and no other
/// triangle of its vertices may appear (a quad cut along the other diagonal, say).
template <std::size_t NumFaces>
void ExpectFacesFannedFromMinimum(const std::array<uv::LocalFace, NumFaces>& faces, const int* ids,
  const int tets[][4], int count)
{
  std::set<std::set<int>> triangles;
  for (int t = 0; t < count; ++t)
  {
    for (int skip = 0; skip < 4; ++skip)
    {
      std::set<int> triangle;
      for (int v = 0; v < 4; ++v)
      {
        if (v != skip)
        {
          triangle.insert(tets[t][v]);
        }
      }
      triangles.insert(triangle);
    }
  }
  for (const uv::LocalFace& face : faces)
  {
    if (face.Size < 4)
    {
      continue;
    }
    const auto& f = face.Vertices;
    int lowest = 0;
    for (int i = 1; i < face.Size; ++i)
    {
      lowest = ids[f[i]] < ids[f[lowest]] ? i : lowest;
    }
    const std::set<int> vertices(f.begin(), f.begin() + face.Size);
    std::size_t fanned = 0, inFace = 0;
    for (int i = 1; i + 1 < face.Size; ++i)
    {
      fanned += triangles.count(
        { f[lowest], f[(lowest + i) % face.Size], f[(lowest + i + 1) % face.Size] });
    }
    for (const std::set<int>& triangle : triangles)
    {
      inFace += std::includes(vertices.begin(), vertices.end(), triangle.begin(), triangle.end()) ? 1 : 0;
    }
    EXPECT_EQ(fanned, static_cast<std::size_t>(face.Size - 2)) << "face not fanned from its smallest id";
    EXPECT_EQ(inFace, fanned) << "face cut by other triangles too";
  }
}

template <std::size_t N, std::size_t NumFaces, typename Split>
void CheckAllOrderings(const std::array<Point, N>& reference, double referenceVolume,
  const std::array<uv::LocalFace, NumFaces>& faces, int expectedTets, Split split)
{
  const std::array<Point, N> sheared = Affine(reference);
  std::array<int, N> ids;
  std::iota(ids.begin(), ids.end(), 0);
  // Every ordering up to 8 vertices; a fixed random sample of the 10! or 12! orderings of the prisms.
  const bool every = N <= 8;
  std::mt19937 random(N);
  int orderings = 0;
  do
  {
    if (!every)
    {
      std::shuffle(ids.begin(), ids.end(), random);
    }
    // Global ids are a permutation scaled and offset, as real meshes have.
    std::array<long long, N> globalIds;
    for (std::size_t i = 0; i < N; ++i)
    {
      globalIds[i] = 1000 + 7 * ids[i];
    }
    int tets[uv::MaxTetsPerCell][4];
    const int count = split(globalIds.data(), tets);
    ASSERT_EQ(count, expectedTets);
    double volume = 0.0, shearedVolume = 0.0;
    for (int t = 0; t < count; ++t)
    {
      const double six = uv::SixSignedVolume(
        reference[tets[t][0]], reference[tets[t][1]], reference[tets[t][2]], reference[tets[t][3]]);
      const double sixSheared = uv::SixSignedVolume(
        sheared[tets[t][0]], sheared[tets[t][1]], sheared[tets[t][2]], sheared[tets[t][3]]);
      EXPECT_GT(six, 1e-12) << "non-positive tet";
      EXPECT_GT(sixSheared, 1e-12) << "non-positive tet after an affine map";
      volume += six / 6.0;
      shearedVolume += sixSheared / 6.0;
    }
    EXPECT_NEAR(volume, referenceVolume, 1e-14);
    EXPECT_NEAR(shearedVolume, referenceVolume * Determinant(), 1e-12);
    ExpectFacesFannedFromMinimum(faces, ids.data(), tets, count);
    ++orderings;
  } while (every ? std::next_permutation(ids.begin(), ids.end()) : orderings < 3000);
  EXPECT_GT(orderings, 1);
}
} // namespace

TEST(LinearCellSplit, HexahedronEveryOrdering)
{
  CheckAllOrderings(UnitHexahedron, 1.0, uv::HexahedronFaces, 6,
    [](const long long* ids, int tets[][4]) { return uv::SplitHexahedron(ids, tets); });
}

TEST(LinearCellSplit, WedgeEveryOrdering)
{
  CheckAllOrderings(UnitWedge, 0.5, uv::WedgeFaces, 3,
    [](const long long* ids, int tets[][4]) { return uv::SplitWedge(ids, tets); });
}

TEST(LinearCellSplit, PyramidEveryOrdering)
{
  CheckAllOrderings(UnitPyramid, 1.0 / 3.0, uv::PyramidFaces, 2,
    [](const long long* ids, int tets[][4]) { return uv::SplitPyramid(ids, tets); });
}

TEST(LinearCellSplit, PentagonalPrismSampledOrderings)
{
  CheckAllOrderings(RegularPrism<5>(), RegularPrismVolume<5>(), uv::PentagonalPrismFaces, 9,
    [](const long long* ids, int tets[][4]) { return uv::SplitPentagonalPrism(ids, tets); });
}

TEST(LinearCellSplit, HexagonalPrismSampledOrderings)
{
  CheckAllOrderings(RegularPrism<6>(), RegularPrismVolume<6>(), uv::HexagonalPrismFaces, 12,
    [](const long long* ids, int tets[][4]) { return uv::SplitHexagonalPrism(ids, tets); });
}

TEST(LinearCellSplit, FacesAreOutward)
{
  // Each face's normal must point away from the cell centroid, or the combinatorial orientation
  // above would be inverted.
  auto check = [](const auto& points, const auto& faces) {
    Point centroid{ 0, 0, 0 };
    for (const Point& p : points)
    {
      for (int d = 0; d < 3; ++d)
      {
        centroid[d] += p[d] / points.size();
      }
    }
    for (const uv::LocalFace& face : faces)
    {
      const Point& a = points[face.Vertices[0]];
      const Point& b = points[face.Vertices[1]];
      const Point& c = points[face.Vertices[2]];
      EXPECT_LT(uv::SixSignedVolume(a, b, c, centroid), 0.0);
    }
  };
  check(UnitHexahedron, uv::HexahedronFaces);
  check(UnitWedge, uv::WedgeFaces);
  check(UnitPyramid, uv::PyramidFaces);
  check(RegularPrism<5>(), uv::PentagonalPrismFaces);
  check(RegularPrism<6>(), uv::HexagonalPrismFaces);
}

TEST(LinearCellSplit, FiveTetrahedraBothParities)
{
  for (bool odd : { false, true })
  {
    const int(*tets)[4] = uv::FiveTetSplit(odd);
    double volume = 0.0;
    for (int t = 0; t < 5; ++t)
    {
      const double six = uv::SixSignedVolume(UnitHexahedron[tets[t][0]], UnitHexahedron[tets[t][1]],
        UnitHexahedron[tets[t][2]], UnitHexahedron[tets[t][3]]);
      EXPECT_GT(six, 0.0);
      volume += six / 6.0;
    }
    EXPECT_NEAR(volume, 1.0, 1e-15);
    // The central tet holds the four corners of even global parity.
    for (int v = 0; v < 4; ++v)
    {
      const Point& corner = UnitHexahedron[tets[0][v]];
      const int parity = (static_cast<int>(corner[0] + corner[1] + corner[2]) + (odd ? 1 : 0)) % 2;
      EXPECT_EQ(parity, 0);
    }
  }
}

TEST(LinearCellSplit, FiveTetrahedraNeighboursShareDiagonals)
{
  // Two cells side by side along x with opposite parity must cut their shared face alike.
  auto diagonalsOnFace = [](bool odd, int faceX) {
    std::set<std::set<int>> edges; // edges given as global (x, y, z) codes x*100 + y*10 + z
    const int(*tets)[4] = uv::FiveTetSplit(odd);
    for (int t = 0; t < 5; ++t)
    {
      for (int a = 0; a < 4; ++a)
      {
        for (int b = a + 1; b < 4; ++b)
        {
          const Point& p = UnitHexahedron[tets[t][a]];
          const Point& q = UnitHexahedron[tets[t][b]];
          if (p[0] == faceX && q[0] == faceX && p[1] != q[1] && p[2] != q[2])
          {
            const int shift = faceX == 1 ? 0 : 1; // global x of this face is 1 for both cells
            edges.insert({ static_cast<int>((p[0] + shift) * 100 + p[1] * 10 + p[2]),
              static_cast<int>((q[0] + shift) * 100 + q[1] * 10 + q[2]) });
          }
        }
      }
    }
    return edges;
  };
  EXPECT_EQ(diagonalsOnFace(false, 1), diagonalsOnFace(true, 0));
  EXPECT_EQ(diagonalsOnFace(false, 1).size(), 1u);
}
