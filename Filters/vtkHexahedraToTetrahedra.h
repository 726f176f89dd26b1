/**
 * @class   vtkHexahedraToTetrahedra
 * @brief   Conforming split of linear 3D cells (hexahedra, voxels, wedges, pyramids, pentagonal and
 *          hexagonal prisms, polyhedra) into tetrahedra.
 *
 * Input: any vtkDataSet (vtkImageData, vtkRectilinearGrid, vtkStructuredGrid, vtkUnstructuredGrid).
 * Output: a vtkUnstructuredGrid of VTK_TETRA cells only, every one positively oriented.
 *
 * - SixTetrahedra (default, any mesh): every polygonal face (quadrilateral, pentagon, hexagon, any
 *   polyhedron face) is fanned from its smallest global point id, so neighbouring cells always agree
 *   (for a quadrilateral: cut along the diagonal through that id). A cell is split as the cone from
 *   its own smallest-id vertex over the faces not containing it: a hexahedron gives 6 tets, a wedge
 *   3, a pyramid 2, a pentagonal prism 9, a hexagonal prism 12. Tetrahedra pass through unchanged.
 * - FiveTetrahedra (structured inputs only): 5 tets per hexahedron with alternating parity so that
 *   neighbours agree. On unstructured input this falls back to SixTetrahedra with a warning.
 *
 * VTK_POLYHEDRON (see uvPolyhedronSplit.h): the face stream may list faces in either orientation.
 * Every face must have at least 3 distinct points and be planar, strictly convex and simple, and
 * the faces must close (each edge used by exactly two faces); lengths are judged relative to the
 * cell's size. A convex polyhedron is split as the cone from its smallest-id vertex, like the fixed
 * types (a hexahedron written as a polyhedron gives the same tets as the VTK_HEXAHEDRON). Any other
 * polyhedron gets one new output point, its centre: position and every point-data array the mean
 * of its distinct vertices (integer arrays rounded, non-numeric arrays take the value of its
 * smallest-id vertex); the centres follow the input's points in cell order. It is split as the cone
 * from the centre over every face's fan, and must be star-shaped with respect to the centre. A
 * polyhedron breaking any of these rules is skipped (no tets) and one error reports how many were
 * skipped, the first one's cell id and why; the other cells are split as usual.
 *
 * Point data and field data pass through unchanged (extended by the centres, if any); cell data is
 * copied to every child tet; the output has a `vtkOriginalCellIds` cell array giving each tet's
 * input cell. 2D, 1D and vertex cells are dropped with one warning giving their count.
 *
 * Higher-order 3D cells (quadratic, triquadratic, Lagrange and Bezier tetrahedra, hexahedra and
 * wedges, quadratic and triquadratic pyramids) are first subdivided into linear cells by
 * vtkHigherOrderSubdivision, whose settings (FieldTolerance, ChordTolerance, MaximumLevel, Level,
 * FieldArrayName) are
 * forwarded from this filter with the same defaults and meaning; the linear cells are then split as
 * above, and `vtkOriginalCellIds` still names the original input cell. The subdivision's messages are
 * reported as this filter's. Other 3D cells (Lagrange and Bezier pyramids) are an error and produce
 * an empty output.
 * Multithreaded with vtkSMPTools.
 */
#ifndef vtkHexahedraToTetrahedra_h
#define vtkHexahedraToTetrahedra_h

#include "vtkUnstructuredVolumeModule.h" // for export macro
#include "vtkUnstructuredGridAlgorithm.h"

class vtkUnstructuredGrid;

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

  ///@{
  /**
   * Settings of the subdivision of higher-order cells (see vtkHigherOrderSubdivision): field and
   * chord tolerances relative to each component's range and each cell's diameter (default 1e-2), the
   * highest automatic level (default 4), a forced level (0, the default: automatic), and the only
   * point array the field tolerance looks at (default: every numeric one).
   */
  vtkSetClampMacro(FieldTolerance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(FieldTolerance, double);
  vtkSetClampMacro(ChordTolerance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ChordTolerance, double);
  vtkSetClampMacro(MaximumLevel, int, 1, 16);
  vtkGetMacro(MaximumLevel, int);
  vtkSetClampMacro(Level, int, 0, 16);
  vtkGetMacro(Level, int);
  vtkSetStringMacro(FieldArrayName);
  vtkGetStringMacro(FieldArrayName);
  ///@}

protected:
  vtkHexahedraToTetrahedra();
  ~vtkHexahedraToTetrahedra() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// The split of linear cells into `output`; 0 on an error.
  int SplitLinear(vtkDataSet* input, vtkUnstructuredGrid* output);
  /// Subdivides the higher-order cells of `input`, then splits the result into `output`.
  int SubdivideAndSplit(vtkDataSet* input, vtkUnstructuredGrid* output);

  int SplitMode = SIX_TETRAHEDRA;
  double FieldTolerance = 1e-2;
  double ChordTolerance = 1e-2;
  int MaximumLevel = 4;
  int Level = 0;
  char* FieldArrayName = nullptr;

private:
  vtkHexahedraToTetrahedra(const vtkHexahedraToTetrahedra&) = delete;
  void operator=(const vtkHexahedraToTetrahedra&) = delete;
};

#endif
