// Boxes on screen and the rectangles of pixels they cover, free of VTK: where a mesh can appear in an
// image, so that passes over the image (clears, full-screen passes, the composite into the scene)
// touch only those pixels.
#ifndef uvScreenRectangle_h
#define uvScreenRectangle_h

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace uv
{

/// A box in normalised device coordinates: low x, low y, high x, high y.
using ScreenBox = glm::dvec4;
inline ScreenBox EmptyScreenBox()
{
  return ScreenBox(1.0, 1.0, -1.0, -1.0);
}
inline ScreenBox WholeScreenBox()
{
  return ScreenBox(-1.0, -1.0, 1.0, 1.0);
}
inline ScreenBox UniteScreenBoxes(const ScreenBox& a, const ScreenBox& b)
{
  return ScreenBox(std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.z, b.z), std::max(a.w, b.w));
}

/// A rectangle of pixels: x, y, width, height.
using PixelRectangle = std::array<int, 4>;

/// A ScreenBox as the pixels of a width x height viewport it covers, a pixel of margin around,
/// clamped to the viewport (an empty box covers none).
inline PixelRectangle ScreenBoxPixels(const ScreenBox& box, int width, int height)
{
  const int x0 = std::clamp(static_cast<int>(std::floor((box[0] + 1.0) * 0.5 * width)) - 1, 0, width);
  const int y0 = std::clamp(static_cast<int>(std::floor((box[1] + 1.0) * 0.5 * height)) - 1, 0, height);
  const int x1 = std::clamp(static_cast<int>(std::ceil((box[2] + 1.0) * 0.5 * width)) + 1, 0, width);
  const int y1 = std::clamp(static_cast<int>(std::ceil((box[3] + 1.0) * 0.5 * height)) + 1, 0, height);
  return { x0, y0, std::max(x1 - x0, 0), std::max(y1 - y0, 0) };
}

/// The pixels the axis-aligned box `bounds` (x0, x1, y0, y1, z0, z1, in the space `toClip` maps from)
/// can cover: its corners projected. The whole viewport when a corner is not in front of the eye.
inline PixelRectangle BoundsPixels(const double bounds[6], const glm::dmat4& toClip, int width, int height)
{
  ScreenBox box = EmptyScreenBox();
  for (int corner = 0; corner < 8; ++corner)
  {
    const glm::dvec4 clip =
      toClip * glm::dvec4(bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + (corner >> 2)], 1.0);
    if (!(clip.w > 1e-12))
    {
      return { 0, 0, width, height };
    }
    const double x = clip.x / clip.w, y = clip.y / clip.w;
    box = UniteScreenBoxes(box, ScreenBox(x, y, x, y));
  }
  return ScreenBoxPixels(box, width, height);
}

/// The pixels two rectangles share (zero width or height when none).
inline PixelRectangle IntersectPixels(const PixelRectangle& a, const PixelRectangle& b)
{
  const int x0 = std::max(a[0], b[0]), y0 = std::max(a[1], b[1]);
  const int x1 = std::min(a[0] + a[2], b[0] + b[2]), y1 = std::min(a[1] + a[3], b[1] + b[3]);
  return { x0, y0, std::max(x1 - x0, 0), std::max(y1 - y0, 0) };
}

/// The smallest rectangle holding both (a rectangle without pixels adds none).
inline PixelRectangle UnitePixels(const PixelRectangle& a, const PixelRectangle& b)
{
  if (a[2] <= 0 || a[3] <= 0)
    return b;
  if (b[2] <= 0 || b[3] <= 0)
    return a;
  const int x0 = std::min(a[0], b[0]), y0 = std::min(a[1], b[1]);
  const int x1 = std::max(a[0] + a[2], b[0] + b[2]), y1 = std::max(a[1] + a[3], b[1] + b[3]);
  return { x0, y0, x1 - x0, y1 - y0 };
}

/// The pixels of a tileWidth x tileHeight tile over which an image of width x height is stretched
/// (filtered) that can read the image's pixels `image`: scaled, with a pixel of the image around for
/// the filter's reach, clamped to the tile.
inline PixelRectangle StretchedPixels(const PixelRectangle& image, int width, int height, int tileWidth, int tileHeight)
{
  if (image[2] <= 0 || image[3] <= 0 || width <= 0 || height <= 0)
    return { 0, 0, 0, 0 };
  const double sx = static_cast<double>(tileWidth) / width, sy = static_cast<double>(tileHeight) / height;
  const int x0 = std::clamp(static_cast<int>(std::floor((image[0] - 1) * sx)), 0, tileWidth);
  const int y0 = std::clamp(static_cast<int>(std::floor((image[1] - 1) * sy)), 0, tileHeight);
  const int x1 = std::clamp(static_cast<int>(std::ceil((image[0] + image[2] + 1) * sx)), 0, tileWidth);
  const int y1 = std::clamp(static_cast<int>(std::ceil((image[1] + image[3] + 1) * sy)), 0, tileHeight);
  return { x0, y0, std::max(x1 - x0, 0), std::max(y1 - y0, 0) };
}

} // namespace uv

#endif
