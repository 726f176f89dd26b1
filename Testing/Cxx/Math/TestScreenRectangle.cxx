// The rectangles of pixels the float target clears and composites (uvScreenRectangle.h).
#include "uvScreenRectangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
bool Holds(const uv::PixelRectangle& r, int x, int y)
{
  return x >= r[0] && x < r[0] + r[2] && y >= r[1] && y < r[1] + r[3];
}

/// The image texels a bilinear read at tile pixel `i` takes along one axis (image of `size` texels
/// stretched over `tileSize` pixels, edges clamped).
std::pair<int, int> TexelsRead(int i, int size, int tileSize)
{
  const double u = (i + 0.5) * size / tileSize - 0.5;
  const int low = static_cast<int>(std::floor(u));
  return { std::clamp(low, 0, size - 1), std::clamp(low + 1, 0, size - 1) };
}
} // namespace

TEST(ScreenRectangle, UnionHoldsBothAndIgnoresEmptyRectangles)
{
  EXPECT_EQ(uv::UnitePixels({ 2, 3, 4, 5 }, { 10, 1, 2, 2 }), (uv::PixelRectangle{ 2, 1, 10, 7 }));
  EXPECT_EQ(uv::UnitePixels({ 2, 3, 4, 5 }, { 50, 50, 0, 7 }), (uv::PixelRectangle{ 2, 3, 4, 5 }));
  EXPECT_EQ(uv::UnitePixels({ 0, 0, 3, 0 }, { 1, 1, 1, 1 }), (uv::PixelRectangle{ 1, 1, 1, 1 }));
  const uv::PixelRectangle none = uv::UnitePixels({ 0, 0, 0, 0 }, { 5, 5, 0, 0 });
  EXPECT_EQ(none[2] * none[3], 0);
}

TEST(ScreenRectangle, StretchedPixelsHoldEveryTilePixelThatReadsTheImagePixels)
{
  EXPECT_EQ(uv::StretchedPixels({ 10, 5, 4, 3 }, 24, 24, 48, 48), (uv::PixelRectangle{ 18, 8, 12, 10 }));
  EXPECT_EQ(uv::StretchedPixels({ 0, 0, 24, 24 }, 24, 24, 48, 48), (uv::PixelRectangle{ 0, 0, 48, 48 }));
  EXPECT_EQ(uv::StretchedPixels({ 3, 3, 0, 5 }, 24, 24, 48, 48)[2], 0);
  // Brute force: every tile pixel whose filtered read takes a texel inside the rectangle is in the
  // stretched one, for odd sizes and scales up and down.
  std::mt19937 random(7);
  for (int trial = 0; trial < 400; ++trial)
  {
    const int width = 1 + static_cast<int>(random() % 40), height = 1 + static_cast<int>(random() % 40);
    const int tileWidth = 1 + static_cast<int>(random() % 90), tileHeight = 1 + static_cast<int>(random() % 90);
    const int x = static_cast<int>(random() % width), y = static_cast<int>(random() % height);
    const uv::PixelRectangle image{ x, y, 1 + static_cast<int>(random() % (width - x)),
      1 + static_cast<int>(random() % (height - y)) };
    const uv::PixelRectangle tile = uv::StretchedPixels(image, width, height, tileWidth, tileHeight);
    for (int j = 0; j < tileHeight; ++j)
      for (int i = 0; i < tileWidth; ++i)
      {
        const auto [x0, x1] = TexelsRead(i, width, tileWidth);
        const auto [y0, y1] = TexelsRead(j, height, tileHeight);
        const bool reads = Holds(image, x0, y0) || Holds(image, x1, y0) || Holds(image, x0, y1) || Holds(image, x1, y1);
        if (reads)
          ASSERT_TRUE(Holds(tile, i, j)) << "trial " << trial << " pixel " << i << ", " << j;
      }
    EXPECT_GE(tile[0], 0);
    EXPECT_GE(tile[1], 0);
    EXPECT_LE(tile[0] + tile[2], tileWidth);
    EXPECT_LE(tile[1] + tile[3], tileHeight);
  }
}
