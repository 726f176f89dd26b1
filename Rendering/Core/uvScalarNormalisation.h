// How the mappers hand a scalar to the GPU: mapped onto [0, 1] by (s - Offset) * Scale over its finite
// values, so float keeps its digits whatever the data's units, and transfer-function nodes and
// isovalues are mapped the same way. A NaN stays NaN, and cells touching one are left out. VTK-free.
#ifndef uvScalarNormalisation_h
#define uvScalarNormalisation_h

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace uv
{

struct ScalarNormalisation
{
  double Offset = 0.0, Scale = 1.0;

  /// The normalisation of value(0), ..., value(count - 1), ignoring NaN and infinities; a constant
  /// (or all-NaN) scalar keeps scale 1.
  template <typename Value>
  static ScalarNormalisation OfFiniteValues(std::size_t count, Value&& value)
  {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (std::size_t p = 0; p < count; ++p)
    {
      const double s = value(p);
      if (std::isfinite(s))
      {
        low = std::min(low, s);
        high = std::max(high, s);
      }
    }
    if (!(low <= high))
    {
      low = high = 0.0; // every scalar is NaN: nothing will be drawn
    }
    ScalarNormalisation normalisation;
    normalisation.Offset = low;
    normalisation.Scale = high > low ? 1.0 / (high - low) : 1.0;
    return normalisation;
  }

  double operator()(double s) const { return (s - this->Offset) * this->Scale; }

  /// The normalisation for a time step of the same mesh whose values this one normalises, `previous`
  /// the last step's: `previous` where it maps these values into [0, 1] and spans at most twice them
  /// (values moving inside the last range), else this one widened by an eighth of its span at each
  /// end, so that values moving a little beyond it next step fit too. While it stays, the normalised
  /// transfer function, and the tables built from it, stay as they are.
  ScalarNormalisation ForTimeStep(const ScalarNormalisation& previous) const
  {
    const double low = this->Offset, high = this->Offset + 1.0 / this->Scale;
    const double previousLow = previous.Offset, previousHigh = previous.Offset + 1.0 / previous.Scale;
    if (previousLow <= low && high <= previousHigh && 2.0 * (high - low) >= previousHigh - previousLow)
      return previous;
    const double margin = (high - low) / 8.0;
    ScalarNormalisation widened;
    widened.Offset = low - margin;
    widened.Scale = 1.0 / (high - low + 2.0 * margin);
    return widened;
  }
};

/// True when every one of the `count` points `ids` has a finite normalised scalar in `pointData`
/// (4 floats per point, the scalar last).
template <typename Id>
bool ScalarsFinite(const std::vector<float>& pointData, const Id* ids, int count)
{
  for (int k = 0; k < count; ++k)
  {
    if (!std::isfinite(pointData[4 * static_cast<std::size_t>(ids[k]) + 3]))
    {
      return false;
    }
  }
  return true;
}

} // namespace uv

#endif
