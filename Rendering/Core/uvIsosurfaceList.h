// Isosurfaces as both mappers keep them: a value, a colour and an opacity each, ascending by value.
// VTK-free, so the normalisation the shaders see is unit-tested with the rest of the math.
#ifndef uvIsosurfaceList_h
#define uvIsosurfaceList_h

#include <algorithm>
#include <vector>

namespace uv
{

struct Isosurface
{
  double Value;
  double Color[3];
  double Opacity; // in [0, 1]
};

class IsosurfaceList
{
public:
  /// Inserts in value order (equal values keep the order they came in); opacity clamped to [0, 1].
  void Add(double value, double red, double green, double blue, double opacity)
  {
    const Isosurface surface{ value, { red, green, blue }, std::min(std::max(opacity, 0.0), 1.0) };
    this->Surfaces.insert(std::upper_bound(this->Surfaces.begin(), this->Surfaces.end(), value,
                            [](double v, const Isosurface& s) { return v < s.Value; }),
      surface);
  }
  /// False when there was nothing to remove.
  bool Clear()
  {
    const bool had = !this->Surfaces.empty();
    this->Surfaces.clear();
    return had;
  }
  int Size() const { return static_cast<int>(this->Surfaces.size()); }

  /// The surfaces that draw anything (opacity > 0), their values mapped by (v - offset) * scale.
  std::vector<Isosurface> Drawn(double offset, double scale) const
  {
    std::vector<Isosurface> drawn;
    for (const Isosurface& s : this->Surfaces)
    {
      if (s.Opacity > 0.0)
      {
        drawn.push_back(s);
        drawn.back().Value = (s.Value - offset) * scale;
      }
    }
    return drawn;
  }

  /// Columns of Texels(drawn): one per surface, at least one.
  static int TexelColumns(const std::vector<Isosurface>& drawn)
  {
    return static_cast<int>(std::max<std::size_t>(1, drawn.size()));
  }

  /// As a 2-row float RGBA texture: row 0 (r, g, b, opacity), row 1 (value, 0, 0, 0); at least one
  /// column (a zero one when empty) so the texture always exists.
  static std::vector<float> Texels(const std::vector<Isosurface>& drawn)
  {
    const std::size_t count = std::max<std::size_t>(1, drawn.size());
    std::vector<float> texels(8 * count, 0.0f);
    for (std::size_t k = 0; k < drawn.size(); ++k)
    {
      for (int d = 0; d < 3; ++d)
        texels[4 * k + d] = static_cast<float>(drawn[k].Color[d]);
      texels[4 * k + 3] = static_cast<float>(drawn[k].Opacity);
      texels[4 * (count + k)] = static_cast<float>(drawn[k].Value);
    }
    return texels;
  }

private:
  std::vector<Isosurface> Surfaces;
};

/// The isosurfaces of a cell scalar (constant in each cell) are the faces between cells on either
/// side of the value: a face from a cell of value `from` into one of value `to` holds each surface of
/// `drawn` (ascending) with (from < v) != (to < v) -- a cell at exactly v counts as above it. Visits
/// them in the order a ray crossing the face meets them (from `from` towards `to`).
template <typename Visit>
void ForEachSurfaceBetweenCells(const std::vector<Isosurface>& drawn, double from, double to, Visit&& visit)
{
  const std::size_t count = drawn.size();
  for (std::size_t i = 0; i < count; ++i)
  {
    const Isosurface& surface = drawn[from < to ? i : count - 1 - i];
    if ((from < surface.Value) != (to < surface.Value))
      visit(surface);
  }
}

} // namespace uv

#endif
