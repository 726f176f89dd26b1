// The scalar a renderer of this module integrates, found the VTK way: the mapper's scalar mode and
// array selection pick a point or a cell array (vtkAbstractMapper::GetScalars), and the colour
// transfer function's vector mode picks what of a multi-component array is rendered: its magnitude or
// one component (ParaView's "Magnitude" / "X" entries set exactly that). Reads VTK data only.
#ifndef vtkuvRenderedScalar_h
#define vtkuvRenderedScalar_h

#include "vtkAbstractMapper.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkCellData.h"
#include "vtkDataSet.h"
#include "vtkPointData.h"
#include "vtkScalarsToColors.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace vtkuv
{

struct RenderedScalar
{
  static constexpr int Magnitude = -1;

  vtkDataArray* Array = nullptr;
  bool OnCells = false;
  int Component = 0; // or Magnitude

  explicit operator bool() const { return this->Array != nullptr; }

  /// The rendered value of tuple `id` (a point id, or a cell id when OnCells).
  double operator()(vtkIdType id) const
  {
    if (this->Component != Magnitude)
    {
      return this->Array->GetComponent(id, this->Component);
    }
    double sum = 0.0;
    for (int c = 0; c < this->Array->GetNumberOfComponents(); ++c)
    {
      const double v = this->Array->GetComponent(id, c);
      sum += v * v;
    }
    return std::sqrt(sum);
  }

  /// The same selection on another dataset derived from the one it was found on (e.g. the output of
  /// a split): the array of the same name and association, or for an unnamed one the active
  /// scalars there. Null Array when there is none.
  RenderedScalar On(vtkDataSet* data) const
  {
    RenderedScalar found = *this;
    vtkDataSetAttributes* arrays = this->OnCells ? static_cast<vtkDataSetAttributes*>(data->GetCellData())
                                                 : static_cast<vtkDataSetAttributes*>(data->GetPointData());
    const char* name = this->Array ? this->Array->GetName() : nullptr;
    found.Array = name ? arrays->GetArray(name) : arrays->GetScalars();
    return found;
  }

  /// Describes the selection in messages ("point array 'p', magnitude").
  std::string Describe() const
  {
    std::string text = std::string(this->OnCells ? "cell" : "point") + " array '" +
      (this->Array && this->Array->GetName() ? this->Array->GetName() : "(unnamed)") + "'";
    if (this->Array && this->Array->GetNumberOfComponents() > 1)
    {
      text += this->Component == Magnitude ? ", magnitude" : ", component " + std::to_string(this->Component);
    }
    return text;
  }
};

/// Magnitude or the component the property's colour function selects (VTK's default: component 0).
/// With dependent components (ParaView's "Use Separate Opacity Array" appends the opacity as the
/// last one) the first component is the scalar, as ParaView's own volume mappers take it.
inline int SelectedComponent(vtkVolumeProperty* property, vtkDataArray* array)
{
  const int components = array->GetNumberOfComponents();
  vtkColorTransferFunction* colors = property ? property->GetRGBTransferFunction(0) : nullptr;
  if (components == 1 || !colors || !property->GetIndependentComponents())
  {
    return 0;
  }
  if (colors->GetVectorMode() == vtkScalarsToColors::COMPONENT)
  {
    return std::min(std::max(colors->GetVectorComponent(), 0), components - 1);
  }
  return RenderedScalar::Magnitude; // MAGNITUDE, and RGBCOLORS, which has no single scalar
}

/// The scalar selected on `data` by scalar mode, access mode, array id and name (as a VTK mapper
/// holds them) and `property`'s vector mode; an empty Array when there is none.
inline RenderedScalar FindRenderedScalar(vtkDataSet* data, int scalarMode, int arrayAccessMode, int arrayId,
  const char* arrayName, vtkVolumeProperty* property)
{
  RenderedScalar scalar;
  int cellFlag = 0;
  scalar.Array = vtkAbstractMapper::GetScalars(data, scalarMode, arrayAccessMode, arrayId, arrayName, cellFlag);
  if (!scalar.Array || cellFlag == 2) // 2: field data, which is not attached to points or cells
  {
    scalar.Array = nullptr;
    return scalar;
  }
  scalar.OnCells = cellFlag == 1;
  scalar.Component = SelectedComponent(property, scalar.Array);
  return scalar;
}

} // namespace vtkuv

#endif
