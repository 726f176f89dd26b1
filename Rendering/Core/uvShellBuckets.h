// The barycentric shell mapper's CPU work per frame, free of VTK and OpenGL: each tetrahedron's range
// of eye distances, the shells that cut the space in front of the eye (spherical under perspective,
// planar slabs under parallel projection) and which cells each shell holds (the bucketing), each
// shell's rectangle on screen, and which shells hold nothing and are skipped. Unit-tested against a
// brute-force assignment in TestBarycentricShell.cxx.
#ifndef uvShellBuckets_h
#define uvShellBuckets_h

#include "uvScreenRectangle.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace uv
{

/// The range of eye distances a tetrahedron covers (eye space, eye at the origin): a lower bound and
/// its maximum. Under perspective |x| >= x.u for the unit u towards the centroid, and x.u is smallest
/// at a vertex; |x| is largest at one. Under parallel projection the depth -z, exact at the vertices.
inline void TetrahedronDistanceRange(const std::array<glm::vec3, 4>& v, bool parallel, float& low, float& high)
{
  if (parallel)
  {
    low = std::min({ -v[0].z, -v[1].z, -v[2].z, -v[3].z });
    high = std::max({ -v[0].z, -v[1].z, -v[2].z, -v[3].z });
    return;
  }
  const glm::vec3 centroid = 0.25f * (v[0] + v[1] + v[2] + v[3]);
  const float centroidLength = glm::length(centroid);
  high = 0.0f;
  low = std::numeric_limits<float>::infinity();
  for (const glm::vec3& p : v)
  {
    high = std::max(high, glm::length(p));
    low = centroidLength > 0.0f ? std::min(low, glm::dot(p, centroid) / centroidLength) : 0.0f;
  }
  low = std::max(low, 0.0f);
}

/// Cells (tetrahedron ids) and their eye-distance ranges, place by place.
struct RangedCells
{
  std::vector<std::uint32_t> const* Ids = nullptr;
  std::vector<float> Low, High;

  std::size_t Size() const { return this->Low.size(); }

  /// The ranges of `ids`, whose four point ids each are in `tetrahedronPoints`, from the points' eye
  /// positions. `parallelFor(count, function(begin, end))` runs it in chunks.
  template <typename ParallelFor>
  void Update(const std::vector<std::uint32_t>& ids, const std::vector<std::uint32_t>& tetrahedronPoints,
    const std::vector<glm::vec3>& eyePoints, bool parallel, ParallelFor&& parallelFor)
  {
    this->Ids = &ids;
    this->Low.resize(ids.size());
    this->High.resize(ids.size());
    parallelFor(ids.size(), [&](std::size_t begin, std::size_t end) {
      std::array<glm::vec3, 4> v;
      for (std::size_t i = begin; i < end; ++i)
      {
        for (int k = 0; k < 4; ++k)
          v[k] = eyePoints[tetrahedronPoints[4 * static_cast<std::size_t>(ids[i]) + k]];
        TetrahedronDistanceRange(v, parallel, this->Low[i], this->High[i]);
      }
    });
  }
};

/// Where the shells lie: shell s starts at Start(s) and is Thickness deep (Slices sample distances).
struct ShellLayout
{
  double First = 0.0;          ///< distance of shell 0's first slice: a whole multiple of SampleDistance
  double SampleDistance = 0.0; ///< as asked, or widened (Widened) so that no more than the maximum are needed
  double Thickness = 0.0;
  int Slices = 0; ///< sample distances per shell
  int Count = 0;
  bool Widened = false;

  /// The shell holding eye distance d; those before the first or after the last are clamped to them.
  int ShellOf(float d) const
  {
    return std::clamp(static_cast<int>(std::floor((d - this->First) / this->Thickness)), 0, this->Count - 1);
  }
  float Start(int shell) const { return static_cast<float>(this->First + shell * this->Slices * this->SampleDistance); }
  /// The margin a cell's range gets at both ends (a thousandth of a shell), so that rounding never
  /// leaves it out of a shell it touches.
  float Slack() const { return static_cast<float>(1e-3 * this->Thickness); }
};

/// Lays out shells of `slicesPerShell` sample distances over every range of `volume` and
/// `isosurface`, at most `maximumShells` of them (the sample distance is widened beyond: Widened).
/// Samples lie at whole multiples of the sample distance from the eye, the same places whatever the
/// nearest cell, so frames (and ranks of a parallel render, each with its own piece) agree. False
/// when there is no cell (nothing to draw).
inline bool LayoutShells(const RangedCells& volume, const RangedCells& isosurface, double sampleDistance,
  int slicesPerShell, int maximumShells, ShellLayout& layout)
{
  float nearest = std::numeric_limits<float>::infinity(), farthest = -nearest;
  for (const RangedCells* cells : { &volume, &isosurface })
  {
    for (float d : cells->Low)
      nearest = std::min(nearest, d);
    for (float d : cells->High)
      farthest = std::max(farthest, d);
  }
  layout = ShellLayout();
  if (!(farthest >= nearest))
  {
    return false;
  }
  double thickness = slicesPerShell * sampleDistance;
  if ((farthest - nearest) / thickness > maximumShells - 1)
  {
    thickness = (farthest - nearest) / (maximumShells - 1);
    sampleDistance = thickness / slicesPerShell;
    layout.Widened = true;
  }
  layout.First = std::floor(nearest / sampleDistance) * sampleDistance;
  layout.SampleDistance = sampleDistance;
  layout.Thickness = thickness;
  layout.Slices = slicesPerShell;
  layout.Count = std::max(1, static_cast<int>(std::ceil((farthest - layout.First) / thickness)));
  return true;
}

/// The box of a tetrahedron's four points on screen (`screenPoints`: normalised device coordinates,
/// NaN for a point not in front of the eye, which makes it the whole screen).
inline ScreenBox TetrahedronScreenBox(
  const std::vector<std::uint32_t>& tetrahedronPoints, std::uint32_t cell, const std::vector<glm::vec2>& screenPoints)
{
  ScreenBox box = EmptyScreenBox();
  for (int k = 0; k < 4; ++k)
  {
    const glm::vec2 p = screenPoints[tetrahedronPoints[4 * static_cast<std::size_t>(cell) + k]];
    if (!(p.x == p.x))
    {
      return WholeScreenBox();
    }
    box = UniteScreenBoxes(box, ScreenBox(p.x, p.y, p.x, p.y));
  }
  return box;
}

/// The volume cells each shell holds (a cell goes into every shell its range overlaps, with the
/// layout's slack at both ends), whether it holds an isosurface cell, and its screen box (the union
/// of those cells' boxes: its full-screen passes need cover no more).
class ShellBuckets
{
public:
  std::vector<std::uint32_t> Offsets; ///< Count() + 1: shell s holds Cells[Offsets[s], Offsets[s + 1])
  std::vector<std::uint32_t> Cells;   ///< volume cell ids, shell after shell, each shell in list order
  std::vector<unsigned char> HasIsosurface;
  std::vector<ScreenBox> Screen;
  std::uint64_t Version = 0; ///< bumped by every Update

  int Count() const { return static_cast<int>(this->Screen.size()); }
  std::uint32_t CellCount(int shell) const { return this->Offsets[shell + 1] - this->Offsets[shell]; }
  /// Nothing overlaps the shell: it is skipped.
  bool IsEmpty(int shell) const { return this->CellCount(shell) == 0 && !this->HasIsosurface[shell]; }
  int SkippedShells() const
  {
    int skipped = 0;
    for (int s = 0; s < this->Count(); ++s)
      skipped += this->IsEmpty(s) ? 1 : 0;
    return skipped;
  }

  /// `cellBox(id)` is cell id's ScreenBox (TetrahedronScreenBox).
  template <typename CellBox>
  void Update(
    const ShellLayout& layout, const RangedCells& volume, const RangedCells& isosurface, const CellBox& cellBox)
  {
    const int count = layout.Count;
    const float slack = layout.Slack();
    this->Offsets.assign(count + 1, 0);
    for (std::size_t i = 0; i < volume.Size(); ++i)
      for (int s = layout.ShellOf(volume.Low[i] - slack); s <= layout.ShellOf(volume.High[i] + slack); ++s)
        ++this->Offsets[s + 1];
    for (int s = 0; s < count; ++s)
      this->Offsets[s + 1] += this->Offsets[s];
    this->Cells.resize(this->Offsets[count]);
    this->Screen.assign(count, EmptyScreenBox());
    std::vector<std::uint32_t> fill(this->Offsets.begin(), this->Offsets.end() - 1);
    for (std::size_t i = 0; i < volume.Size(); ++i)
    {
      const std::uint32_t cell = (*volume.Ids)[i];
      const ScreenBox box = cellBox(cell);
      for (int s = layout.ShellOf(volume.Low[i] - slack); s <= layout.ShellOf(volume.High[i] + slack); ++s)
      {
        this->Cells[fill[s]++] = cell;
        this->Screen[s] = UniteScreenBoxes(this->Screen[s], box);
      }
    }
    this->HasIsosurface.assign(count, 0);
    for (std::size_t i = 0; i < isosurface.Size(); ++i)
    {
      const ScreenBox box = cellBox((*isosurface.Ids)[i]);
      for (int s = layout.ShellOf(isosurface.Low[i] - slack); s <= layout.ShellOf(isosurface.High[i] + slack); ++s)
      {
        this->HasIsosurface[s] = 1;
        this->Screen[s] = UniteScreenBoxes(this->Screen[s], box);
      }
    }
    ++this->Version;
  }
};

} // namespace uv

#endif
