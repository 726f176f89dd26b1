// The part of a hexahedral mesh a transfer function leaves visible, for the ray caster: its
// boundary faces (the mesh's own faces of visible cells, and the faces between a visible and an
// invisible cell). Rays enter at the front of the visible matter (space leaping), end a few
// invisible cells after leaving it (exit-based leaping), cost nothing where no visible cell lies on
// them (empty rays), and leap over invisible runs inside the mesh by peeling on to the region's
// next entry face. These are the culling surfaces of Xue, Zhang and Crawfis's iSBVR, made of whole
// cells as the paper "inflates" its isosurface, so nothing visible is culled: a cell is visible when
// its scalar range meets non-zero extinction or holds an isovalue (uvCellVisibility.h). The walk
// itself keeps the mesh's own neighbours: where a ray only grazes an invisible cell between visible
// ones, rasterisation may put its pixel on the other side of the fold's edge, so no entry face would
// pick the ray up again; walking on through the grazed cell keeps it. VTK-free.
#ifndef uvVisibleRegion_h
#define uvVisibleRegion_h

#include "uvCellVisibility.h"
#include "uvHexahedralMesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace uv
{
/// Per cell, the range of its scalar: its corners' for a point scalar (a trilinear field, and a
/// collapsed one, takes its extremes at the corners), or a cell scalar's value, widened to its face
/// neighbours' values when `widenToNeighbours` (a cell scalar's isosurfaces lie on the faces between
/// cells, so both cells beside such a face must stay). `pointValues` holds 4 floats per point, the
/// scalar last; `neighbours` is HexahedralFaces::Neighbours.
template <typename ParallelFor>
void HexahedralCellRanges(const std::vector<std::uint32_t>& cellPoints, const std::vector<float>& pointValues,
  const std::vector<float>& cellScalars, const std::vector<std::int32_t>& neighbours, bool widenToNeighbours,
  std::vector<float>& low, std::vector<float>& high, ParallelFor&& parallelFor)
{
  const std::size_t cellCount = cellPoints.size() / 8;
  low.resize(cellCount);
  high.resize(cellCount);
  parallelFor(cellCount, [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c)
    {
      float a, b;
      if (cellScalars.empty())
      {
        a = b = pointValues[4 * cellPoints[8 * c] + 3];
        for (int k = 1; k < 8; ++k)
        {
          const float value = pointValues[4 * cellPoints[8 * c + k] + 3];
          a = std::min(a, value);
          b = std::max(b, value);
        }
      }
      else
      {
        a = b = cellScalars[c];
        for (int f = 0; f < 6 && widenToNeighbours; ++f)
        {
          const std::int32_t neighbour = neighbours[8 * c + f];
          if (neighbour < 0)
            continue;
          a = std::min(a, cellScalars[neighbour / 8]);
          b = std::max(b, cellScalars[neighbour / 8]);
        }
      }
      low[c] = a;
      high[c] = b;
    }
  });
}

struct VisibleRegion
{
  std::vector<std::int32_t> Boundary;   ///< as HexahedralFaces::Boundary: (cell, local face, 0, 0)
  std::size_t VisibleCells = 0;

  std::size_t BoundaryCount() const { return this->Boundary.size() / 4; }
};

/// The region of the cells flagged `visible` (one byte per cell, non-zero: visible).
inline VisibleRegion MakeVisibleRegion(const HexahedralFaces& faces, const std::vector<unsigned char>& visible)
{
  VisibleRegion region;
  // The mesh's boundary faces of visible cells, then the faces the region cut (a face a visible
  // cell shares with an invisible one).
  for (std::size_t i = 0; i + 3 < faces.Boundary.size(); i += 4)
    if (visible[faces.Boundary[i]])
      region.Boundary.insert(region.Boundary.end(), faces.Boundary.begin() + i, faces.Boundary.begin() + i + 4);
  for (std::size_t c = 0; c < visible.size(); ++c)
  {
    if (!visible[c])
      continue;
    ++region.VisibleCells;
    for (int f = 0; f < 6; ++f)
    {
      const std::int32_t neighbour = faces.Neighbours[8 * c + f];
      if (neighbour >= 0 && !visible[neighbour / 8])
        region.Boundary.insert(region.Boundary.end(), { static_cast<std::int32_t>(c), f, 0, 0 });
    }
  }
  return region;
}

/// Per cell, whether it is visible: its range [low, high] meets non-zero extinction (`zeroSet`:
/// ZeroExtinctionIntervals) or holds one of `sortedIsovalues`.
template <typename ParallelFor>
std::vector<unsigned char> VisibleCells(const std::vector<float>& low, const std::vector<float>& high,
  const std::vector<std::pair<double, double>>& zeroSet, const std::vector<double>& sortedIsovalues,
  ParallelFor&& parallelFor)
{
  std::vector<unsigned char> visible(low.size(), 0);
  parallelFor(low.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c)
      visible[c] = RoleOf(low[c], high[c], zeroSet, sortedIsovalues) != 0 ? 1 : 0;
  });
  return visible;
}
/// A box holding every visible cell's corners (low x, y, z, then high), widened by a little more
/// than float rounding, so that a ray past it meets no visible cell again; where no cell is visible,
/// the point at the origin. `pointValues` holds 4 floats per point, the position first.
inline std::array<float, 6> BoxOfCells(const std::vector<std::uint32_t>& cellPoints,
  const std::vector<float>& pointValues, const std::vector<unsigned char>& visible)
{
  std::array<float, 6> box = { HUGE_VALF, HUGE_VALF, HUGE_VALF, -HUGE_VALF, -HUGE_VALF, -HUGE_VALF };
  for (std::size_t c = 0; c < visible.size(); ++c)
  {
    if (!visible[c])
      continue;
    for (int k = 0; k < 8; ++k)
    {
      const float* p = &pointValues[4 * std::size_t(cellPoints[8 * c + k])];
      for (int i = 0; i < 3; ++i)
      {
        box[i] = std::min(box[i], p[i]);
        box[3 + i] = std::max(box[3 + i], p[i]);
      }
    }
  }
  if (!(box[0] <= box[3]))
    return {};
  float extent = 0.0f;
  for (int i = 0; i < 3; ++i)
    extent = std::max({ extent, box[3 + i] - box[i], std::abs(box[i]), std::abs(box[3 + i]) });
  const float margin = 1e-5f * extent;
  for (int i = 0; i < 3; ++i)
  {
    box[i] -= margin;
    box[3 + i] += margin;
  }
  return box;
}
} // namespace uv

#endif
