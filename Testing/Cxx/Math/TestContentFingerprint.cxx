// The content fingerprint (uvContentFingerprint.h): equal bytes give equal fingerprints however the
// chunks are spread over threads, and any one changed bit, swapped chunk or length changes it.
#include "uvContentFingerprint.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <random>
#include <set>
#include <vector>

namespace
{
void Serial(std::size_t count, const std::function<void(std::size_t, std::size_t)>& function)
{
  function(0, count);
}

// Chunks in reverse order, one at a time, as a thread pool might run them.
void Reversed(std::size_t count, const std::function<void(std::size_t, std::size_t)>& function)
{
  for (std::size_t c = count; c-- > 0;)
    function(c, c + 1);
}

std::vector<unsigned char> RandomBytes(std::size_t count, unsigned seed)
{
  std::mt19937 random(seed);
  std::vector<unsigned char> bytes(count);
  for (unsigned char& b : bytes)
    b = static_cast<unsigned char>(random());
  return bytes;
}

std::uint64_t Of(const std::vector<unsigned char>& bytes)
{
  return uv::Fingerprint(bytes.data(), bytes.size(), Serial);
}
}

TEST(ContentFingerprint, EqualContentEqualFingerprintWhateverTheThreads)
{
  const std::size_t size = 3 * uv::FingerprintChunkBytes + 12345;
  const std::vector<unsigned char> bytes = RandomBytes(size, 1);
  const std::vector<unsigned char> copy = bytes;
  EXPECT_EQ(Of(bytes), Of(copy));
  EXPECT_EQ(Of(bytes), uv::Fingerprint(bytes.data(), bytes.size(), Reversed));
}

TEST(ContentFingerprint, EveryFlippedBitChangesIt)
{
  // Sizes below, at and across the chunk and the 16-byte step, so tails and lanes are all covered.
  for (std::size_t size : { std::size_t(1), std::size_t(15), std::size_t(16), std::size_t(33),
         uv::FingerprintChunkBytes, uv::FingerprintChunkBytes + 7 })
  {
    std::vector<unsigned char> bytes = RandomBytes(size, 2);
    const std::uint64_t original = Of(bytes);
    std::mt19937 random(3);
    for (int trial = 0; trial < 200; ++trial)
    {
      const std::size_t at = random() % size;
      const unsigned char bit = static_cast<unsigned char>(1u << (random() % 8));
      bytes[at] ^= bit;
      EXPECT_NE(Of(bytes), original) << "size " << size << " byte " << at;
      bytes[at] ^= bit;
    }
    EXPECT_EQ(Of(bytes), original);
  }
}

TEST(ContentFingerprint, OrderAndLengthMatter)
{
  // Two chunks swapped, the same bytes one shorter, and all-zero blocks of different lengths.
  std::vector<unsigned char> bytes = RandomBytes(2 * uv::FingerprintChunkBytes, 4);
  const std::uint64_t original = Of(bytes);
  std::rotate(bytes.begin(), bytes.begin() + uv::FingerprintChunkBytes, bytes.end());
  EXPECT_NE(Of(bytes), original);
  EXPECT_NE(uv::Fingerprint(bytes.data(), bytes.size() - 1, Serial), Of(bytes));
  std::set<std::uint64_t> zeros;
  for (std::size_t size = 0; size < 64; ++size)
    zeros.insert(Of(std::vector<unsigned char>(size, 0)));
  EXPECT_EQ(zeros.size(), 64u);
}
