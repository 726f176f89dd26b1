/**
 * @class   vtkVertexGradientFilter
 * @brief   Per-vertex gradient of a point scalar on tetrahedral, hexahedral and mixed linear meshes.
 *
 * The gradient at a vertex is the volume-weighted mean of the gradients of the cells around it:
 * tetrahedra exactly, hexahedra (and voxels) and wedges from their isoparametric interpolation at
 * the cell centre, pyramids as two tetrahedra. This is exact for fields linear in x, y, z on any
 * valid mesh (distorted ones included). On smooth fields it converges as O(h^2) at interior vertices
 * of smooth meshes and O(h) at boundary vertices, whose cells all lie on one side.
 *
 * Choose the scalar with SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
 * name); by default the active point scalars are used. The result is a 3-component point array,
 * `Gradients` unless SetResultArrayName says otherwise, double for double input and float otherwise.
 *
 * Mirrored cells (negative image spacing, left-handed structured grids) count like any other.
 * Cells touching a non-finite scalar, degenerate cells, and cells that are not linear 3D cells
 * contribute nothing; a vertex with no contributing cell gets NaN. So a NaN in the input
 * changes only the gradients of the vertices that share a cell with it.
 * A missing or multi-component array is an error, and the output then has no gradient array.
 * vtkImageData takes a direct structured path with the same result, without building vertex-cell links.
 * Multithreaded with vtkSMPTools; the result does not depend on the number of threads.
 */
#ifndef vtkVertexGradientFilter_h
#define vtkVertexGradientFilter_h

#include "vtkUnstructuredVolumeModule.h" // for export macro
#include "vtkDataSetAlgorithm.h"

#include <glm/vec3.hpp> // for the gradient buffer
#include <vector>       // for the gradient buffer

class VTKUNSTRUCTUREDVOLUME_EXPORT vtkVertexGradientFilter : public vtkDataSetAlgorithm
{
public:
  static vtkVertexGradientFilter* New();
  vtkTypeMacro(vtkVertexGradientFilter, vtkDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Name of the output gradient array. Default "Gradients".
   */
  vtkSetStringMacro(ResultArrayName);
  vtkGetStringMacro(ResultArrayName);
  ///@}

protected:
  vtkVertexGradientFilter();
  ~vtkVertexGradientFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// Stores per-vertex gradients as the result array, double for double scalars, float otherwise.
  void AddGradientArray(
    vtkDataSet* output, vtkDataArray* scalars, const std::vector<glm::dvec3>& vertexGradients);

  char* ResultArrayName = nullptr;

private:
  vtkVertexGradientFilter(const vtkVertexGradientFilter&) = delete;
  void operator=(const vtkVertexGradientFilter&) = delete;
};

#endif
