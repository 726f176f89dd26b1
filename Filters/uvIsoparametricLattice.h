// Lattices of one subdivision level L on VTK's 3D cell families, the linear sub-cells that fill
// them, and keys that let neighbouring cells share the lattice points of a common face or edge.
// Free of VTK so it can be tested alone.
//
// Lattice points have integer indices (i, j, k) and a reference position (i, j, k) / L in a straight
// cell of the family:
//   tetrahedron  i, j, k >= 0, i + j + k <= L (the reference is VTK's parametric tet);
//   hexahedron   0 <= i, j, k <= L (the unit cube);
//   wedge        the triangle lattice i + j <= L times the layers k = 0..L;
//   pyramid      layers k = 0..L of (L - k + 1)^2 points, 0 <= i, j <= L - k. The reference pyramid
//                has its base [0,1]^2 at z = 0 and its apex (0,0,1) above corner 0; it is a shear of
//                VTK's pyramid with the apex above the base centre, so every sub-cell is straight.
// Parametric coordinates are VTK's: the reference position for tet, hexahedron and wedge; for the
// pyramid, VTK's collapsed-cube (r, s, t) with t = z, r = x / (1 - z), s = y / (1 - z) (the apex
// any (r, s) at t = 1; we use (0, 0, 1) as vtkPyramid lists it).
//
// Sub-cells, in VTK's linear corner order and oriented as the parent's reference:
//   hexahedron   L^3 hexahedra;
//   wedge        L^2 triangles (upright (i,j),(i+1,j),(i,j+1) and inverted (i+1,j),(i+1,j+1),(i,j+1),
//                both turning as the parent's corners 0,1,2) times L layers: L^3 wedges;
//   tetrahedron  per lattice point the upright tet (i+j+k <= L-1), the octahedron between
//                a=(i+1,j,k), b=(i,j+1,k), c=(i,j,k+1), d=(i+1,j+1,k), e=(i+1,j,k+1), f=(i,j+1,k+1)
//                (i+j+k <= L-2) cut along a-f into four tets, and the inverted tet d,e,f,(i+1,j+1,k+1)
//                (i+j+k <= L-3): L^3 tets;
//   pyramid      per layer of m = L - k points a side: m^2 upright pyramids (base (i..i+1, j..j+1) on
//                layer k, apex (i,j) on layer k+1), (m-1)^2 inverted pyramids (the square on layer
//                k+1, apex (i+1,j+1) on layer k) and 2m(m-1) tets in the gaps: L(4L^2-1)/3 cells.
// Every face of the domain is cut as its intrinsic lattice: a triangle into the triangles of its
// three line families, a quadrilateral into its square grid. Two cells of any families sharing a
// face at the same L therefore cut it into the same sub-faces (the pyramid too: triangles on its
// sides, squares on its base).
//
// Conforming keys: a lattice point written through the linear weights of the cell's corners
// (barycentric, trilinear, the linear wedge or pyramid basis) is the same point whichever cell of a
// shared face or edge writes it, and whatever that cell's local numbering. The weights are rational
// with denominators dividing L^2 lcm(1..L), so they are kept exactly as integers over that
// denominator; a key is the level plus the sorted (global corner id, weight) pairs with zero weights
// dropped (corners repeated in a degenerate cell summed).
#ifndef uvIsoparametricLattice_h
#define uvIsoparametricLattice_h

#include "uvCellFamily.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <numeric>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

namespace uv
{

/// Highest supported level: keeps L^2 lcm(1..L) well inside 64 bits and the sub-cell count sane.
constexpr int MaxLatticeLevel = 16;

inline int CornerCount(CellFamily family)
{
  switch (family)
  {
    case CellFamily::Tetrahedron:
      return 4;
    case CellFamily::Hexahedron:
      return 8;
    case CellFamily::Wedge:
      return 6;
    default:
      return 5;
  }
}

/// Denominator of the integer corner weights at level L.
inline std::int64_t KeyDenominator(int level)
{
  std::int64_t lcm = 1;
  for (int n = 2; n <= level; ++n)
  {
    lcm = lcm / std::gcd(lcm, static_cast<std::int64_t>(n)) * n;
  }
  return static_cast<std::int64_t>(level) * level * lcm;
}

/// VTK's parametric coordinates of a reference position of the family (see the file comment).
inline std::array<double, 3> ParametricCoordsOf(CellFamily family, const std::array<double, 3>& reference)
{
  if (family != CellFamily::Pyramid)
  {
    return reference;
  }
  const double below = 1.0 - reference[2];
  if (below <= 0.0)
  {
    return { 0.0, 0.0, 1.0 };
  }
  return { reference[0] / below, reference[1] / below, reference[2] };
}

/// A linear sub-cell: 4 (tet), 5 (pyramid), 6 (wedge) or 8 (hexahedron) lattice point indices.
struct LatticeSubCell
{
  int Size = 0;
  std::array<int, 8> Points{};
};

template <typename IdType>
struct LatticeKey
{
  int Level = 0;
  int Size = 0;
  std::array<IdType, 8> Corners{};
  std::array<std::int64_t, 8> Weights{};

  bool operator==(const LatticeKey& other) const
  {
    return this->Level == other.Level && this->Size == other.Size &&
      std::equal(this->Corners.begin(), this->Corners.begin() + this->Size, other.Corners.begin()) &&
      std::equal(this->Weights.begin(), this->Weights.begin() + this->Size, other.Weights.begin());
  }
  bool operator<(const LatticeKey& other) const
  {
    const auto tie = [](const LatticeKey& key) {
      return std::make_tuple(key.Level, key.Size, key.Corners, key.Weights);
    };
    return tie(*this) < tie(other);
  }
};

template <typename IdType>
struct LatticeKeyHash
{
  std::size_t operator()(const LatticeKey<IdType>& key) const
  {
    std::size_t h = std::hash<int>()(key.Level);
    for (int n = 0; n < key.Size; ++n)
    {
      h = h * 1000003u ^ std::hash<IdType>()(key.Corners[n]);
      h = h * 1000003u ^ std::hash<std::int64_t>()(key.Weights[n]);
    }
    return h;
  }
};

class IsoparametricLattice
{
public:
  IsoparametricLattice(CellFamily family, int level)
    : Family(family)
    , Level(level)
    , Denominator(KeyDenominator(level))
  {
    if (level < 1 || level > MaxLatticeLevel)
    {
      throw std::invalid_argument("lattice level out of range");
    }
    this->BuildPoints();
    this->BuildSubCells();
    this->BuildEdges();
  }

  CellFamily GetFamily() const { return this->Family; }
  int GetLevel() const { return this->Level; }
  std::int64_t GetDenominator() const { return this->Denominator; }
  std::size_t NumberOfPoints() const { return this->Indices.size(); }
  const std::array<int, 3>& Index(std::size_t point) const { return this->Indices[point]; }
  std::array<double, 3> Reference(std::size_t point) const
  {
    const std::array<int, 3>& index = this->Indices[point];
    const double l = this->Level;
    return { index[0] / l, index[1] / l, index[2] / l };
  }
  std::array<double, 3> ParametricCoords(std::size_t point) const
  {
    return ParametricCoordsOf(this->Family, this->Reference(point));
  }
  /// Linear corner weights of a point, as integers over GetDenominator().
  const std::array<std::int64_t, 8>& CornerWeights(std::size_t point) const { return this->Weights[point]; }
  const std::vector<LatticeSubCell>& SubCells() const { return this->Cells; }
  /// The distinct edges of the sub-cells, each as (smaller, larger) point index.
  const std::vector<std::array<int, 2>>& Edges() const { return this->EdgeList; }
  /// Point index of lattice indices (i, j, k), or -1 outside the lattice.
  int PointAt(int i, int j, int k) const
  {
    if (!this->Inside(i, j, k))
    {
      return -1;
    }
    const std::size_t at = (static_cast<std::size_t>(k) * (this->Level + 1) + j) * (this->Level + 1) + i;
    return this->Lookup[at];
  }

  /// The conforming key of a point given the global ids of the cell's corners (VTK corner order).
  template <typename IdType>
  LatticeKey<IdType> Key(std::size_t point, const IdType* cornerIds) const
  {
    LatticeKey<IdType> key;
    key.Level = this->Level;
    std::array<std::pair<IdType, std::int64_t>, 8> terms;
    int count = 0;
    for (int c = 0; c < CornerCount(this->Family); ++c)
    {
      if (this->Weights[point][c] != 0)
      {
        terms[count++] = { cornerIds[c], this->Weights[point][c] };
      }
    }
    std::sort(terms.begin(), terms.begin() + count);
    for (int n = 0; n < count; ++n)
    {
      if (key.Size > 0 && key.Corners[key.Size - 1] == terms[n].first)
      {
        key.Weights[key.Size - 1] += terms[n].second; // a corner repeated in a degenerate cell
        continue;
      }
      key.Corners[key.Size] = terms[n].first;
      key.Weights[key.Size] = terms[n].second;
      ++key.Size;
    }
    return key;
  }

private:
  bool Inside(int i, int j, int k) const
  {
    const int l = this->Level;
    if (i < 0 || j < 0 || k < 0 || i > l || j > l || k > l)
    {
      return false;
    }
    switch (this->Family)
    {
      case CellFamily::Tetrahedron:
        return i + j + k <= l;
      case CellFamily::Wedge:
        return i + j <= l;
      case CellFamily::Pyramid:
        return i + k <= l && j + k <= l;
      default:
        return true;
    }
  }

  std::array<std::int64_t, 8> WeightsAt(int i, int j, int k) const
  {
    const std::int64_t l = this->Level, d = this->Denominator;
    std::array<std::int64_t, 8> w{};
    switch (this->Family)
    {
      case CellFamily::Tetrahedron:
        w = { (l - i - j - k) * (d / l), i * (d / l), j * (d / l), k * (d / l) };
        break;
      case CellFamily::Hexahedron:
      {
        const std::int64_t unit = d / (l * l * l);
        const std::int64_t x[2] = { l - i, i }, y[2] = { l - j, j }, z[2] = { l - k, k };
        // VTK's corner order: counter-clockwise in z = 0, then z = 1.
        const int bx[8] = { 0, 1, 1, 0, 0, 1, 1, 0 }, by[8] = { 0, 0, 1, 1, 0, 0, 1, 1 };
        for (int c = 0; c < 8; ++c)
        {
          w[c] = x[bx[c]] * y[by[c]] * z[c / 4] * unit;
        }
        break;
      }
      case CellFamily::Wedge:
      {
        const std::int64_t unit = d / (l * l);
        const std::int64_t triangle[3] = { l - i - j, i, j }, layer[2] = { l - k, k };
        for (int c = 0; c < 6; ++c)
        {
          w[c] = triangle[c % 3] * layer[c / 3] * unit;
        }
        break;
      }
      case CellFamily::Pyramid:
      {
        const std::int64_t m = l - k; // points a side on this layer, less one
        w[4] = k * (d / l);
        if (m > 0)
        {
          const std::int64_t unit = d / (l * m);
          w[0] = (m - i) * (m - j) * unit;
          w[1] = i * (m - j) * unit;
          w[2] = i * j * unit;
          w[3] = (m - i) * j * unit;
        }
        break;
      }
    }
    return w;
  }

  void BuildPoints()
  {
    const int l = this->Level;
    this->Lookup.assign(static_cast<std::size_t>(l + 1) * (l + 1) * (l + 1), -1);
    for (int k = 0; k <= l; ++k)
    {
      for (int j = 0; j <= l; ++j)
      {
        for (int i = 0; i <= l; ++i)
        {
          if (this->Inside(i, j, k))
          {
            this->Lookup[(static_cast<std::size_t>(k) * (l + 1) + j) * (l + 1) + i] =
              static_cast<int>(this->Indices.size());
            this->Indices.push_back({ i, j, k });
            this->Weights.push_back(this->WeightsAt(i, j, k));
          }
        }
      }
    }
  }

  void Add(std::initializer_list<std::array<int, 3>> corners)
  {
    LatticeSubCell cell;
    for (const std::array<int, 3>& c : corners)
    {
      cell.Points[cell.Size++] = this->PointAt(c[0], c[1], c[2]);
    }
    this->Cells.push_back(cell);
  }

  /// A tet of the lattice, turned positive in the reference (the parent's orientation).
  void AddTet(const std::array<int, 3>& a, const std::array<int, 3>& b, const std::array<int, 3>& c,
    const std::array<int, 3>& d)
  {
    std::array<int, 3> u, v, w;
    for (int n = 0; n < 3; ++n)
    {
      u[n] = b[n] - a[n];
      v[n] = c[n] - a[n];
      w[n] = d[n] - a[n];
    }
    const int six = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
      u[2] * (v[0] * w[1] - v[1] * w[0]);
    if (six > 0)
    {
      this->Add({ a, b, c, d });
    }
    else
    {
      this->Add({ a, c, b, d });
    }
  }

  void BuildSubCells()
  {
    switch (this->Family)
    {
      case CellFamily::Tetrahedron:
        this->BuildTetrahedra();
        break;
      case CellFamily::Hexahedron:
        this->BuildHexahedra();
        break;
      case CellFamily::Wedge:
        this->BuildWedges();
        break;
      case CellFamily::Pyramid:
        this->BuildPyramids();
        break;
    }
  }

  void BuildTetrahedra()
  {
    const int l = this->Level;
    for (const std::array<int, 3>& p : this->Indices)
    {
      const int i = p[0], j = p[1], k = p[2], sum = i + j + k;
      const std::array<int, 3> a = { i + 1, j, k }, b = { i, j + 1, k }, c = { i, j, k + 1 },
                               d = { i + 1, j + 1, k }, e = { i + 1, j, k + 1 }, f = { i, j + 1, k + 1 };
      if (sum <= l - 1)
      {
        this->AddTet(p, a, b, c);
      }
      if (sum <= l - 2)
      {
        this->AddTet(a, f, b, d);
        this->AddTet(a, f, d, e);
        this->AddTet(a, f, e, c);
        this->AddTet(a, f, c, b);
      }
      if (sum <= l - 3)
      {
        this->AddTet(d, e, f, { i + 1, j + 1, k + 1 });
      }
    }
  }

  void BuildHexahedra()
  {
    const int l = this->Level;
    for (int k = 0; k < l; ++k)
    {
      for (int j = 0; j < l; ++j)
      {
        for (int i = 0; i < l; ++i)
        {
          this->Add({ { i, j, k }, { i + 1, j, k }, { i + 1, j + 1, k }, { i, j + 1, k }, { i, j, k + 1 },
            { i + 1, j, k + 1 }, { i + 1, j + 1, k + 1 }, { i, j + 1, k + 1 } });
        }
      }
    }
  }

  void BuildWedges()
  {
    const int l = this->Level;
    for (int k = 0; k < l; ++k)
    {
      for (int j = 0; j < l; ++j)
      {
        for (int i = 0; i + j < l; ++i)
        {
          this->Add({ { i, j, k }, { i + 1, j, k }, { i, j + 1, k }, { i, j, k + 1 }, { i + 1, j, k + 1 },
            { i, j + 1, k + 1 } });
          if (i + j + 2 <= l)
          {
            this->Add({ { i + 1, j, k }, { i + 1, j + 1, k }, { i, j + 1, k }, { i + 1, j, k + 1 },
              { i + 1, j + 1, k + 1 }, { i, j + 1, k + 1 } });
          }
        }
      }
    }
  }

  void BuildPyramids()
  {
    const int l = this->Level;
    for (int k = 0; k < l; ++k)
    {
      const int m = l - k;
      for (int j = 0; j < m; ++j)
      {
        for (int i = 0; i < m; ++i)
        {
          this->Add({ { i, j, k }, { i + 1, j, k }, { i + 1, j + 1, k }, { i, j + 1, k }, { i, j, k + 1 } });
          if (i + 1 < m && j + 1 < m)
          {
            // Counter-clockwise as seen from its apex below.
            this->Add({ { i, j, k + 1 }, { i, j + 1, k + 1 }, { i + 1, j + 1, k + 1 }, { i + 1, j, k + 1 },
              { i + 1, j + 1, k } });
          }
          if (i + 1 < m)
          {
            this->AddTet({ i + 1, j, k }, { i + 1, j + 1, k }, { i, j, k + 1 }, { i + 1, j, k + 1 });
          }
          if (j + 1 < m)
          {
            this->AddTet({ i, j + 1, k }, { i + 1, j + 1, k }, { i, j, k + 1 }, { i, j + 1, k + 1 });
          }
        }
      }
    }
  }

  void BuildEdges()
  {
    static const std::vector<std::array<int, 2>> tet = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 },
      { 2, 3 } };
    static const std::vector<std::array<int, 2>> pyramid = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 },
      { 0, 4 }, { 1, 4 }, { 2, 4 }, { 3, 4 } };
    static const std::vector<std::array<int, 2>> wedge = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 3, 4 },
      { 4, 5 }, { 5, 3 }, { 0, 3 }, { 1, 4 }, { 2, 5 } };
    static const std::vector<std::array<int, 2>> hexahedron = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 },
      { 4, 5 }, { 5, 6 }, { 6, 7 }, { 7, 4 }, { 0, 4 }, { 1, 5 }, { 2, 6 }, { 3, 7 } };
    for (const LatticeSubCell& cell : this->Cells)
    {
      const std::vector<std::array<int, 2>>& local =
        cell.Size == 4 ? tet : cell.Size == 5 ? pyramid : cell.Size == 6 ? wedge : hexahedron;
      for (const std::array<int, 2>& e : local)
      {
        const int a = cell.Points[e[0]], b = cell.Points[e[1]];
        this->EdgeList.push_back({ std::min(a, b), std::max(a, b) });
      }
    }
    std::sort(this->EdgeList.begin(), this->EdgeList.end());
    this->EdgeList.erase(std::unique(this->EdgeList.begin(), this->EdgeList.end()), this->EdgeList.end());
  }

  CellFamily Family;
  int Level;
  std::int64_t Denominator;
  std::vector<std::array<int, 3>> Indices;
  std::vector<std::array<std::int64_t, 8>> Weights;
  std::vector<int> Lookup;
  std::vector<LatticeSubCell> Cells;
  std::vector<std::array<int, 2>> EdgeList;
};

} // namespace uv

#endif
