/**
 * @class   vtkHexahedraToTetrahedra
 * @brief   Conforming split of linear 3D cells (hexahedra, voxels, wedges, pyramids) into tetrahedra.
 *
 * Input: any vtkDataSet (vtkImageData, vtkRectilinearGrid, vtkStructuredGrid, vtkUnstructuredGrid).
 * Output: a vtkUnstructuredGrid of VTK_TETRA cells only, every one positively oriented.
 *
 * - SixTetrahedra (default, any mesh): every quadrilateral face is cut along the diagonal through
 *   its smallest global point id, so neighbouring cells always agree; a hexahedron gives 6 tets, a
 *   wedge 3, a pyramid 2. Tetrahedra pass through unchanged.
 * - FiveTetrahedra (structured inputs only): 5 tets per hexahedron with alternating parity so that
 *   neighbours agree. On unstructured input this falls back to SixTetrahedra with a warning.
 *
 * Point data and field data pass through unchanged; cell data is copied to every child tet; the
 * output has a `vtkOriginalCellIds` cell array giving each tet's input cell.
 * 2D, 1D and vertex cells are dropped with one warning giving their count. Non-linear cells
 * (quadratic, Lagrange, Bezier), polyhedra and other unsupported 3D cells are an error and produce
 * an empty output: linearize them first (e.g. vtkTessellatorFilter).
 * Multithreaded with vtkSMPTools.
 */
#ifndef vtkHexahedraToTetrahedra_h
#define vtkHexahedraToTetrahedra_h

#include "vtkUnstructuredVolumeModule.h" // for export macro
#include "vtkUnstructuredGridAlgorithm.h"

class VTKUNSTRUCTUREDVOLUME_EXPORT vtkHexahedraToTetrahedra : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkHexahedraToTetrahedra* New();
  vtkTypeMacro(vtkHexahedraToTetrahedra, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum SplitModes
  {
    SIX_TETRAHEDRA = 0,
    FIVE_TETRAHEDRA = 1
  };

  ///@{
  /**
   * How hexahedra are split; see the class description. Default SIX_TETRAHEDRA.
   */
  vtkSetClampMacro(SplitMode, int, SIX_TETRAHEDRA, FIVE_TETRAHEDRA);
  vtkGetMacro(SplitMode, int);
  void SetSplitModeToSixTetrahedra() { this->SetSplitMode(SIX_TETRAHEDRA); }
  void SetSplitModeToFiveTetrahedra() { this->SetSplitMode(FIVE_TETRAHEDRA); }
  ///@}

protected:
  vtkHexahedraToTetrahedra();
  ~vtkHexahedraToTetrahedra() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int SplitMode = SIX_TETRAHEDRA;

private:
  vtkHexahedraToTetrahedra(const vtkHexahedraToTetrahedra&) = delete;
  void operator=(const vtkHexahedraToTetrahedra&) = delete;
};

#endif
