// Vertex gradients of a mapper's rendered scalar, for lighting: a 3-component point array the input
// carries, or vtkVertexGradientFilter's, computed only when the mesh or its scalar changed. Shared
// by every mapper that lights with them. Reads VTK data; the mappers' GPU code is elsewhere.
#ifndef vtkuvVertexGradientCache_h
#define vtkuvVertexGradientCache_h

#include "vtkuvRenderedScalar.h"

#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkVertexGradientFilter.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace vtkuv
{

/// Vertex gradients of `scalar` (a point scalar of `cells`: the rendered magnitude or component),
/// 4 floats per point of `cells` (w unused): `given` when it is a 3-component point array, otherwise
/// computed by vtkVertexGradientFilter. Non-finite gradients become 0 (lit as facing the light).
inline std::vector<float> VertexGradients(vtkDataSet* cells, const RenderedScalar& scalar, vtkDataArray* given)
{
  vtkSmartPointer<vtkDataArray> gradients = given;
  if (!given)
  {
    // The filter sees the structure and the rendered value alone, under a name of its own.
    vtkSmartPointer<vtkDataSet> scalarOnly = vtk::TakeSmartPointer(cells->NewInstance());
    scalarOnly->CopyStructure(cells);
    vtkSmartPointer<vtkDataArray> named = vtk::TakeSmartPointer(scalar.Array->NewInstance());
    if (scalar.Array->GetNumberOfComponents() == 1)
    {
      named->ShallowCopy(scalar.Array);
    }
    else
    {
      named = vtkSmartPointer<vtkDoubleArray>::New();
      named->SetNumberOfTuples(scalar.Array->GetNumberOfTuples());
      for (vtkIdType p = 0; p < named->GetNumberOfTuples(); ++p)
        named->SetComponent(p, 0, scalar(p));
    }
    named->SetName("uvScalar");
    scalarOnly->GetPointData()->AddArray(named);
    vtkNew<vtkVertexGradientFilter> filter;
    filter->SetInputData(scalarOnly);
    filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "uvScalar");
    filter->SetResultArrayName("uvGradient");
    filter->Update();
    gradients = vtkDataSet::SafeDownCast(filter->GetOutputDataObject(0))->GetPointData()->GetArray("uvGradient");
  }
  const vtkIdType pointCount = cells->GetNumberOfPoints();
  std::vector<float> result(4 * pointCount, 0.0f);
  if (gradients)
  {
    vtkSMPTools::For(0, pointCount, [&](vtkIdType begin, vtkIdType end) {
      double g[3];
      for (vtkIdType p = begin; p < end; ++p)
      {
        gradients->GetTuple(p, g);
        for (int d = 0; d < 3; ++d)
          result[4 * p + d] = std::isfinite(g[d]) ? static_cast<float>(g[d]) : 0.0f;
      }
    });
  }
  return result;
}

/// Vertex gradients for lighting (4 floats per point): the point array `arrayName` of the mesh when it
/// has 3 components, else computed (vtkVertexGradientFilter), each only once per mesh version and
/// array.
struct VertexGradientCache
{
  std::vector<float> Values;
  int Computations = 0; ///< times the filter ran

  /// `cells` and `scalar` are what the mesh of version `meshVersion` was built from (its point ids
  /// are theirs). True when the values changed (upload them again). `ignoredArray` is set when an
  /// array of that name exists but has not 3 components (the caller warns).
  bool Update(vtkDataSet* cells, const RenderedScalar& scalar, std::uint64_t meshVersion, const char* arrayName,
    bool& ignoredArray)
  {
    vtkDataArray* given = arrayName ? cells->GetPointData()->GetArray(arrayName) : nullptr;
    ignoredArray = given && given->GetNumberOfComponents() != 3;
    if (ignoredArray)
      given = nullptr;
    if (meshVersion == this->MeshVersion && given == this->Given)
      return false;
    this->Values = VertexGradients(cells, scalar, given);
    this->Computations += given ? 0 : 1;
    this->MeshVersion = meshVersion;
    this->Given = given;
    ++this->Version;
    return true;
  }

  std::uint64_t Version = 0; ///< bumped whenever Values change

private:
  std::uint64_t MeshVersion = 0;
  const void* Given = nullptr; // the array read, or null when computed (compared, never read)
};

} // namespace vtkuv

#endif
