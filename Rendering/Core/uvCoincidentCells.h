// Cells that repeat another, as a mesh appended to itself has: the optical model adds their media,
// while a walk or a shell sample meets one cell per place. Each run of copies becomes one cell of
// their count's density. VTK-free.
#ifndef uvCoincidentCells_h
#define uvCoincidentCells_h

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace uv
{

/// Per cell of `cellPoints` (`Corners` ids each: 8 for hexahedra, 4 for tetrahedra), how many cells
/// it stands for: cells that repeat another, with the same corners by position (`samePoint`: per
/// point, one id standing for its position, as CoincidentPointRepresentatives or CoincidentPointIds
/// give) and the same field on them (the scalar at each corner, `pointData`'s fourth float, or the
/// same `cellScalars` value), as a mesh appended twice has, are merged into the first of them, which
/// gets their count, and count 0 themselves. Empty when no cell repeats another.
/// `sort(begin, end, less)` orders (hash, cell) pairs.
template <int Corners, typename Sort>
std::vector<float> CoincidentCellDensities(const std::vector<std::uint32_t>& cellPoints,
  const std::vector<std::uint32_t>& samePoint, const std::vector<float>& pointData,
  const std::vector<float>& cellScalars, Sort&& sort)
{
  const std::size_t cellCount = cellPoints.size() / Corners;
  // Each cell's corners as (position's representative, scalar), sorted: equal for copies.
  const auto corners = [&](std::size_t c) {
    std::array<std::pair<std::uint32_t, float>, Corners> key;
    for (int k = 0; k < Corners; ++k)
    {
      const std::uint32_t id = cellPoints[Corners * c + k];
      key[k] = { samePoint[id], cellScalars.empty() ? pointData[4 * std::size_t(id) + 3] : 0.0f };
    }
    std::sort(key.begin(), key.end());
    return key;
  };
  const auto same = [&](std::uint32_t a, std::uint32_t b) {
    return corners(a) == corners(b) && (cellScalars.empty() || cellScalars[a] == cellScalars[b]);
  };
  // Sorted by a hash of that key (and the cell scalar): copies fall into one run, checked exactly.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> hashed(cellCount);
  for (std::size_t c = 0; c < cellCount; ++c)
  {
    std::uint64_t hash = 1469598103934665603ull;
    const auto mix = [&hash](std::uint32_t bits) { hash = (hash ^ bits) * 1099511628211ull; };
    for (const auto& corner : corners(c))
    {
      std::uint32_t valueBits;
      std::memcpy(&valueBits, &corner.second, sizeof valueBits);
      mix(corner.first);
      mix(valueBits);
    }
    if (!cellScalars.empty())
    {
      std::uint32_t valueBits;
      std::memcpy(&valueBits, &cellScalars[c], sizeof valueBits);
      mix(valueBits);
    }
    hashed[c] = { hash, static_cast<std::uint32_t>(c) };
  }
  sort(hashed.begin(), hashed.end(), [](const auto& a, const auto& b) { return a < b; });
  std::vector<float> density(cellCount, 1.0f);
  bool merged = false;
  for (std::size_t i = 0; i < cellCount;)
  {
    std::size_t j = i + 1;
    while (j < cellCount && hashed[j].first == hashed[i].first)
      ++j;
    // Within a run (almost always one cell), each copy joins the first equal cell before it.
    for (std::size_t k = i + 1; k < j; ++k)
      for (std::size_t first = i; first < k; ++first)
        if (density[hashed[first].second] > 0.0f && same(hashed[first].second, hashed[k].second))
        {
          density[hashed[first].second] += 1.0f;
          density[hashed[k].second] = 0.0f;
          merged = true;
          break;
        }
    i = j;
  }
  return merged ? density : std::vector<float>();
}

/// Per cell of `cellPoints` (`Corners` ids each), the first cell with the same point ids in any
/// order: itself unless it repeats an earlier one. Empty when no cell repeats another. Copies on the
/// same ids share every face, so a face joins more than two cells: what orders cells by their faces
/// takes one of each. `sort(begin, end, less)` orders (key, cell) pairs.
template <int Corners, typename Sort>
std::vector<std::uint32_t> FirstCopies(const std::vector<std::uint32_t>& cellPoints, Sort&& sort)
{
  const std::size_t cellCount = cellPoints.size() / Corners;
  using Key = std::array<std::uint32_t, Corners>;
  std::vector<std::pair<Key, std::uint32_t>> keyed(cellCount);
  for (std::size_t c = 0; c < cellCount; ++c)
  {
    std::copy_n(cellPoints.begin() + Corners * c, Corners, keyed[c].first.begin());
    std::sort(keyed[c].first.begin(), keyed[c].first.end());
    keyed[c].second = static_cast<std::uint32_t>(c);
  }
  sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a < b; });
  std::vector<std::uint32_t> first(cellCount);
  bool repeated = false;
  for (std::size_t i = 0; i < cellCount; ++i)
  {
    const bool same = i > 0 && keyed[i].first == keyed[i - 1].first;
    first[keyed[i].second] = same ? first[keyed[i - 1].second] : keyed[i].second; // runs sort by cell
    repeated = repeated || same;
  }
  return repeated ? first : std::vector<std::uint32_t>();
}

} // namespace uv

#endif
