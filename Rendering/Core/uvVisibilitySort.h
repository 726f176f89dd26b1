// Visibility order for cell projection, free of VTK: a stable least-significant-digit radix sort of
// (key, cell) pairs, parallel over chunks through a caller-supplied loop (vtkSMPTools in the mapper,
// a plain loop in the tests). Stable and chunked the same way for any thread count, so the order
// (and the image) does not depend on the number of threads.
#ifndef uvVisibilitySort_h
#define uvVisibilitySort_h

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

namespace uv
{

/// An unsigned key whose order is the order of the float (all finite values and infinities).
inline std::uint32_t OrderedKey(float value)
{
  if (value == 0.0f)
  {
    value = 0.0f; // -0 and +0 are one key
  }
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return (bits & 0x80000000u) ? ~bits : (bits | 0x80000000u);
}

/// A plain serial loop over chunks: forEachChunk(count, function(chunk)).
struct SerialChunks
{
  template <typename Function>
  void operator()(int count, const Function& function) const
  {
    for (int chunk = 0; chunk < count; ++chunk)
    {
      function(chunk);
    }
  }
};

/// Sorts `values` by ascending `keys`, stably; both are reordered. `scratchKeys` and
/// `scratchValues` are resized and used as the second buffers (kept by the caller to avoid
/// reallocating every frame). Passes whose digit is the same for every key are skipped. The keys
/// are split into at most `maximumChunks` chunks of at least `minimumChunk` keys: each chunk has a
/// count per digit that every pass clears and sums, which would outweigh a short list's sort. A
/// stable sort has one result, so the chunking never changes the order.
template <typename ForEachChunk>
void RadixSortPairs(std::vector<std::uint32_t>& keys, std::vector<std::uint32_t>& values,
  std::vector<std::uint32_t>& scratchKeys, std::vector<std::uint32_t>& scratchValues,
  const ForEachChunk& forEachChunk, int maximumChunks = 64, std::size_t minimumChunk = 16384)
{
  constexpr int digitBits = 11;
  constexpr std::uint32_t buckets = 1u << digitBits;
  const std::size_t n = keys.size();
  scratchKeys.resize(n);
  scratchValues.resize(n);
  if (n < 2)
  {
    return;
  }
  const std::size_t chunksOfMinimum = n / std::max<std::size_t>(1, minimumChunk);
  const int chunkCount =
    static_cast<int>(std::max<std::size_t>(1, std::min<std::size_t>(std::size_t(maximumChunks), chunksOfMinimum)));
  const std::size_t chunkSize = (n + chunkCount - 1) / chunkCount;
  std::vector<std::array<std::uint32_t, buckets>> counts(chunkCount);
  for (int shift = 0; shift < 32; shift += digitBits)
  {
    forEachChunk(chunkCount, [&](int chunk) {
      auto& count = counts[chunk];
      count.fill(0);
      const std::size_t begin = std::min(n, chunk * chunkSize), end = std::min(n, begin + chunkSize);
      for (std::size_t i = begin; i < end; ++i)
      {
        ++count[(keys[i] >> shift) & (buckets - 1)];
      }
    });
    // Exclusive prefix over (digit, chunk): chunk c's items of digit d go after every item of a
    // smaller digit and after chunks < c of the same digit.
    std::uint32_t running = 0;
    bool oneDigit = false;
    for (std::uint32_t d = 0; d < buckets; ++d)
    {
      std::uint32_t digitTotal = 0;
      for (int c = 0; c < chunkCount; ++c)
      {
        const std::uint32_t here = counts[c][d];
        counts[c][d] = running;
        running += here;
        digitTotal += here;
      }
      oneDigit = oneDigit || digitTotal == n;
    }
    if (oneDigit)
    {
      continue; // every key has this digit: the pass would not move anything
    }
    forEachChunk(chunkCount, [&](int chunk) {
      auto& offset = counts[chunk];
      const std::size_t begin = std::min(n, chunk * chunkSize), end = std::min(n, begin + chunkSize);
      for (std::size_t i = begin; i < end; ++i)
      {
        const std::uint32_t target = offset[(keys[i] >> shift) & (buckets - 1)]++;
        scratchKeys[target] = keys[i];
        scratchValues[target] = values[i];
      }
    });
    keys.swap(scratchKeys);
    values.swap(scratchValues);
  }
}

} // namespace uv

#endif
