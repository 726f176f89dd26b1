// The points of any vtkDataSet as the mappers upload them, 4 floats each: the position relative to the
// centre of the bounds, subtracted in double before the conversion to float (so meshes far from the
// origin keep their precision), and the rendered scalar (vtkuvRenderedScalar.h) normalised
// over its finite values (uvScalarNormalisation.h): with the points, or per cell for cell data.
// Reads VTK data; the mappers' GPU code is elsewhere.
#ifndef vtkuvRecentredPoints_h
#define vtkuvRecentredPoints_h

#include "uvScalarNormalisation.h"
#include "vtkuvRenderedScalar.h"

#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkSMPTools.h"

#include <glm/glm.hpp>

#include <vector>

namespace vtkuv
{

struct RecentredPoints
{
  std::vector<float> Values;     // 4 per point: position - Center, normalised point scalar (0 for cell data)
  std::vector<float> CellValues; // for a cell scalar: its normalised value per input cell, else empty
  glm::dvec3 Center{ 0.0 };
  double Bounds[6] = { 0.0, -1.0, 0.0, -1.0, 0.0, -1.0 }; // of the points, model space
  uv::ScalarNormalisation Normalisation;

  /// From `data`'s points (through vtkDataSet::GetPoint, so image data and rectilinear grids need no
  /// vtkPoints) and the rendered scalar, on its points or its cells. With `previous` (a time step of
  /// the same mesh: the last step's), a normalisation that changes only when the values leave it
  /// (ScalarNormalisation::ForTimeStep).
  void Build(vtkDataSet* data, const RenderedScalar& scalar, const uv::ScalarNormalisation* previous = nullptr)
  {
    const vtkIdType pointCount = data->GetNumberOfPoints();
    const vtkIdType valueCount = scalar.OnCells ? data->GetNumberOfCells() : pointCount;
    this->Normalisation = uv::ScalarNormalisation::OfFiniteValues(static_cast<std::size_t>(valueCount),
      [&scalar](std::size_t id) { return scalar(static_cast<vtkIdType>(id)); });
    if (previous)
      this->Normalisation = this->Normalisation.ForTimeStep(*previous);
    const uv::ScalarNormalisation normalisation = this->Normalisation;
    this->CellValues.assign(scalar.OnCells ? valueCount : 0, 0.0f);
    if (scalar.OnCells)
    {
      vtkSMPTools::For(0, valueCount, [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType c = begin; c < end; ++c)
          this->CellValues[c] = static_cast<float>(normalisation(scalar(c)));
      });
    }
    double* bounds = this->Bounds;
    data->GetBounds(bounds);
    this->Center = glm::dvec3(bounds[0] + bounds[1], bounds[2] + bounds[3], bounds[4] + bounds[5]) * 0.5;
    this->Values.assign(4 * pointCount, 0.0f);
    if (pointCount == 0)
    {
      return;
    }
    double first[3];
    data->GetPoint(0, first); // vtkDataSet::GetPoint(id, x) is thread-safe after one serial call
    const glm::dvec3 center = this->Center;
    vtkSMPTools::For(0, pointCount, [&](vtkIdType begin, vtkIdType end) {
      double x[3];
      for (vtkIdType p = begin; p < end; ++p)
      {
        data->GetPoint(p, x);
        for (int d = 0; d < 3; ++d)
          this->Values[4 * p + d] = static_cast<float>(x[d] - center[d]);
        if (!scalar.OnCells)
          this->Values[4 * p + 3] = static_cast<float>(normalisation(scalar(p)));
      }
    });
  }
};

} // namespace vtkuv

#endif
