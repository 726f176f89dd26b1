// Which cells' volumes overlap where a mesh folds (uv::IsTangledHexahedron), free of VTK. The
// hexahedral walk holds one cell at each point of a ray; where cells overlap, the reference's medium
// is their superposition (uv::IntegrateOverlap). So each cell carries the list of cells it overlaps,
// and the walk adds those partners' media wherever they claim a point of its segment.
//
// Only folded cells make overlaps here: a pair counts when one of its cells is folded. A mesh whose
// unfolded cells interpenetrate (two separate layers pushed through each other) is not searched.
#ifndef uvOverlappingCells_h
#define uvOverlappingCells_h

#include "uvHexahedralMesh.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <utility>
#include <vector>

namespace uv
{

/// Per cell, the cells whose volume overlaps its own (both ways), as compressed rows: cell c's
/// partners are Cells[Offsets[c]] up to Cells[Offsets[c + 1]].
struct OverlapPartners
{
  std::vector<std::uint32_t> Offsets; // cells + 1 entries
  std::vector<std::uint32_t> Cells;

  std::size_t PairCount() const { return this->Cells.size() / 2; }

  /// The GPU layout: the offsets, each shifted past them, then the partners (one int each).
  std::vector<std::int32_t> Packed() const
  {
    std::vector<std::int32_t> packed;
    packed.reserve(this->Offsets.size() + this->Cells.size());
    const auto shift = static_cast<std::int64_t>(this->Offsets.size());
    for (std::uint32_t offset : this->Offsets)
      packed.push_back(static_cast<std::int32_t>(shift + offset));
    packed.insert(packed.end(), this->Cells.begin(), this->Cells.end());
    return packed;
  }
};

/// Whether the cell with corners p claims x as the reference does: Newton from its centre converges
/// to coordinates in the unit cube grown by `margin` (shrunk where negative).
inline bool ClaimsPointFromCentre(const glm::dvec3 p[8], const glm::dvec3& x, double margin)
{
  glm::dvec3 xi(0.5);
  return InverseTrilinear(p, x, xi) && InUnitCube(xi, margin);
}

/// Whether some point of a lattice of samples^3 points inside cell a (mapped from coordinates
/// (i + 1/2) / samples) is claimed by both a and b, b with a margin that a shared face's rounding
/// does not reach. An overlap thinner than the lattice's spacing may be missed.
inline bool LatticeOfOneInOther(const glm::dvec3 a[8], const glm::dvec3 b[8], int samples)
{
  for (int i = 0; i < samples; ++i)
    for (int j = 0; j < samples; ++j)
      for (int k = 0; k < samples; ++k)
      {
        const glm::dvec3 xi = (glm::dvec3(i, j, k) + 0.5) / double(samples);
        const double r = xi.x, s = xi.y, t = xi.z;
        const glm::dvec3 x = (1 - t) * ((1 - s) * ((1 - r) * a[0] + r * a[1]) + s * ((1 - r) * a[3] + r * a[2])) +
          t * ((1 - s) * ((1 - r) * a[4] + r * a[5]) + s * ((1 - r) * a[7] + r * a[6]));
        if (ClaimsPointFromCentre(b, x, -1e-6) && ClaimsPointFromCentre(a, x, 1e-9))
          return true;
      }
  return false;
}

/// Whether the volumes of cells a and b overlap, sampled both ways (LatticeOfOneInOther).
inline bool CellsOverlap(const glm::dvec3 a[8], const glm::dvec3 b[8], int samples)
{
  return LatticeOfOneInOther(a, b, samples) || LatticeOfOneInOther(b, a, samples);
}

struct CellBox
{
  glm::dvec3 Low{ 0.0 }, High{ 0.0 };

  explicit CellBox(const glm::dvec3 p[8])
    : Low(p[0])
    , High(p[0])
  {
    for (int k = 1; k < 8; ++k)
    {
      this->Low = glm::min(this->Low, p[k]);
      this->High = glm::max(this->High, p[k]);
    }
  }
  bool Meets(const CellBox& other) const
  {
    return glm::all(glm::lessThanEqual(this->Low, other.High)) && glm::all(glm::lessThanEqual(other.Low, this->High));
  }
};

namespace detail
{
/// The folded cells' boxes in a uniform grid of bins over their union (about one cell per bin), so
/// that each cell of the mesh meets only the folded cells near it.
class FoldedCellBins
{
public:
  FoldedCellBins(std::vector<std::uint32_t> cells, std::vector<CellBox> boxes)
    : Cells(std::move(cells))
    , Boxes(std::move(boxes))
    , Union(this->Boxes.front())
  {
    for (const CellBox& box : this->Boxes)
    {
      this->Union.Low = glm::min(this->Union.Low, box.Low);
      this->Union.High = glm::max(this->Union.High, box.High);
    }
    this->PerAxis = std::clamp(static_cast<int>(std::cbrt(double(this->Cells.size()))), 1, 64);
    this->Bins.resize(static_cast<std::size_t>(this->PerAxis) * this->PerAxis * this->PerAxis);
    for (std::size_t i = 0; i < this->Boxes.size(); ++i)
      this->ForBinsOf(this->Boxes[i], [&](std::size_t bin) { this->Bins[bin].push_back(i); });
  }

  /// Calls found(folded cell, its box) for each folded cell whose box meets `box` (once each).
  template <typename Found>
  void ForFoldedCellsMeeting(const CellBox& box, std::vector<std::size_t>& scratch, Found&& found) const
  {
    if (!box.Meets(this->Union))
      return;
    scratch.clear();
    this->ForBinsOf(box, [&](std::size_t bin) { scratch.insert(scratch.end(), this->Bins[bin].begin(), this->Bins[bin].end()); });
    std::sort(scratch.begin(), scratch.end());
    scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
    for (std::size_t i : scratch)
      if (this->Boxes[i].Meets(box))
        found(this->Cells[i]);
  }

private:
  std::vector<std::uint32_t> Cells;
  std::vector<CellBox> Boxes;
  CellBox Union;
  int PerAxis = 1;
  std::vector<std::vector<std::size_t>> Bins;

  template <typename Visit>
  void ForBinsOf(const CellBox& box, Visit&& visit) const
  {
    glm::ivec3 low, high;
    const glm::dvec3 size = glm::max(this->Union.High - this->Union.Low, glm::dvec3(1e-300));
    for (int axis = 0; axis < 3; ++axis)
    {
      auto bin = [&](double x) {
        const double f = (x - this->Union.Low[axis]) / size[axis] * this->PerAxis;
        return std::clamp(static_cast<int>(std::floor(f)), 0, this->PerAxis - 1);
      };
      low[axis] = bin(box.Low[axis]);
      high[axis] = bin(box.High[axis]);
    }
    for (int z = low.z; z <= high.z; ++z)
      for (int y = low.y; y <= high.y; ++y)
        for (int x = low.x; x <= high.x; ++x)
          visit(static_cast<std::size_t>((z * this->PerAxis + y) * this->PerAxis + x));
  }
};
} // namespace detail

/// The overlap partners of every cell (empty rows where the mesh has no folded cell): each folded
/// cell against every cell whose box meets its own, tested by CellsOverlap with `samples` per axis.
/// `parallelFor` as ClassifyHexahedra's.
template <typename ParallelFor>
OverlapPartners FindOverlapPartners(const std::vector<std::uint32_t>& cellPoints, const std::vector<float>& pointData,
  ParallelFor&& parallelFor, int samples = 6)
{
  const std::size_t cellCount = cellPoints.size() / 8;
  const std::vector<unsigned char> folded = ClassifyHexahedra(cellPoints, pointData, parallelFor,
    [](const glm::dvec3* p, const std::uint32_t*) { return static_cast<unsigned char>(IsTangledHexahedron(p)); });
  std::vector<std::uint32_t> foldedCells;
  std::vector<CellBox> boxes;
  for (std::size_t c = 0; c < cellCount; ++c)
  {
    if (!folded[c])
      continue;
    glm::dvec3 p[8];
    HexahedronCornerPoints(cellPoints, pointData, c, p);
    foldedCells.push_back(static_cast<std::uint32_t>(c));
    boxes.emplace_back(p);
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  if (!foldedCells.empty())
  {
    const detail::FoldedCellBins bins(std::move(foldedCells), std::move(boxes));
    std::mutex joining;
    parallelFor(cellCount, [&](std::size_t begin, std::size_t end) {
      std::vector<std::pair<std::uint32_t, std::uint32_t>> found;
      std::vector<std::size_t> scratch;
      glm::dvec3 p[8], q[8];
      for (std::size_t c = begin; c < end; ++c)
      {
        HexahedronCornerPoints(cellPoints, pointData, c, p);
        bins.ForFoldedCellsMeeting(CellBox(p), scratch, [&](std::uint32_t f) {
          HexahedronCornerPoints(cellPoints, pointData, f, q);
          if (f != c && CellsOverlap(p, q, samples))
          {
            found.emplace_back(static_cast<std::uint32_t>(c), f);
            found.emplace_back(f, static_cast<std::uint32_t>(c));
          }
        });
      }
      const std::lock_guard<std::mutex> lock(joining);
      pairs.insert(pairs.end(), found.begin(), found.end());
    });
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  OverlapPartners partners;
  partners.Offsets.assign(cellCount + 1, 0);
  for (const auto& pair : pairs)
    ++partners.Offsets[pair.first + 1];
  for (std::size_t c = 0; c < cellCount; ++c)
    partners.Offsets[c + 1] += partners.Offsets[c];
  for (const auto& pair : pairs)
    partners.Cells.push_back(pair.second);
  return partners;
}

/// The faces between two cells of every cell with overlap partners that `keep(cell)` selects (cell,
/// local face, 0, 0 each, as HexahedralFaces::Boundary lists boundary faces). A fold can push a cell
/// through the mesh's boundary, and a ray then enters the mesh through such a face before any
/// boundary face: the entry pass draws these faces too.
template <typename Keep>
std::vector<std::int32_t> FacesOfOverlappingCells(
  const OverlapPartners& partners, const std::vector<std::int32_t>& neighbours, Keep&& keep)
{
  std::vector<std::int32_t> faces;
  for (std::size_t c = 0; c + 1 < partners.Offsets.size(); ++c)
  {
    if (partners.Offsets[c + 1] == partners.Offsets[c] || !keep(c))
      continue;
    for (int f = 0; f < 6; ++f)
      if (neighbours[8 * c + f] >= 0)
        faces.insert(faces.end(), { static_cast<std::int32_t>(c), f, 0, 0 });
  }
  return faces;
}

} // namespace uv

#endif
