// A 64-bit fingerprint of a block of memory, so that a mapper can tell whether a time step's arrays
// (a reader makes new ones every step) hold what it built from: the same cells, the same points.
// Fixed-size chunks are hashed in parallel and combined in chunk order, so the result does not depend
// on how the work was split among threads. VTK-free.
#ifndef uvContentFingerprint_h
#define uvContentFingerprint_h

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace uv
{

/// A bijective 64-bit mixer (each bit of the input affects every bit of the output).
inline std::uint64_t MixBits(std::uint64_t x)
{
  x ^= x >> 31;
  x *= 0x7fb5d329728ea185ULL;
  x ^= x >> 27;
  x *= 0x81dadef4bc2dd44dULL;
  x ^= x >> 33;
  return x;
}

/// Fingerprint of bytes [begin, begin + count), seeded (the chunk's index, so equal chunks at
/// different places differ).
inline std::uint64_t FingerprintChunk(const unsigned char* begin, std::size_t count, std::uint64_t seed)
{
  std::uint64_t a = MixBits(seed + 0x9e3779b97f4a7c15ULL), b = MixBits(a ^ count);
  std::size_t i = 0;
  // Two lanes, so consecutive words do not wait on one multiply chain.
  for (; i + 16 <= count; i += 16)
  {
    std::uint64_t w0, w1;
    std::memcpy(&w0, begin + i, 8);
    std::memcpy(&w1, begin + i + 8, 8);
    a = (a ^ w0) * 0x9fb21c651e98df25ULL;
    a ^= a >> 29;
    b = (b ^ w1) * 0xc2b2ae3d27d4eb4fULL;
    b ^= b >> 31;
  }
  if (count - i >= 8)
  {
    std::uint64_t w;
    std::memcpy(&w, begin + i, 8);
    a = (a ^ w) * 0x9fb21c651e98df25ULL;
    a ^= a >> 29;
    i += 8;
  }
  std::uint64_t tail = 0; // the last 0 to 7 bytes
  std::memcpy(&tail, begin + i, count - i);
  return MixBits(a ^ MixBits(b ^ tail ^ (static_cast<std::uint64_t>(count - i) << 56)));
}

constexpr std::size_t FingerprintChunkBytes = std::size_t(1) << 20;

/// Fingerprint of `bytes` bytes at `data`. `parallelFor(count, function(begin, end))` runs chunks
/// [begin, end) of [0, count), possibly concurrently.
template <typename ParallelFor>
std::uint64_t Fingerprint(const void* data, std::size_t bytes, ParallelFor&& parallelFor)
{
  const auto* base = static_cast<const unsigned char*>(data);
  const std::size_t chunks = (bytes + FingerprintChunkBytes - 1) / FingerprintChunkBytes;
  std::vector<std::uint64_t> parts(chunks);
  parallelFor(chunks, [&](std::size_t first, std::size_t last) {
    for (std::size_t c = first; c < last; ++c)
    {
      const std::size_t offset = c * FingerprintChunkBytes;
      const std::size_t count = bytes - offset < FingerprintChunkBytes ? bytes - offset : FingerprintChunkBytes;
      parts[c] = FingerprintChunk(base + offset, count, c);
    }
  });
  std::uint64_t result = MixBits(bytes ^ 0x243f6a8885a308d3ULL);
  for (std::uint64_t part : parts)
    result = MixBits(result ^ part) + 0x13198a2e03707344ULL;
  return result;
}

} // namespace uv

#endif
