// The VTK-free polyhedron split: the same tets as the fixed cell types for convex cells, a centre
// point for non-convex ones, conformity across shared polygonal faces, and every kind of bad input.
#include "uvPolyhedronSplit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <vector>

namespace
{
using Point = std::array<double, 3>;
using Face = std::vector<long long>;
using Split = uv::PolyhedronSplit<long long>;

struct Polyhedron
{
  std::vector<Point> Points; // indexed by global id
  std::vector<Face> Faces;   // global ids
};

std::vector<long long> Stream(const std::vector<Face>& faces)
{
  std::vector<long long> stream = { static_cast<long long>(faces.size()) };
  for (const Face& face : faces)
  {
    stream.push_back(static_cast<long long>(face.size()));
    stream.insert(stream.end(), face.begin(), face.end());
  }
  return stream;
}

Split SplitOf(const Polyhedron& cell)
{
  const std::vector<long long> stream = Stream(cell.Faces);
  return uv::SplitPolyhedron(stream.data(), stream.size(), static_cast<long long>(cell.Points.size()),
    [&](long long id) { return cell.Points[static_cast<std::size_t>(id)]; });
}

Point Coordinates(const Polyhedron& cell, const Split& split, long long id)
{
  return id == Split::CentreId ? split.Centre : cell.Points[static_cast<std::size_t>(id)];
}

/// Every tet positive; returns the total volume.
double ExpectPositive(const Polyhedron& cell, const Split& split)
{
  double volume = 0.0;
  for (const auto& tet : split.Tets)
  {
    const double six = uv::SixSignedVolume(Coordinates(cell, split, tet[0]), Coordinates(cell, split, tet[1]),
      Coordinates(cell, split, tet[2]), Coordinates(cell, split, tet[3]));
    EXPECT_GT(six, 0.0) << "non-positive tet";
    volume += six / 6.0;
  }
  return volume;
}

/// Volume by the divergence theorem over the faces, oriented outwards by the caller.
double FaceVolume(const Polyhedron& cell)
{
  double six = 0.0;
  for (const Face& face : cell.Faces)
  {
    for (std::size_t i = 1; i + 1 < face.size(); ++i)
    {
      six += uv::SixSignedVolume(Point{ 0, 0, 0 }, cell.Points[face[0]], cell.Points[face[i]],
        cell.Points[face[i + 1]]);
    }
  }
  return six / 6.0;
}

/// Tets as sets of point ids (orientation is checked separately).
std::set<std::set<long long>> TetSet(const std::vector<std::array<long long, 4>>& tets)
{
  std::set<std::set<long long>> out;
  for (const auto& tet : tets)
  {
    out.insert(std::set<long long>(tet.begin(), tet.end()));
  }
  return out;
}

/// The triangles of the tets that lie in the given face (all three corners among its vertices).
std::set<std::set<long long>> TrianglesOnFace(const Split& split, const Face& face)
{
  std::set<std::set<long long>> out;
  const std::set<long long> vertices(face.begin(), face.end());
  for (const auto& tet : split.Tets)
  {
    for (int skip = 0; skip < 4; ++skip)
    {
      std::set<long long> triangle;
      for (int v = 0; v < 4; ++v)
      {
        if (v != skip)
        {
          triangle.insert(tet[v]);
        }
      }
      if (std::includes(vertices.begin(), vertices.end(), triangle.begin(), triangle.end()))
      {
        out.insert(triangle);
      }
    }
  }
  return out;
}

/// A fixed cell type written as a polyhedron: local faces mapped to global ids.
template <std::size_t NumFaces>
Polyhedron FromLocal(const std::vector<Point>& local, const std::array<uv::LocalFace, NumFaces>& faces,
  const std::vector<long long>& globalIds)
{
  Polyhedron cell;
  cell.Points.resize(static_cast<std::size_t>(*std::max_element(globalIds.begin(), globalIds.end()) + 1));
  for (std::size_t i = 0; i < local.size(); ++i)
  {
    cell.Points[globalIds[i]] = local[i];
  }
  for (const uv::LocalFace& face : faces)
  {
    Face global;
    for (int i = 0; i < face.Size; ++i)
    {
      global.push_back(globalIds[face.Vertices[i]]);
    }
    cell.Faces.push_back(global);
  }
  return cell;
}

std::vector<Point> Sheared(std::vector<Point> points)
{
  for (Point& p : points)
  {
    p = { 2.0 + 1.3 * p[0] + 0.4 * p[1] - 0.2 * p[2], -1.0 - 0.3 * p[0] + 0.9 * p[1] + 0.5 * p[2],
      0.2 * p[0] - 0.1 * p[1] + 1.7 * p[2] };
  }
  return points;
}

const std::vector<Point> UnitHexahedron = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
  { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };

std::vector<Point> RegularPrism(int n, double z0 = 0.0, double z1 = 1.0)
{
  std::vector<Point> points(2 * n);
  for (int i = 0; i < n; ++i)
  {
    const double angle = 2.0 * std::acos(-1.0) * i / n;
    points[i] = { std::cos(angle), std::sin(angle), z0 };
    points[n + i] = { std::cos(angle), std::sin(angle), z1 };
  }
  return points;
}

/// A fixed cell as a polyhedron must split exactly as the fixed split, over random global ids, face
/// order and face orientation.
template <std::size_t NumFaces, typename FixedSplit>
void ExpectSameAsFixedSplit(const std::vector<Point>& local, const std::array<uv::LocalFace, NumFaces>& faces,
  FixedSplit fixed)
{
  std::mt19937 random(static_cast<unsigned>(local.size()));
  for (int trial = 0; trial < 500; ++trial)
  {
    std::vector<long long> ids(local.size());
    std::iota(ids.begin(), ids.end(), 0);
    std::shuffle(ids.begin(), ids.end(), random);
    for (long long& id : ids)
    {
      id = 3 + 5 * id;
    }
    Polyhedron cell = FromLocal(Sheared(local), faces, ids);
    const double volume = FaceVolume(cell);
    std::shuffle(cell.Faces.begin(), cell.Faces.end(), random);
    for (Face& face : cell.Faces)
    {
      if (random() % 2)
      {
        std::reverse(face.begin(), face.end());
      }
    }
    const Split split = SplitOf(cell);
    ASSERT_TRUE(split.Error.empty()) << split.Error;
    EXPECT_FALSE(split.HasCentre);
    int tets[uv::MaxTetsPerCell][4];
    const int count = fixed(ids.data(), tets);
    std::vector<std::array<long long, 4>> expected;
    for (int t = 0; t < count; ++t)
    {
      expected.push_back({ ids[tets[t][0]], ids[tets[t][1]], ids[tets[t][2]], ids[tets[t][3]] });
    }
    EXPECT_EQ(TetSet(split.Tets), TetSet(expected));
    EXPECT_NEAR(ExpectPositive(cell, split), volume, 1e-12 * volume);
  }
}

/// An L extruded over z in [0, 1]: the corners of the L outline are (0,0) (3,0) (3,w) (w,w) (w,3) (0,3), arms w wide. Its top and bottom are each two
/// convex quads meeting along (0,0)-(w,w), so every face is strictly convex and the cell is not.
Polyhedron LShape(double w, long long offset = 0)
{
  const std::array<std::array<double, 2>, 6> outline = { { { 0, 0 }, { 3, 0 }, { 3, w }, { w, w }, { w, 3 },
    { 0, 3 } } };
  Polyhedron cell;
  cell.Points.resize(static_cast<std::size_t>(offset));
  for (double z : { 0.0, 1.0 })
  {
    for (const auto& xy : outline)
    {
      cell.Points.push_back({ xy[0], xy[1], z });
    }
  }
  auto b = [&](int i) { return offset + i; };     // bottom corner i
  auto t = [&](int i) { return offset + 6 + i; }; // top corner i
  cell.Faces = { { b(0), b(3), b(2), b(1) }, { b(0), b(5), b(4), b(3) }, { t(0), t(1), t(2), t(3) },
    { t(0), t(3), t(4), t(5) } };
  for (int i = 0; i < 6; ++i)
  {
    cell.Faces.push_back({ b(i), b((i + 1) % 6), t((i + 1) % 6), t(i) });
  }
  return cell;
}
} // namespace

TEST(PolyhedronSplit, HexahedronAsPolyhedronIsTheHexahedronSplit)
{
  ExpectSameAsFixedSplit(UnitHexahedron, uv::HexahedronFaces,
    [](const long long* ids, int tets[][4]) { return uv::SplitHexahedron(ids, tets); });
}

TEST(PolyhedronSplit, PrismsAndWedgesAsPolyhedraAreTheirFixedSplits)
{
  ExpectSameAsFixedSplit(RegularPrism(5), uv::PentagonalPrismFaces,
    [](const long long* ids, int tets[][4]) { return uv::SplitPentagonalPrism(ids, tets); });
  ExpectSameAsFixedSplit(RegularPrism(6), uv::HexagonalPrismFaces,
    [](const long long* ids, int tets[][4]) { return uv::SplitHexagonalPrism(ids, tets); });
  const std::vector<Point> wedge = { { 0, 0, 0 }, { 0, 1, 0 }, { 1, 0, 0 }, { 0, 0, 1 }, { 0, 1, 1 }, { 1, 0, 1 } };
  ExpectSameAsFixedSplit(wedge, uv::WedgeFaces,
    [](const long long* ids, int tets[][4]) { return uv::SplitWedge(ids, tets); });
}

TEST(PolyhedronSplit, ConvexHouseWithPentagonalFaces)
{
  // A unit cube with a roof ridge at height 1.5: two pentagonal gables, no new point needed.
  Polyhedron house;
  house.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 },
    { 0, 1, 1 }, { 0, 0.5, 1.5 }, { 1, 0.5, 1.5 } };
  house.Faces = { { 0, 3, 2, 1 }, { 0, 1, 5, 4 }, { 2, 3, 7, 6 }, { 0, 4, 8, 7, 3 }, { 1, 2, 6, 9, 5 },
    { 4, 5, 9, 8 }, { 6, 7, 8, 9 } };
  const Split split = SplitOf(house);
  ASSERT_TRUE(split.Error.empty()) << split.Error;
  EXPECT_FALSE(split.HasCentre);
  EXPECT_NEAR(ExpectPositive(house, split), 1.25, 1e-14);
  EXPECT_NEAR(FaceVolume(house), 1.25, 1e-14);
}

TEST(PolyhedronSplit, NonConvexLShapeGetsItsCentre)
{
  const Polyhedron l = LShape(2.0, 7);
  const Split split = SplitOf(l);
  ASSERT_TRUE(split.Error.empty()) << split.Error;
  ASSERT_TRUE(split.HasCentre);
  // The centre is the mean of the 12 distinct vertices.
  EXPECT_EQ(split.Vertices.size(), 12u);
  EXPECT_NEAR(split.Centre[0], 10.0 / 6.0, 1e-15);
  EXPECT_NEAR(split.Centre[1], 10.0 / 6.0, 1e-15);
  EXPECT_NEAR(split.Centre[2], 0.5, 1e-15);
  // A tet per fan triangle: 10 quads -> 20, each with the centre.
  EXPECT_EQ(split.Tets.size(), 20u);
  for (const auto& tet : split.Tets)
  {
    EXPECT_EQ(std::count(tet.begin(), tet.end(), Split::CentreId), 1);
  }
  EXPECT_NEAR(ExpectPositive(l, split), 8.0, 1e-13);
  EXPECT_NEAR(FaceVolume(l), 8.0, 1e-13);
}

TEST(PolyhedronSplit, NeighboursShareFaceTriangles)
{
  // A column of three hexagonal prisms with random ids; each shared hexagon must be cut alike from
  // both sides, and each boundary face into its n-2 fan triangles.
  std::mt19937 random(11);
  for (int trial = 0; trial < 200; ++trial)
  {
    std::vector<long long> ids(24);
    std::iota(ids.begin(), ids.end(), 0);
    std::shuffle(ids.begin(), ids.end(), random);
    std::vector<Split> splits;
    std::vector<Polyhedron> cells;
    for (int level = 0; level < 3; ++level)
    {
      const std::vector<long long> cellIds(ids.begin() + 6 * level, ids.begin() + 6 * level + 12);
      cells.push_back(FromLocal(RegularPrism(6, level, level + 1.0), uv::HexagonalPrismFaces, cellIds));
      // Even levels through the polyhedron path, odd ones through the fixed split: both must agree.
      splits.push_back(SplitOf(cells.back()));
      if (level % 2 == 1)
      {
        int tets[uv::MaxTetsPerCell][4];
        const int count = uv::SplitHexagonalPrism(cellIds.data(), tets);
        splits.back().Tets.clear();
        for (int t = 0; t < count; ++t)
        {
          splits.back().Tets.push_back(
            { cellIds[tets[t][0]], cellIds[tets[t][1]], cellIds[tets[t][2]], cellIds[tets[t][3]] });
        }
      }
      ASSERT_TRUE(splits.back().Error.empty()) << splits.back().Error;
      EXPECT_NEAR(ExpectPositive(cells.back(), splits.back()), 1.5 * std::sqrt(3.0), 1e-12);
    }
    for (int level = 0; level + 1 < 3; ++level)
    {
      const Face shared = cells[level].Faces[1]; // the top of this level is the bottom of the next
      const auto below = TrianglesOnFace(splits[level], shared);
      EXPECT_EQ(below.size(), 4u);
      EXPECT_EQ(below, TrianglesOnFace(splits[level + 1], shared));
    }
  }
}

TEST(PolyhedronSplit, NonConvexNonStarShapedIsAnError)
{
  // Thin arms: the vertex mean lies in the notch, outside the L.
  const Split split = SplitOf(LShape(1.0));
  EXPECT_TRUE(split.Tets.empty());
  EXPECT_NE(split.Error.find("not star-shaped"), std::string::npos) << split.Error;
}

TEST(PolyhedronSplit, BadInputIsAnErrorNotACrash)
{
  const Polyhedron cube = FromLocal(UnitHexahedron, uv::HexahedronFaces, { 0, 1, 2, 3, 4, 5, 6, 7 });
  auto errorOf = [](const Polyhedron& cell) {
    const Split split = SplitOf(cell);
    EXPECT_TRUE(split.Tets.empty());
    return split.Error;
  };
  auto expectError = [&](const Polyhedron& cell, const std::string& words) {
    const std::string error = errorOf(cell);
    EXPECT_NE(error.find(words), std::string::npos) << "expected '" << words << "', got '" << error << "'";
  };
  ASSERT_TRUE(SplitOf(cube).Error.empty());

  Polyhedron bent = cube; // one corner lifted off its three faces' planes
  bent.Points[6] = { 1, 1, 1.2 };
  expectError(bent, "is not planar");

  Polyhedron open = cube;
  open.Faces.pop_back();
  expectError(open, "the faces do not close");

  Polyhedron repeated = cube;
  repeated.Faces[0] = { 0, 3, 2, 3 };
  expectError(repeated, "repeats point 3");

  Polyhedron tooSmall = cube;
  tooSmall.Faces[0] = { 0, 3 };
  expectError(tooSmall, "fewer than 3 points");

  Polyhedron outOfRange = cube;
  outOfRange.Faces[0][0] = 99;
  expectError(outOfRange, "out of range");

  Polyhedron doubled = cube; // two cubes in one cell: closed, but two surfaces
  for (int i = 0; i < 8; ++i)
  {
    doubled.Points.push_back({ UnitHexahedron[i][0] + 3, UnitHexahedron[i][1], UnitHexahedron[i][2] });
  }
  for (const Face& face : cube.Faces)
  {
    doubled.Faces.push_back({ face[0] + 8, face[1] + 8, face[2] + 8, face[3] + 8 });
  }
  expectError(doubled, "more than one closed surface");

  // A prism over a non-convex pentagon (a dart) and over a pentagram.
  auto prismOver = [](const std::vector<std::array<double, 2>>& outline) {
    Polyhedron cell;
    const long long n = static_cast<long long>(outline.size());
    for (double z : { 0.0, 1.0 })
    {
      for (const auto& xy : outline)
      {
        cell.Points.push_back({ xy[0], xy[1], z });
      }
    }
    Face bottom, top;
    for (long long i = 0; i < n; ++i)
    {
      bottom.push_back((n - i) % n);
      top.push_back(n + i);
      cell.Faces.push_back({ i, (i + 1) % n, n + (i + 1) % n, n + i });
    }
    cell.Faces.push_back(bottom);
    cell.Faces.push_back(top);
    return cell;
  };
  expectError(prismOver({ { 0, 0 }, { 2, 0 }, { 2, 2 }, { 1, 0.5 }, { 0, 2 } }), "is not strictly convex");
  std::vector<std::array<double, 2>> star;
  for (int i = 0; i < 5; ++i)
  {
    const double angle = 2.0 * std::acos(-1.0) * (2 * i % 5) / 5;
    star.push_back({ std::cos(angle), std::sin(angle) });
  }
  const std::string starError = errorOf(prismOver(star));
  EXPECT_FALSE(starError.empty());
  // Straight angles (a hanging node) are refused: their fans would not conform.
  expectError(prismOver({ { 0, 0 }, { 1, 0 }, { 2, 0 }, { 2, 2 }, { 0, 2 } }), "is not strictly convex");

  Polyhedron coincident = cube;
  coincident.Points[1] = coincident.Points[0];
  EXPECT_FALSE(errorOf(coincident).empty());

  // A truncated stream and a stream too short for its face count.
  const std::vector<long long> stream = Stream(cube.Faces);
  auto pointOf = [&](long long id) { return cube.Points[static_cast<std::size_t>(id)]; };
  for (std::size_t length : { std::size_t(0), std::size_t(1), std::size_t(7), stream.size() - 1 })
  {
    const Split split = uv::SplitPolyhedron(stream.data(), length, 8LL, pointOf);
    EXPECT_NE(split.Error.find(length == 0 ? "at least 4 faces" : "ends inside face"), std::string::npos)
      << length << ": " << split.Error;
    EXPECT_TRUE(split.Tets.empty());
  }
}

TEST(PolyhedronSplit, SelfIntersectingFaceIsNamed)
{
  // A pentagram face, every corner turning left, twice round: caught by its total turning.
  Polyhedron pyramid;
  std::vector<long long> base;
  for (int i = 0; i < 5; ++i)
  {
    const double angle = 2.0 * std::acos(-1.0) * (2 * i % 5) / 5;
    pyramid.Points.push_back({ std::cos(angle), std::sin(angle), 0.0 });
    base.push_back(4 - i);
  }
  pyramid.Points.push_back({ 0, 0, 1 });
  pyramid.Faces.push_back(base);
  for (long long i = 0; i < 5; ++i)
  {
    pyramid.Faces.push_back({ i, (i + 1) % 5, 5 });
  }
  const Split split = SplitOf(pyramid);
  EXPECT_TRUE(split.Tets.empty());
  EXPECT_NE(split.Error.find("intersects itself"), std::string::npos) << split.Error;
}
