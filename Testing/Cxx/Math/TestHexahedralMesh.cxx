// The hexahedral mesh's connectivity (uvHexahedralMesh.h, uvNonConformingFaces.h) and the scalar normalisation every mapper
// uploads with (uvScalarNormalisation.h), on a small block of cells.
#include "uvHexahedralMesh.h"
#include "uvNonConformingFaces.h"
#include "uvScalarNormalisation.h"
#include "uvTestHexahedralRow.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace
{
using uvtest::Serial;
using Block = uvtest::HexahedralRow;
} // namespace

TEST(HexahedronMesh, NeighboursAreMutualAndTheRestIsBoundary)
{
  const Block block(3);
  std::vector<double> progress;
  const uv::HexahedralFaces faces = uv::MakeHexahedralFaces(block.CellPoints, {}, Serial,
    [](auto begin, auto end) { std::sort(begin, end); }, [&](double f) { progress.push_back(f); });
  EXPECT_EQ(progress, (std::vector<double>{ 0.5, 1.0 }));
  ASSERT_EQ(faces.Neighbours.size(), 8u * 3u);
  // Face 3 (r = 1) of cell c meets face 5 (r = 0) of cell c + 1, both ways.
  for (int c = 0; c < 2; ++c)
  {
    EXPECT_EQ(faces.Neighbours[8 * c + 3], 8 * (c + 1) + 5);
    EXPECT_EQ(faces.Neighbours[8 * (c + 1) + 5], 8 * c + 3);
  }
  EXPECT_EQ(faces.Neighbours[8 * 0 + 5], -1);
  EXPECT_EQ(faces.Neighbours[8 * 2 + 3], -1);
  ASSERT_EQ(faces.Boundary.size(), 4u * (6 * 3 - 2 * 2));
  for (std::size_t b = 0; b < faces.Boundary.size(); b += 4)
    EXPECT_EQ(faces.Neighbours[8 * faces.Boundary[b] + faces.Boundary[b + 1]], -1);
}

TEST(HexahedronMesh, CollapsedCellsShareTrianglesAndHaveNoCollapsedFaces)
{
  // A unit cube split into two wedges by its diagonal plane x = y, and a tetrahedron on the
  // second wedge's triangle at z = 1, through the *AsHexahedron orders. Cube points: (i, j, k) as
  // i + 2 j + 4 k; the apex is point 8.
  const std::uint32_t wedgeA[6] = { 0, 1, 3, 4, 5, 7 }; // below the diagonal: (0,0) (1,0) (1,1)... as VTK
  const std::uint32_t wedgeB[6] = { 0, 3, 2, 4, 7, 6 };
  const std::uint32_t tetrahedron[4] = { 4, 6, 7, 8 };
  std::vector<std::uint32_t> cells;
  for (const std::uint32_t* wedge : { wedgeA, wedgeB })
    for (int k : uv::WedgeAsHexahedron)
      cells.push_back(wedge[k]);
  for (int k : uv::TetrahedronAsHexahedron)
    cells.push_back(tetrahedron[k]);
  const uv::HexahedralFaces faces =
    uv::MakeHexahedralFaces(cells, {}, Serial, [](auto begin, auto end) { std::sort(begin, end); }, [](double) {});
  // Each wedge: 2 triangles, 3 quads, 1 collapsed face; the tetrahedron: 4 triangles, 2 collapsed.
  // Shared: the diagonal quad (wedge A / wedge B) and the top triangle of wedge B / the tetrahedron.
  int joined = 0;
  for (int cell = 0; cell < 3; ++cell)
    for (int f = 0; f < 6; ++f)
    {
      const int across = faces.Neighbours[8 * cell + f];
      if (across < 0)
        continue;
      ++joined;
      EXPECT_EQ(faces.Neighbours[across], 8 * cell + f);
    }
  EXPECT_EQ(joined, 4);
  EXPECT_EQ(faces.Boundary.size(), 4u * ((5 - 1) + (5 - 2) + (4 - 1)));
  std::array<std::uint32_t, 4> key;
  const std::uint32_t triangle[4] = { 7, 3, 3, 5 }, edge[4] = { 2, 2, 6, 6 };
  EXPECT_EQ(uv::FaceKey(triangle, key), 3);
  EXPECT_EQ(key, (std::array<std::uint32_t, 4>{ 3, 5, 7, uv::NoPoint }));
  EXPECT_EQ(uv::FaceKey(edge, key), 2);
}

TEST(HexahedronMesh, RepeatedPointsStillJoinTheirCells)
{
  // Two cubes of Block(2) whose shared face's points are repeated for the second cube (as some
  // writers store meshes): joined through the coincident points' representatives, not by id.
  Block block(2);
  const std::size_t pointCount = block.PointData.size() / 4;
  for (int k = 8; k < 16; ++k)
  {
    std::uint32_t& id = block.CellPoints[k];
    if (block.PointData[4 * id] != 1.0f)
      continue; // not on the shared face x = 1
    block.PointData.insert(block.PointData.end(), block.PointData.begin() + 4 * id, block.PointData.begin() + 4 * id + 4);
    id = static_cast<std::uint32_t>(block.PointData.size() / 4 - 1);
  }
  ASSERT_EQ(block.PointData.size() / 4, pointCount + 4);
  auto sort = [](auto begin, auto end) { std::sort(begin, end); };
  EXPECT_EQ(uv::MakeHexahedralFaces(block.CellPoints, {}, Serial, sort, [](double) {}).Neighbours[8 * 0 + 3], -1);
  const std::vector<std::uint32_t> same = uv::CoincidentPointRepresentatives(
    block.PointData, [](auto begin, auto end, auto less) { std::sort(begin, end, less); });
  for (std::size_t p = pointCount; p < pointCount + 4; ++p)
    EXPECT_LT(same[p], pointCount);
  const uv::HexahedralFaces faces = uv::MakeHexahedralFaces(block.CellPoints, same, Serial, sort, [](double) {});
  EXPECT_EQ(faces.Neighbours[8 * 0 + 3], 8 * 1 + 5);
  EXPECT_EQ(faces.Boundary.size(), 4u * 10);
}

TEST(HexahedronMesh, CoincidentCellsMergeIntoOneOfTheirDensity)
{
  // Block(3) appended again: once on the same ids, once more (the middle cell only) on copies of its
  // points, and a copy of the last cell whose field differs at one corner.
  Block block(3);
  const std::vector<std::uint32_t> original = block.CellPoints;
  const auto sort = [](auto begin, auto end, auto less) { std::sort(begin, end, less); };
  const auto same = [&] { return uv::CoincidentPointRepresentatives(block.PointData, sort); };
  EXPECT_TRUE(uv::CoincidentCellDensities<8>(block.CellPoints, same(), block.PointData, {}, sort).empty());
  block.CellPoints.insert(block.CellPoints.end(), original.begin(), original.end());
  for (int k = 8; k < 16; ++k)
  {
    const std::uint32_t id = original[k];
    block.PointData.insert(block.PointData.end(), block.PointData.begin() + 4 * id, block.PointData.begin() + 4 * id + 4);
    block.CellPoints.push_back(static_cast<std::uint32_t>(block.PointData.size() / 4 - 1));
  }
  for (int k = 16; k < 24; ++k)
  {
    const std::uint32_t id = original[k];
    block.PointData.insert(block.PointData.end(), block.PointData.begin() + 4 * id, block.PointData.begin() + 4 * id + 4);
    block.PointData.back() += k == 16 ? 1.0f : 0.0f; // another value at one corner: another medium
    block.CellPoints.push_back(static_cast<std::uint32_t>(block.PointData.size() / 4 - 1));
  }
  const std::vector<float> density =
    uv::CoincidentCellDensities<8>(block.CellPoints, same(), block.PointData, {}, sort);
  EXPECT_EQ(density, (std::vector<float>{ 2, 3, 2, 0, 0, 0, 0, 1 }));
  // A cell scalar (the point values are not drawn then): copies with another value stay apart.
  const std::vector<float> cellScalars = { 0.1f, 0.2f, 0.3f, 0.1f, 0.2f, 0.9f, 0.2f, 0.3f };
  EXPECT_EQ(uv::CoincidentCellDensities<8>(block.CellPoints, same(), block.PointData, cellScalars, sort),
    (std::vector<float>{ 2, 3, 2, 0, 0, 1, 0, 0 }));
}

TEST(HexahedronMesh, FlatCellsAreJoinedByIdNotThroughCoincidentPoints)
{
  // The middle cube of three flattened: its points at x = 2 moved onto those at x = 1. Its faces
  // coincide with both neighbours' and its side faces collapse through the representatives; by id
  // the row stays joined through it.
  Block block(3);
  for (std::size_t p = 0; p < block.PointData.size() / 4; ++p)
    if (block.PointData[4 * p] == 2.0f)
      block.PointData[4 * p] = 1.0f;
  const std::vector<std::uint32_t> same = uv::CoincidentPointRepresentatives(
    block.PointData, [](auto begin, auto end, auto less) { std::sort(begin, end, less); });
  const uv::HexahedralFaces faces =
    uv::MakeHexahedralFaces(block.CellPoints, same, Serial, [](auto begin, auto end) { std::sort(begin, end); },
      [](double) {});
  EXPECT_EQ(faces.Neighbours[8 * 0 + 3], 8 * 1 + 5);
  EXPECT_EQ(faces.Neighbours[8 * 1 + 3], 8 * 2 + 5);
  EXPECT_EQ(faces.Boundary.size(), 4u * 10); // the flat cube's sides, collapsed, bound nothing
}

TEST(HexahedronMesh, CellHoldingAPointAndTangledCells)
{
  Block block(3);
  EXPECT_EQ(uv::HexahedronHolding(block.CellPoints, block.PointData, glm::dvec3(1.5, 0.5, 0.5)), 1);
  EXPECT_EQ(uv::HexahedronHolding(block.CellPoints, block.PointData, glm::dvec3(3.5, 0.5, 0.5)), -1);
  EXPECT_EQ(uv::CountTangledHexahedra(block.CellPoints, block.PointData, Serial), 0u);
  // Corner 6 of the last cell pushed through its opposite face folds it.
  const std::uint32_t corner = block.CellPoints[8 * 2 + 6];
  block.PointData[4 * corner + 0] = 2.2f;
  block.PointData[4 * corner + 1] = 0.2f;
  block.PointData[4 * corner + 2] = -1.0f;
  EXPECT_EQ(uv::CountTangledHexahedra(block.CellPoints, block.PointData, Serial), 1u);
}

TEST(HexahedronMesh, ScalarNormalisationIgnoresNaN)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> values = { 4.0, nan, -2.0, 1.0 };
  const auto n = uv::ScalarNormalisation::OfFiniteValues(values.size(), [&](std::size_t p) { return values[p]; });
  EXPECT_EQ(n.Offset, -2.0);
  EXPECT_DOUBLE_EQ(n.Scale, 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(n(4.0), 1.0);
  EXPECT_TRUE(std::isnan(n(nan)));
  const auto constant = uv::ScalarNormalisation::OfFiniteValues(2, [](std::size_t) { return 3.0; });
  EXPECT_EQ(constant.Scale, 1.0);
  const auto none = uv::ScalarNormalisation::OfFiniteValues(1, [nan](std::size_t) { return nan; });
  EXPECT_EQ(none.Offset, 0.0);
  const std::vector<float> points = { 0, 0, 0, 0.5f, 0, 0, 0, float(nan) };
  const int first[1] = { 0 }, both[2] = { 0, 1 };
  EXPECT_TRUE(uv::ScalarsFinite(points, first, 1));
  EXPECT_FALSE(uv::ScalarsFinite(points, both, 2));
}

TEST(HexahedronMesh, ATimeStepKeepsTheNormalisationItsValuesFit)
{
  const auto of = [](double low, double high) {
    const std::vector<double> values = { low, high };
    return uv::ScalarNormalisation::OfFiniteValues(2, [&](std::size_t p) { return values[p]; });
  };
  const uv::ScalarNormalisation previous = of(-2.0, 6.0);
  const auto kept = of(-1.0, 4.0).ForTimeStep(previous); // inside, over half the span
  EXPECT_EQ(kept.Offset, previous.Offset);
  EXPECT_EQ(kept.Scale, previous.Scale);
  // Outside, or a quarter of the span: its own range with an eighth of it as headroom at each end,
  // which the next step's values a little beyond it keep.
  for (const auto& range : { std::pair<double, double>(1.0, 2.0), { -3.0, 4.0 }, { 0.0, 7.0 } })
  {
    const auto own = of(range.first, range.second).ForTimeStep(previous);
    const double span = range.second - range.first;
    EXPECT_DOUBLE_EQ(own(range.first), 0.1);
    EXPECT_DOUBLE_EQ(own(range.second), 0.9);
    const auto next = of(range.first - 0.1 * span, range.second).ForTimeStep(own);
    EXPECT_EQ(next.Offset, own.Offset);
  }
}

TEST(HexahedronMesh, TetrahedronFaceNeighboursAcrossEachCorner)
{
  // Two tetrahedra sharing face (1, 2, 3): across corner 0 of the first lies the second, across
  // corner 3 of the second (point 4) the first; every other face is on the boundary.
  const std::vector<std::uint32_t> tetrahedra = { 0, 1, 2, 3, 1, 2, 3, 4 };
  const std::vector<float> values = { 0.25f, 0.75f };
  const uv::TetrahedronFaceNeighbours neighbours = uv::MakeTetrahedronFaceNeighbours(
    tetrahedra, values, Serial, [](auto begin, auto end) { std::sort(begin, end); });
  EXPECT_EQ(neighbours.Values, (std::vector<float>{ 0.75f, 0.25f, 0.25f, 0.25f, 0.75f, 0.75f, 0.75f, 0.25f }));
  EXPECT_EQ(neighbours.Low, (std::vector<float>{ 0.25f, 0.25f }));
  EXPECT_EQ(neighbours.High, (std::vector<float>{ 0.75f, 0.75f }));
}

TEST(HexahedronMesh, ACellFlatByItsIdsBoundsNothing)
{
  // Three cubes stacked in z; the middle one pinched out as reservoir writers do it: its top
  // nodes are its bottom nodes. Its top and bottom faces are the same four ids, which the cells
  // above and below also use: four faces of one key. The flat cell bounds nothing, so the other
  // two are neighbours.
  auto id = [](int i, int j, int k) { return static_cast<std::uint32_t>(i + 2 * j + 4 * k); };
  auto cube = [&](int bottom, int top) {
    return std::vector<std::uint32_t>{ id(0, 0, bottom), id(1, 0, bottom), id(1, 1, bottom), id(0, 1, bottom),
      id(0, 0, top), id(1, 0, top), id(1, 1, top), id(0, 1, top) };
  };
  std::vector<std::uint32_t> cells;
  for (const auto& cell : { cube(0, 1), cube(1, 1), cube(1, 2) })
    cells.insert(cells.end(), cell.begin(), cell.end());
  const uv::HexahedralFaces faces =
    uv::MakeHexahedralFaces(cells, {}, Serial, [](auto begin, auto end) { std::sort(begin, end); }, [](double) {});
  EXPECT_EQ(faces.Neighbours[8 * 0 + 1], 8 * 2 + 0); // cube 0's top (face 1) meets cube 2's bottom
  EXPECT_EQ(faces.Neighbours[8 * 2 + 0], 8 * 0 + 1);
  for (int f = 0; f < 6; ++f)
    EXPECT_EQ(faces.Neighbours[8 * 1 + f], -1);
  for (std::size_t b = 0; b < faces.Boundary.size(); b += 4)
    EXPECT_NE(faces.Boundary[b], 1);
  EXPECT_EQ(faces.Boundary.size(), 4u * 10u); // two cubes' outer faces only
}

TEST(HexahedronMesh, FacesAcrossAFaultLieAgainstEachOther)
{
  // Two rows of one cube side by side in x, the second moved down by half a cube with points of
  // its own (a fault with a throw): its face x = 1 lies against the first's, sharing no point.
  uvtest::HexahedralRow left(1), right(1);
  for (std::size_t p = 0; p < right.PointData.size(); p += 4)
  {
    right.PointData[p] += 1.0f;
    right.PointData[p + 2] -= 0.5f;
  }
  std::vector<std::uint32_t> cells = left.CellPoints;
  for (std::uint32_t point : right.CellPoints)
    cells.push_back(point + static_cast<std::uint32_t>(left.PointData.size() / 4));
  std::vector<float> points = left.PointData;
  points.insert(points.end(), right.PointData.begin(), right.PointData.end());
  uv::HexahedralFaces faces =
    uv::MakeHexahedralFaces(cells, {}, Serial, [](auto begin, auto end) { std::sort(begin, end); }, [](double) {});
  ASSERT_EQ(faces.Boundary.size(), 4u * 12u);
  EXPECT_EQ(uv::LinkNonConformingFaces(cells, points, faces), 2u);
  EXPECT_EQ(uv::FarSideCell(faces.Neighbours[8 * 0 + 3]), 1); // face 3: r = 1, x = 1
  EXPECT_EQ(uv::FarSideCell(faces.Neighbours[8 * 1 + 5]), 0); // face 5: r = 0
  EXPECT_EQ(faces.Neighbours[8 * 0 + 1], -1);                   // the top lies against nothing
  // Moved apart by a tenth of a cube, they are a gap, not a fault.
  for (std::size_t p = left.PointData.size(); p < points.size(); p += 4)
    points[p] += 0.1f;
  faces = uv::MakeHexahedralFaces(cells, {}, Serial, [](auto begin, auto end) { std::sort(begin, end); }, [](double) {});
  EXPECT_EQ(uv::LinkNonConformingFaces(cells, points, faces), 0u);
}

TEST(HexahedronMesh, ConvexCellsWithPlanarFacesAreFlagged)
{
  // A box, a tetrahedron and a wedge (collapsed hexahedra), and a trapezoidal prism (planar faces,
  // a bilinear map) are walked through their planes; a box with one corner lifted (a warped face),
  // a non-convex cell (a corner pushed inwards through the opposite faces' planes), a left-handed
  // box and a flat one are told apart.
  const glm::dvec3 box[8] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 },
    { 1, 1, 1 }, { 0, 1, 1 } };
  const std::uint32_t ids[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  EXPECT_TRUE(uv::IsConvexWithPlanarFaces(box, ids));

  glm::dvec3 p[8];
  std::uint32_t collapsed[8];
  for (const auto& order : { uv::TetrahedronAsHexahedron, uv::WedgeAsHexahedron })
  {
    const glm::dvec3 corners[6] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 }, { 0, 1, 1 } };
    for (int k = 0; k < 8; ++k)
    {
      p[k] = corners[order[k]];
      collapsed[k] = static_cast<std::uint32_t>(order[k]);
    }
    EXPECT_TRUE(uv::IsConvexWithPlanarFaces(p, collapsed));
  }

  std::copy(box, box + 8, p);
  p[6] = { 1.2, 1.2, 1 }; // the top face stays planar, its sides lean out in plane
  p[7] = { 0, 1.2, 1 };
  p[5] = { 1.2, 0, 1 };
  EXPECT_TRUE(uv::IsConvexWithPlanarFaces(p, ids));

  std::copy(box, box + 8, p);
  p[6].z = 1.01; // three faces warp
  EXPECT_FALSE(uv::IsConvexWithPlanarFaces(p, ids));

  std::copy(box, box + 8, p);
  p[6] = { 0.4, 0.4, 0.4 }; // three faces fold inwards
  EXPECT_FALSE(uv::IsConvexWithPlanarFaces(p, ids));

  for (int k = 0; k < 8; ++k)
    p[k] = box[k] * glm::dvec3(1, 1, -1); // left-handed: still convex, every plane turned outwards
  EXPECT_TRUE(uv::IsConvexWithPlanarFaces(p, ids));

  for (int k = 0; k < 8; ++k)
    p[k] = box[k] * glm::dvec3(1, 1, 0); // no volume
  EXPECT_FALSE(uv::IsConvexWithPlanarFaces(p, ids));
}

TEST(HexahedronMesh, TheMeshsCellGeometryIsItsMostGeneralCells)
{
  // A row of cubes is parallelepipeds, and still is sheared; lift one corner, which warps the faces
  // of the two cells sharing it, and the mesh is general. A frustum is convex with planar faces
  // but no parallelepiped; nor is a cell with a collapsed corner.
  Block block(3);
  EXPECT_EQ(uv::MeshCellGeometry(block.CellPoints, block.PointData, Serial), uv::CellGeometry::Parallelepipeds);
  for (std::size_t p = 0; p < block.PointData.size(); p += 4)
    block.PointData[p] += 0.3f * block.PointData[p + 2]; // sheared along x by z
  EXPECT_EQ(uv::MeshCellGeometry(block.CellPoints, block.PointData, Serial), uv::CellGeometry::Parallelepipeds);
  block.PointData[4 * block.CellPoints[6] + 2] += 0.2f; // the first cell's far corner lifted
  EXPECT_EQ(uv::MeshCellGeometry(block.CellPoints, block.PointData, Serial), uv::CellGeometry::Any);

  const glm::dvec3 frustum[8] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1.2, 0, 1 },
    { 1.2, 1.2, 1 }, { 0, 1.2, 1 } };
  const std::uint32_t ids[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  EXPECT_TRUE(uv::IsConvexWithPlanarFaces(frustum, ids));
  EXPECT_FALSE(uv::IsParallelepiped(frustum, ids));
  const std::uint32_t wedge[8] = { 0, 1, 2, 2, 4, 5, 6, 6 };
  glm::dvec3 collapsed[8];
  std::copy(frustum, frustum + 8, collapsed);
  collapsed[3] = collapsed[2];
  collapsed[7] = collapsed[6];
  EXPECT_FALSE(uv::IsParallelepiped(collapsed, wedge));
}
