// The project's transfer function (uvOpticalModel.h) from a vtkVolumeProperty: one place, so the
// reference renderer and every mapper read a property the same way.
#ifndef uvTransferFunctionFromVolumeProperty_h
#define uvTransferFunctionFromVolumeProperty_h

#include "uvOpticalModel.h"

#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <vector>

namespace uv
{

/// Nodes: the union of the colour and opacity nodes. Where VTK's functions are not linear between
/// their nodes (a midpoint other than 0.5, a non-zero sharpness, or a colour space other than RGB),
/// `subdivisions` extra nodes per interval make the piecewise-linear model follow them closely.
/// Returns an empty optional-like result (no nodes) when the property has no opacity function.
inline std::vector<TransferFunction::Node> TransferFunctionNodes(
  vtkVolumeProperty* property, int subdivisions = 32)
{
  std::vector<TransferFunction::Node> nodes;
  vtkPiecewiseFunction* opacity = property ? property->GetScalarOpacity(0) : nullptr;
  if (!opacity || opacity->GetSize() == 0)
  {
    return nodes;
  }
  const bool gray = property->GetColorChannels(0) == 1;
  vtkColorTransferFunction* color = gray ? nullptr : property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* grayFunction = gray ? property->GetGrayTransferFunction(0) : nullptr;
  const double unitDistance = property->GetScalarOpacityUnitDistance(0);

  std::vector<double> scalars;
  bool curved = false;
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
  if (curved && scalars.size() > 1)
  {
    std::vector<double> refined;
    for (std::size_t i = 0; i + 1 < scalars.size(); ++i)
    {
      for (int k = 0; k < subdivisions; ++k)
      {
        refined.push_back(scalars[i] + (scalars[i + 1] - scalars[i]) * k / subdivisions);
      }
    }
    refined.push_back(scalars.back());
    scalars = refined;
  }
  for (double s : scalars)
  {
    glm::dvec3 rgb(1.0);
    if (color)
    {
      color->GetColor(s, &rgb.x);
    }
    else if (grayFunction)
    {
      rgb = glm::dvec3(grayFunction->GetValue(s));
    }
    nodes.push_back({ s, rgb, ExtinctionFromOpacity(opacity->GetValue(s), unitDistance) });
  }
  return nodes;
}

} // namespace uv

#endif
