// Which cells a transfer function makes invisible: a cell whose whole scalar range lies where the
// extinction is zero, and that holds no isovalue, adds nothing to any ray and need not be drawn.
// VTK-free (unit-tested with the rest of the math); every mapper decides visibility with it.
#ifndef uvCellVisibility_h
#define uvCellVisibility_h

#include "uvOpticalModel.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

namespace uv
{

/// Closed intervals of normalised scalar where the extinction is zero: the set that decides which
/// tetrahedra are invisible.
inline std::vector<std::pair<double, double>> ZeroExtinctionIntervals(const std::vector<TransferFunction::Node>& nodes)
{
  std::vector<std::pair<double, double>> intervals;
  const double infinity = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    if (nodes[i].Extinction > 0.0)
      continue;
    const double begin = i == 0 ? -infinity : nodes[i].Scalar;
    std::size_t j = i;
    while (j + 1 < nodes.size() && nodes[j + 1].Extinction <= 0.0)
      ++j;
    const double end = j + 1 == nodes.size() ? infinity : nodes[j].Scalar;
    intervals.emplace_back(begin, end);
    i = j;
  }
  return intervals;
}

/// True when one zero-extinction interval holds the whole scalar range [low, high].
inline bool RangeHasZeroExtinction(double low, double high, const std::vector<std::pair<double, double>>& zeroSet)
{
  auto after = std::upper_bound(zeroSet.begin(), zeroSet.end(), low,
    [](double v, const std::pair<double, double>& z) { return v < z.first; });
  return after != zeroSet.begin() && std::prev(after)->second >= high;
}

/// True when a sorted isovalue lies in [low, high].
inline bool RangeHoldsIsovalue(double low, double high, const std::vector<double>& sortedIsovalues)
{
  auto iso = std::lower_bound(sortedIsovalues.begin(), sortedIsovalues.end(), low);
  return iso != sortedIsovalues.end() && *iso <= high;
}

/// What a cell with scalar range [low, high] contributes: some extinction (VolumeRole), an isovalue
/// (IsosurfaceRole), both, or nothing (0: never drawn).
enum CellRole : unsigned char
{
  VolumeRole = 1,
  IsosurfaceRole = 2
};

inline unsigned char RoleOf(double low, double high, const std::vector<std::pair<double, double>>& zeroSet,
  const std::vector<double>& sortedIsovalues)
{
  return static_cast<unsigned char>((RangeHasZeroExtinction(low, high, zeroSet) ? 0 : VolumeRole) |
    (RangeHoldsIsovalue(low, high, sortedIsovalues) ? IsosurfaceRole : 0));
}

/// The cells a mapper draws, by role, rebuilt only when the cells' ranges (their version), the
/// zero-extinction set or the isovalues change. An empty zero set (skipping off) makes every cell a
/// volume cell.
class CellLists
{
public:
  std::vector<std::uint32_t> Isosurface, Drawn; // Drawn: either role
  std::size_t GetBytes() const
  {
    return sizeof(std::uint32_t) * (this->Isosurface.capacity() + this->Drawn.capacity() + this->VolumeOnly.capacity());
  }
  /// The cells with some extinction: Drawn itself when every drawn cell has (not kept twice).
  const std::vector<std::uint32_t>& Volume() const { return this->VolumeIsDrawn ? this->Drawn : this->VolumeOnly; }
  std::uint64_t Version = 0; ///< bumped whenever the lists change
  int Builds = 0;            ///< classifications run

  /// `parallelFor(count, function(begin, end))` runs the classification in chunks. True when the
  /// lists changed. The caller keys `cellsVersion` to the cells' ranges and to which cells the ids
  /// name (new cells under the same ids must also change the version it passes to what uses the ids).
  template <typename ParallelFor>
  bool Update(std::uint64_t cellsVersion, const std::vector<float>& low, const std::vector<float>& high,
    const std::vector<std::pair<double, double>>& zeroSet, const std::vector<double>& sortedIsovalues,
    ParallelFor&& parallelFor)
  {
    if (this->Version != 0 && cellsVersion == this->CellsVersion && zeroSet == this->ZeroSet &&
      sortedIsovalues == this->Isovalues)
    {
      return false;
    }
    const std::size_t count = low.size();
    std::vector<unsigned char> roles(count, 0);
    parallelFor(count, [&](std::size_t begin, std::size_t end) {
      for (std::size_t c = begin; c < end; ++c)
        roles[c] = RoleOf(low[c], high[c], zeroSet, sortedIsovalues);
    });
    // Sized exactly (lists of every cell are a large share of a mapper's memory).
    std::size_t volumeCount = 0, isosurfaceCount = 0, drawnCount = 0;
    for (std::size_t c = 0; c < count; ++c)
    {
      volumeCount += roles[c] & VolumeRole ? 1 : 0;
      isosurfaceCount += roles[c] & IsosurfaceRole ? 1 : 0;
      drawnCount += roles[c] ? 1 : 0;
    }
    const bool volumeIsDrawn = volumeCount == drawnCount;
    std::vector<std::uint32_t> volumeOnly(volumeIsDrawn ? 0 : volumeCount), isosurface(isosurfaceCount),
      drawn(drawnCount);
    std::size_t v = 0, i = 0, d = 0;
    for (std::size_t c = 0; c < count; ++c)
    {
      const auto id = static_cast<std::uint32_t>(c);
      if ((roles[c] & VolumeRole) && !volumeIsDrawn)
        volumeOnly[v++] = id;
      if (roles[c] & IsosurfaceRole)
        isosurface[i++] = id;
      if (roles[c])
        drawn[d++] = id;
    }
    this->CellsVersion = cellsVersion;
    this->ZeroSet = zeroSet;
    this->Isovalues = sortedIsovalues;
    ++this->Builds;
    // New values of the same cells often leave the lists as they were (a time step): then nothing
    // downstream (order, uploads) needs redoing.
    if (this->Version != 0 && volumeIsDrawn == this->VolumeIsDrawn && drawn == this->Drawn &&
      isosurface == this->Isosurface && volumeOnly == this->VolumeOnly)
    {
      return false;
    }
    this->VolumeIsDrawn = volumeIsDrawn;
    this->VolumeOnly.swap(volumeOnly);
    this->Isosurface.swap(isosurface);
    this->Drawn.swap(drawn);
    ++this->Version;
    return true;
  }

private:
  std::vector<std::uint32_t> VolumeOnly;
  bool VolumeIsDrawn = true;
  std::uint64_t CellsVersion = 0;
  std::vector<std::pair<double, double>> ZeroSet;
  std::vector<double> Isovalues;
};

} // namespace uv

#endif
