// The VTK-free subdivision lattices: counts, sub-cells that tile the reference cell with the
// parent's orientation, interior faces shared by two sub-cells, exact keys, and identical key sets
// on a face shared by two cells of any families and local numberings.
#include "uvIsoparametricLattice.h"
#include "uvLinearCellSplit.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace
{
using uv::CellFamily;
using Key = uv::LatticeKey<long long>;
using Point = std::array<double, 3>;

const CellFamily Families[4] = { CellFamily::Tetrahedron, CellFamily::Hexahedron, CellFamily::Wedge,
  CellFamily::Pyramid };

const char* Name(CellFamily family)
{
  switch (family)
  {
    case CellFamily::Tetrahedron:
      return "tetrahedron";
    case CellFamily::Hexahedron:
      return "hexahedron";
    case CellFamily::Wedge:
      return "wedge";
    default:
      return "pyramid";
  }
}

/// Our own evaluation of VTK's linear basis at parametric coordinates (r, s, t).
std::vector<double> LinearBasis(CellFamily family, const Point& p)
{
  const double r = p[0], s = p[1], t = p[2];
  switch (family)
  {
    case CellFamily::Tetrahedron:
      return { 1 - r - s - t, r, s, t };
    case CellFamily::Hexahedron:
      return { (1 - r) * (1 - s) * (1 - t), r * (1 - s) * (1 - t), r * s * (1 - t), (1 - r) * s * (1 - t),
        (1 - r) * (1 - s) * t, r * (1 - s) * t, r * s * t, (1 - r) * s * t };
    case CellFamily::Wedge:
      return { (1 - r - s) * (1 - t), r * (1 - t), s * (1 - t), (1 - r - s) * t, r * t, s * t };
    default:
      return { (1 - r) * (1 - s) * (1 - t), r * (1 - s) * (1 - t), r * s * (1 - t), (1 - r) * s * (1 - t), t };
  }
}

/// The sub-cell split into tets by uvLinearCellSplit (local ids as global ids), as point indices.
std::vector<std::array<int, 4>> Tets(const uv::LatticeSubCell& cell)
{
  const long long ids[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  int local[uv::MaxTetsPerCell][4];
  int count = 0;
  switch (cell.Size)
  {
    case 4:
      local[0][0] = 0, local[0][1] = 1, local[0][2] = 2, local[0][3] = 3;
      count = 1;
      break;
    case 5:
      count = uv::SplitPyramid(ids, local);
      break;
    case 6:
      count = uv::SplitWedge(ids, local);
      break;
    default:
      count = uv::SplitHexahedron(ids, local);
  }
  std::vector<std::array<int, 4>> tets;
  for (int t = 0; t < count; ++t)
  {
    tets.push_back({ cell.Points[local[t][0]], cell.Points[local[t][1]], cell.Points[local[t][2]],
      cell.Points[local[t][3]] });
  }
  return tets;
}

/// The faces of a sub-cell as lists of its point indices (VTK's local faces).
std::vector<std::vector<int>> Faces(const uv::LatticeSubCell& cell)
{
  static const std::vector<std::vector<int>> tet = { { 0, 1, 2 }, { 0, 1, 3 }, { 1, 2, 3 }, { 0, 2, 3 } };
  std::vector<std::vector<int>> local;
  auto add = [&](const auto& faces) {
    for (const uv::LocalFace& face : faces)
    {
      local.emplace_back(face.Vertices.begin(), face.Vertices.begin() + face.Size);
    }
  };
  if (cell.Size == 4)
  {
    local = tet;
  }
  else if (cell.Size == 5)
  {
    add(uv::PyramidFaces);
  }
  else if (cell.Size == 6)
  {
    add(uv::WedgeFaces);
  }
  else
  {
    add(uv::HexahedronFaces);
  }
  std::vector<std::vector<int>> faces;
  for (const std::vector<int>& face : local)
  {
    std::vector<int> points;
    for (int v : face)
    {
      points.push_back(cell.Points[v]);
    }
    faces.push_back(points);
  }
  return faces;
}

/// True when every lattice index of the face lies on one face plane of the family's domain.
bool OnDomainBoundary(const uv::IsoparametricLattice& lattice, const std::vector<int>& face)
{
  const int l = lattice.GetLevel();
  // Each plane as a.(i, j, k) == b.
  std::vector<std::pair<std::array<int, 3>, int>> planes = { { { 1, 0, 0 }, 0 }, { { 0, 1, 0 }, 0 },
    { { 0, 0, 1 }, 0 } };
  switch (lattice.GetFamily())
  {
    case CellFamily::Tetrahedron:
      planes.push_back({ { 1, 1, 1 }, l });
      break;
    case CellFamily::Hexahedron:
      planes.insert(planes.end(), { { { 1, 0, 0 }, l }, { { 0, 1, 0 }, l }, { { 0, 0, 1 }, l } });
      break;
    case CellFamily::Wedge:
      planes.insert(planes.end(), { { { 1, 1, 0 }, l }, { { 0, 0, 1 }, l } });
      break;
    case CellFamily::Pyramid:
      planes.insert(planes.end(), { { { 1, 0, 1 }, l }, { { 0, 1, 1 }, l } });
      break;
  }
  for (const auto& plane : planes)
  {
    bool all = true;
    for (int p : face)
    {
      const std::array<int, 3>& index = lattice.Index(p);
      all = all && plane.first[0] * index[0] + plane.first[1] * index[1] + plane.first[2] * index[2] == plane.second;
    }
    if (all)
    {
      return true;
    }
  }
  return false;
}

double DomainVolume(CellFamily family)
{
  switch (family)
  {
    case CellFamily::Tetrahedron:
      return 1.0 / 6.0;
    case CellFamily::Hexahedron:
      return 1.0;
    case CellFamily::Wedge:
      return 0.5;
    default:
      return 1.0 / 3.0;
  }
}

/// The corners of the reference cell (the lattice of level 1) in VTK order.
std::vector<Point> ReferenceCorners(CellFamily family)
{
  const uv::IsoparametricLattice one(family, 1);
  std::vector<Point> corners;
  for (int c : one.SubCells()[0].Points)
  {
    corners.push_back(one.Reference(static_cast<std::size_t>(c)));
  }
  corners.resize(static_cast<std::size_t>(uv::CornerCount(family)));
  return corners;
}

struct Cell
{
  CellFamily Family;
  std::vector<long long> Corners; // global ids in VTK order
};

/// Sub-faces of a cell lying on the face with the given global corners, each as its sorted keys.
std::set<std::vector<Key>> SubFacesOn(const Cell& cell, int level, const std::set<long long>& face)
{
  const uv::IsoparametricLattice lattice(cell.Family, level);
  auto onFace = [&](const Key& key) {
    for (int n = 0; n < key.Size; ++n)
    {
      if (!face.count(key.Corners[n]))
      {
        return false;
      }
    }
    return true;
  };
  std::set<std::vector<Key>> subFaces;
  for (const uv::LatticeSubCell& sub : lattice.SubCells())
  {
    for (const std::vector<int>& f : Faces(sub))
    {
      std::vector<Key> keys;
      bool inside = true;
      for (int p : f)
      {
        keys.push_back(lattice.Key(static_cast<std::size_t>(p), cell.Corners.data()));
        inside = inside && onFace(keys.back());
      }
      if (inside)
      {
        std::sort(keys.begin(), keys.end());
        subFaces.insert(keys);
      }
    }
  }
  return subFaces;
}

void ExpectSameSubFaces(const Cell& a, const Cell& b, const std::set<long long>& face)
{
  for (int level = 1; level <= 6; ++level)
  {
    SCOPED_TRACE(level);
    const std::set<std::vector<Key>> fromA = SubFacesOn(a, level, face);
    const std::set<std::vector<Key>> fromB = SubFacesOn(b, level, face);
    EXPECT_EQ(fromA.size(), static_cast<std::size_t>(level * level));
    EXPECT_TRUE(fromA == fromB) << Name(a.Family) << " and " << Name(b.Family) << " cut the face differently";
  }
}
} // namespace

TEST(IsoparametricLattice, Counts)
{
  for (CellFamily family : Families)
  {
    SCOPED_TRACE(Name(family));
    for (int l = 1; l <= 8; ++l)
    {
      const uv::IsoparametricLattice lattice(family, l);
      std::size_t points = 0, cells = static_cast<std::size_t>(l * l * l);
      switch (family)
      {
        case CellFamily::Tetrahedron:
          points = static_cast<std::size_t>((l + 1) * (l + 2) * (l + 3) / 6);
          break;
        case CellFamily::Hexahedron:
          points = static_cast<std::size_t>((l + 1) * (l + 1) * (l + 1));
          break;
        case CellFamily::Wedge:
          points = static_cast<std::size_t>((l + 1) * (l + 1) * (l + 2) / 2);
          break;
        case CellFamily::Pyramid:
          points = static_cast<std::size_t>((l + 1) * (l + 2) * (2 * l + 3) / 6);
          cells = static_cast<std::size_t>(l * (4 * l * l - 1) / 3);
          break;
      }
      EXPECT_EQ(lattice.NumberOfPoints(), points);
      EXPECT_EQ(lattice.SubCells().size(), cells);
    }
  }
  EXPECT_THROW(uv::IsoparametricLattice(CellFamily::Tetrahedron, 0), std::invalid_argument);
  EXPECT_THROW(uv::IsoparametricLattice(CellFamily::Tetrahedron, uv::MaxLatticeLevel + 1), std::invalid_argument);
}

TEST(IsoparametricLattice, SubCellsTileTheReferenceCellWithItsOrientation)
{
  for (CellFamily family : Families)
  {
    SCOPED_TRACE(Name(family));
    // The parent's own split gives its orientation (VTK's wedge turns the other way from the rest).
    const std::vector<Point> corners = ReferenceCorners(family);
    const uv::IsoparametricLattice one(family, 1);
    const std::array<int, 4> first = Tets(one.SubCells()[0])[0];
    const double parentSign = uv::SixSignedVolume(corners[static_cast<std::size_t>(first[0])],
                                corners[static_cast<std::size_t>(first[1])], corners[static_cast<std::size_t>(first[2])],
                                corners[static_cast<std::size_t>(first[3])]) > 0.0 ? 1.0 : -1.0;
    for (int l = 1; l <= 6; ++l)
    {
      const uv::IsoparametricLattice lattice(family, l);
      double volume = 0.0;
      int wrongSign = 0;
      for (const uv::LatticeSubCell& cell : lattice.SubCells())
      {
        for (const std::array<int, 4>& tet : Tets(cell))
        {
          const double six = parentSign *
            uv::SixSignedVolume(lattice.Reference(static_cast<std::size_t>(tet[0])),
              lattice.Reference(static_cast<std::size_t>(tet[1])), lattice.Reference(static_cast<std::size_t>(tet[2])),
              lattice.Reference(static_cast<std::size_t>(tet[3])));
          wrongSign += six > 0.0 ? 0 : 1;
          volume += six / 6.0;
        }
      }
      EXPECT_EQ(wrongSign, 0) << "level " << l;
      EXPECT_NEAR(volume, DomainVolume(family), 1e-12) << "level " << l;
    }
  }
}

TEST(IsoparametricLattice, InteriorFacesAreSharedByTwoSubCells)
{
  for (CellFamily family : Families)
  {
    SCOPED_TRACE(Name(family));
    const int domainFaces = family == CellFamily::Tetrahedron ? 4 : family == CellFamily::Hexahedron ? 6 : 5;
    for (int l = 1; l <= 6; ++l)
    {
      const uv::IsoparametricLattice lattice(family, l);
      std::map<std::vector<int>, std::pair<int, bool>> faces; // count, on the boundary
      for (const uv::LatticeSubCell& cell : lattice.SubCells())
      {
        for (std::vector<int> face : Faces(cell))
        {
          const bool boundary = OnDomainBoundary(lattice, face);
          std::sort(face.begin(), face.end());
          faces[face].first++;
          faces[face].second = boundary;
        }
      }
      int boundaryFaces = 0, wrong = 0;
      for (const auto& face : faces)
      {
        boundaryFaces += face.second.second ? 1 : 0;
        wrong += face.second.first == (face.second.second ? 1 : 2) ? 0 : 1;
      }
      EXPECT_EQ(wrong, 0) << "level " << l;
      EXPECT_EQ(boundaryFaces, domainFaces * l * l) << "level " << l;
    }
  }
}

TEST(IsoparametricLattice, WeightsAreTheLinearBasisAtTheParametricCoords)
{
  for (CellFamily family : Families)
  {
    SCOPED_TRACE(Name(family));
    for (int l = 1; l <= 8; ++l)
    {
      const uv::IsoparametricLattice lattice(family, l);
      const double d = static_cast<double>(lattice.GetDenominator());
      const long long corners[8] = { 10, 11, 12, 13, 14, 15, 16, 17 };
      std::set<Key> keys;
      for (std::size_t p = 0; p < lattice.NumberOfPoints(); ++p)
      {
        const std::vector<double> basis = LinearBasis(family, lattice.ParametricCoords(p));
        std::int64_t sum = 0;
        for (int c = 0; c < uv::CornerCount(family); ++c)
        {
          EXPECT_NEAR(lattice.CornerWeights(p)[c] / d, basis[c], 1e-12);
          EXPECT_GE(lattice.CornerWeights(p)[c], 0);
          sum += lattice.CornerWeights(p)[c];
        }
        EXPECT_EQ(sum, lattice.GetDenominator());
        keys.insert(lattice.Key(p, corners));
      }
      EXPECT_EQ(keys.size(), lattice.NumberOfPoints()) << "two lattice points share a key";
    }
  }
  // The apex is one point, written as vtkPyramid lists it.
  const uv::IsoparametricLattice pyramid(CellFamily::Pyramid, 3);
  const Point apex = pyramid.ParametricCoords(static_cast<std::size_t>(pyramid.PointAt(0, 0, 3)));
  EXPECT_EQ(apex, (Point{ 0.0, 0.0, 1.0 }));
}

TEST(IsoparametricLattice, DegenerateCornersMergeInTheKey)
{
  const uv::IsoparametricLattice lattice(CellFamily::Hexahedron, 2);
  const long long collapsed[8] = { 0, 1, 2, 3, 4, 4, 4, 4 }; // the top face collapsed to one point
  const Key top = lattice.Key(static_cast<std::size_t>(lattice.PointAt(1, 1, 2)), collapsed);
  ASSERT_EQ(top.Size, 1);
  EXPECT_EQ(top.Corners[0], 4);
  EXPECT_EQ(top.Weights[0], lattice.GetDenominator());
}

TEST(IsoparametricLattice, SharedFacesGetIdenticalKeys)
{
  const Cell tet = { CellFamily::Tetrahedron, { 0, 1, 2, 3 } };
  // Face {1, 2, 3} from a second tet numbered differently.
  ExpectSameSubFaces(tet, { CellFamily::Tetrahedron, { 5, 3, 1, 2 } }, { 1, 2, 3 });
  // Face {0, 1, 2} as a wedge's bottom, and as another wedge's top.
  ExpectSameSubFaces(tet, { CellFamily::Wedge, { 2, 0, 1, 10, 11, 12 } }, { 0, 1, 2 });
  ExpectSameSubFaces(tet, { CellFamily::Wedge, { 10, 11, 12, 1, 2, 0 } }, { 0, 1, 2 });
  // Face {1, 2, 3} as a pyramid's side.
  ExpectSameSubFaces(tet, { CellFamily::Pyramid, { 1, 2, 30, 31, 3 } }, { 1, 2, 3 });

  const Cell hex = { CellFamily::Hexahedron, { 0, 1, 2, 3, 4, 5, 6, 7 } };
  // Quadrilateral {1, 2, 6, 5} as the wedge's face (2, 0, 3, 5).
  ExpectSameSubFaces(hex, { CellFamily::Wedge, { 1, 20, 2, 5, 21, 6 } }, { 1, 2, 5, 6 });
  // The top {4, 5, 6, 7} as a pyramid's base, rotated, and as another hexahedron's side.
  ExpectSameSubFaces(hex, { CellFamily::Pyramid, { 6, 7, 4, 5, 40 } }, { 4, 5, 6, 7 });
  ExpectSameSubFaces(hex, { CellFamily::Hexahedron, { 50, 4, 7, 51, 52, 5, 6, 53 } }, { 4, 5, 6, 7 });
  // A pyramid's side shared with a tet of the pyramid's own numbering.
  ExpectSameSubFaces({ CellFamily::Pyramid, { 0, 1, 2, 3, 4 } }, { CellFamily::Tetrahedron, { 3, 4, 2, 9 } },
    { 2, 3, 4 });
}
