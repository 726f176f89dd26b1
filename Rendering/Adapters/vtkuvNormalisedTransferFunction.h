// The project's transfer function (uvOpticalModel.h) from a vtkVolumeProperty: one place, so the
// reference renderer and every mapper read a property the same way.
#ifndef vtkuvNormalisedTransferFunction_h
#define vtkuvNormalisedTransferFunction_h

#include "uvOpticalModel.h"
#include "uvTransferFunctionSimplification.h"

#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace vtkuv
{

namespace detail
{
/// The sorted distinct scalars of the opacity and colour nodes; `curved` tells whether VTK's
/// functions bend between them (a midpoint other than 0.5, a sharpness, a colour space not RGB).
inline std::vector<double> NodeScalars(
  vtkPiecewiseFunction* opacity, vtkColorTransferFunction* color, bool& curved)
{
  std::vector<double> scalars;
  curved = false;
  double node[6];
  for (int i = 0; i < opacity->GetSize(); ++i)
  {
    opacity->GetNodeValue(i, node);
    scalars.push_back(node[0]);
    curved = curved || node[2] != 0.5 || node[3] != 0.0;
  }
  if (color)
  {
    curved = curved || color->GetColorSpace() != VTK_CTF_RGB;
    for (int i = 0; i < color->GetSize(); ++i)
    {
      color->GetNodeValue(i, node);
      scalars.push_back(node[0]);
      curved = curved || node[4] != 0.5 || node[5] != 0.0;
    }
  }
  std::sort(scalars.begin(), scalars.end());
  scalars.erase(std::unique(scalars.begin(), scalars.end()), scalars.end());
  return scalars;
}

/// `scalars` with each interval halved, depth first, until `straight(a, b)` holds on every piece or
/// a piece is a `maximumSubdivisions`-th of its interval.
template <typename Straight>
std::vector<double> RefinedWhereCurved(
  const std::vector<double>& scalars, int maximumSubdivisions, const Straight& straight)
{
  std::vector<double> refined;
  for (std::size_t i = 0; i + 1 < scalars.size(); ++i)
  {
    // `pieces` is how many of the interval's finest pieces one spans.
    std::vector<std::pair<double, int>> pending{ { scalars[i], maximumSubdivisions } };
    const double step = (scalars[i + 1] - scalars[i]) / maximumSubdivisions;
    while (!pending.empty())
    {
      const auto [start, pieces] = pending.back();
      pending.pop_back();
      const double end = start + pieces * step;
      if (pieces == 1 || straight(start, end))
      {
        refined.push_back(start);
      }
      else
      {
        pending.push_back({ start + (pieces / 2) * step, pieces - pieces / 2 });
        pending.push_back({ start, pieces / 2 });
      }
    }
  }
  refined.push_back(scalars.back());
  return refined;
}
} // namespace detail

/// Nodes: the union of the colour and opacity nodes. Where VTK's functions are not linear between
/// their nodes (a midpoint other than 0.5, a non-zero sharpness, or a colour space other than RGB),
/// each interval is halved until the straight line between its ends is within `tolerance` of VTK's
/// colour (every channel) and opacity at a quarter, half and three quarters of it, into at most
/// `maximumSubdivisions` pieces: the piecewise-linear model follows the curves, with nodes only where
/// they bend (every node is a split point of every ray integral, so their number is frame time).
/// An opacity function without nodes (VTK evaluates it to zero everywhere) gives one transparent
/// node, so every renderer draws nothing of the volume but its isosurfaces, as for any invisible one.
/// Returns no nodes only without a property.
inline std::vector<uv::TransferFunction::Node> TransferFunctionNodes(
  vtkVolumeProperty* property, int maximumSubdivisions = 32, double tolerance = 2e-3)
{
  std::vector<uv::TransferFunction::Node> nodes;
  vtkPiecewiseFunction* opacity = property ? property->GetScalarOpacity(0) : nullptr;
  if (!opacity)
  {
    return nodes;
  }
  if (opacity->GetSize() == 0)
  {
    nodes.push_back({ 0.0, glm::dvec3(0.0), 0.0 });
    return nodes;
  }
  const bool gray = property->GetColorChannels(0) == 1;
  vtkColorTransferFunction* color = gray ? nullptr : property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* grayFunction = gray ? property->GetGrayTransferFunction(0) : nullptr;
  const double unitDistance = property->GetScalarOpacityUnitDistance(0);
  // VTK's colour and opacity at s, as one vector.
  auto sample = [&](double s) {
    std::array<double, 4> value{ 1.0, 1.0, 1.0, opacity->GetValue(s) };
    if (color)
    {
      color->GetColor(s, value.data());
    }
    else if (grayFunction)
    {
      value[0] = value[1] = value[2] = grayFunction->GetValue(s);
    }
    return value;
  };
  auto straight = [&](double a, double b) {
    const std::array<double, 4> va = sample(a), vb = sample(b);
    for (double f : { 0.25, 0.5, 0.75 })
    {
      const std::array<double, 4> v = sample(a + f * (b - a));
      for (int c = 0; c < 4; ++c)
      {
        if (std::abs(v[c] - ((1.0 - f) * va[c] + f * vb[c])) > tolerance)
        {
          return false;
        }
      }
    }
    return true;
  };

  bool curved = false;
  std::vector<double> scalars = detail::NodeScalars(opacity, color, curved);
  if (curved && scalars.size() > 1 && maximumSubdivisions > 1)
  {
    scalars = detail::RefinedWhereCurved(scalars, maximumSubdivisions, straight);
  }
  for (double s : scalars)
  {
    const std::array<double, 4> value = sample(s);
    const glm::dvec3 rgb(value[0], value[1], value[2]);
    nodes.push_back({ s, rgb, uv::ExtinctionFromOpacity(value[3], unitDistance) });
  }
  return nodes;
}

/// TransferFunctionNodes with those dropped that lie within `tolerance` of the line between the
/// nodes kept around them (uvTransferFunctionSimplification.h: colour absolutely, extinction
/// relatively; 0 keeps every node), and at most `maximum` of them (0: any number; else at least 2)
/// for a shader that reads nodes from uniforms only: curved functions get one piece per interval
/// first; when that is still too many, the function is resampled at `maximum` evenly spaced scalars
/// over its nodes' range and `resampled` set.
inline std::vector<uv::TransferFunction::Node> TransferFunctionNodesAtMost(
  vtkVolumeProperty* property, std::size_t maximum, double tolerance, bool& resampled)
{
  resampled = false;
  const auto simplified = [tolerance](std::vector<uv::TransferFunction::Node> all) {
    return tolerance > 0.0 ? uv::SimplifyTransferFunction(all, tolerance, tolerance) : all;
  };
  std::vector<uv::TransferFunction::Node> nodes = simplified(TransferFunctionNodes(property));
  if (maximum == 0 || nodes.size() <= maximum)
  {
    return nodes;
  }
  nodes = simplified(TransferFunctionNodes(property, 1));
  if (nodes.size() <= maximum)
  {
    return nodes;
  }
  const uv::TransferFunction function(nodes);
  const double first = nodes.front().Scalar, last = nodes.back().Scalar;
  nodes.clear();
  for (std::size_t k = 0; k < maximum; ++k)
  {
    const double s = first + (last - first) * static_cast<double>(k) / static_cast<double>(maximum - 1);
    const auto node = function.Evaluate(s);
    nodes.push_back({ s, node.Color, node.Extinction });
  }
  resampled = true;
  return nodes;
}

/// A property's nodes with their scalars normalised as a mapper uploads its field ((s - offset) *
/// scale), rebuilt only when the property or the normalisation changes.
class NormalisedTransferFunction
{
public:
  std::vector<uv::TransferFunction::Node> Nodes;

  /// True when the nodes were rebuilt (upload them again; isovalues normalised the same way too).
  /// Nodes stays empty when the property has no opacity function. `tolerance` drops nodes within it
  /// of their neighbours' line, a `maximumNodes` other than 0 limits their number
  /// (TransferFunctionNodesAtMost; Resampled tells whether it resampled).
  bool Update(vtkVolumeProperty* property, double offset, double scale, double tolerance, std::size_t maximumNodes = 0)
  {
    if (property->GetMTime() == this->Time && offset == this->Offset && scale == this->Scale &&
      tolerance == this->Tolerance && maximumNodes == this->MaximumNodes)
      return false;
    this->Nodes = TransferFunctionNodesAtMost(property, maximumNodes, tolerance, this->Resampled);
    for (auto& node : this->Nodes)
      node.Scalar = (node.Scalar - offset) * scale;
    this->Time = property->GetMTime();
    this->Offset = offset;
    this->Scale = scale;
    this->Tolerance = tolerance;
    this->MaximumNodes = maximumNodes;
    return true;
  }

  bool Resampled = false; ///< the last rebuild resampled the function to maximumNodes nodes

private:
  std::size_t MaximumNodes = 0;
  double Tolerance = -1.0;
  vtkMTimeType Time = 0;
  double Offset = std::numeric_limits<double>::quiet_NaN(), Scale = std::numeric_limits<double>::quiet_NaN();
};

} // namespace vtkuv

#endif
