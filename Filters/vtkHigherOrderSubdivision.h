/**
 * @class   vtkHigherOrderSubdivision
 * @brief   Conforming subdivision of higher-order 3D cells into linear cells of their own family.
 *
 * Every higher-order 3D cell VTK 9.1 can interpolate (VTK_QUADRATIC_TETRA, _HEXAHEDRON, _WEDGE and
 * _PYRAMID, VTK_TRIQUADRATIC_HEXAHEDRON, VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON,
 * VTK_QUADRATIC_LINEAR_WEDGE, VTK_BIQUADRATIC_QUADRATIC_WEDGE, VTK_TRIQUADRATIC_PYRAMID, and the
 * Lagrange and Bezier tetrahedra, hexahedra and wedges) is replaced by the linear cells of its
 * lattice of level L (uvIsoparametricLattice.h): L^3 tets, hexahedra or wedges; a pyramid gives
 * L(4L^2-1)/3 pyramids and tets. Positions and every point array at the lattice points come from the
 * cell's own isoparametric interpolation (vtkCell::InterpolateFunctions; integer arrays rounded,
 * non-numeric arrays as vtkAbstractArray::InterpolateTuple gives them).
 *
 * Conformity: the lattice points are shared between cells through keys made of the corners' linear
 * weights, so two cells sharing a face or edge share every output point on it and cut the face into
 * the same sub-faces, whatever their families (a pyramid's sides are cut as a tet's faces, its base as
 * a hexahedron's). That needs the same lattice on both sides of every face, so one level L holds for
 * the whole mesh; per-cell adaptive levels would need transition patterns between levels and are not
 * done. A lattice point at one of the cell's own nodes reuses that input point (at L = 2 a quadratic
 * tet's or triquadratic hexahedron's lattice is its nodes), so no two output points coincide.
 *
 * Level: SetLevel(n) with n > 0 forces L = n. With Level 0 (the default) L is the smallest level in
 * [1, MaximumLevel] for which, on every higher-order cell, at the midpoint of every lattice edge and
 * at the centre of every sub-cell:
 * - |cell's field - linear interpolation from the lattice points| <= FieldTolerance times the range of
 *   that component over the input, for every component of every numeric point array (only the array
 *   named FieldArrayName when that is set). The linear value is the mean of the edge's ends (exact
 *   for any later tetrahedralisation keeping the lattice edges) or of the sub-cell's corners.
 * - |cell's position - linear position| <= ChordTolerance times the cell's diameter (its corners'
 *   bounding-box diagonal).
 * When MaximumLevel is reached without meeting both, a warning gives the worst errors and L is
 * MaximumLevel. After Update, GetChosenLevel() gives L (0 when the input has no higher-order cell),
 * GetFieldError() and GetChordError() the worst relative errors measured at L.
 *
 * Output: a vtkUnstructuredGrid with the input's points first and unchanged, then the new points in
 * the order of the first cell that needs them, in its lattice order; every point array covers every
 * point. Linear 3D cells pass through with their point ids (polyhedra with their faces). Cell data is
 * copied to every child; a `vtkOriginalCellIds` cell array names each output cell's input cell. 2D,
 * 1D and vertex cells (higher-order ones included) are dropped with one warning giving their count.
 * Lagrange and Bezier pyramids (which VTK 9.1 cannot interpolate) are an error and give an empty
 * output.
 */
#ifndef vtkHigherOrderSubdivision_h
#define vtkHigherOrderSubdivision_h

#include "vtkUnstructuredGridAlgorithm.h"
#include "vtkUnstructuredVolumeModule.h" // for export macro

#include <vector> // for ChooseLevel

class VTKUNSTRUCTUREDVOLUME_EXPORT vtkHigherOrderSubdivision : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkHigherOrderSubdivision* New();
  vtkTypeMacro(vtkHigherOrderSubdivision, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The highest level: keeps the lattice keys exact and the output a sane size.
  static constexpr int MaximumSupportedLevel = 16;

  /// True for the higher-order 3D cell types this filter subdivides.
  static bool IsSubdividedCellType(int cellType);

  ///@{
  /// Field error allowed at the chosen level, relative to each component's range. Default 1e-2.
  vtkSetClampMacro(FieldTolerance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(FieldTolerance, double);
  ///@}

  ///@{
  /// Chord (position) error allowed at the chosen level, relative to each cell's diameter. Default 1e-2.
  vtkSetClampMacro(ChordTolerance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ChordTolerance, double);
  ///@}

  ///@{
  /// Highest level the automatic choice may take. Default 4 (64 linear cells per cell).
  vtkSetClampMacro(MaximumLevel, int, 1, MaximumSupportedLevel);
  vtkGetMacro(MaximumLevel, int);
  ///@}

  ///@{
  /// A level forced for every cell, or 0 (default) for the automatic choice.
  vtkSetClampMacro(Level, int, 0, MaximumSupportedLevel);
  vtkGetMacro(Level, int);
  ///@}

  ///@{
  /// The only point array the field tolerance looks at; null or empty (default): every numeric one.
  vtkSetStringMacro(FieldArrayName);
  vtkGetStringMacro(FieldArrayName);
  ///@}

  ///@{
  /// Results of the last update: the level used and the worst relative errors measured there.
  vtkGetMacro(ChosenLevel, int);
  vtkGetMacro(FieldError, double);
  vtkGetMacro(ChordError, double);
  ///@}

protected:
  vtkHigherOrderSubdivision();
  ~vtkHigherOrderSubdivision() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// Sets ChosenLevel, FieldError and ChordError for the given higher-order cells.
  void ChooseLevel(vtkDataSet* input, const std::vector<vtkIdType>& cells);

  double FieldTolerance = 1e-2;
  double ChordTolerance = 1e-2;
  int MaximumLevel = 4;
  int Level = 0;
  char* FieldArrayName = nullptr;
  int ChosenLevel = 0;
  double FieldError = 0.0;
  double ChordError = 0.0;

private:
  vtkHigherOrderSubdivision(const vtkHigherOrderSubdivision&) = delete;
  void operator=(const vtkHigherOrderSubdivision&) = delete;
};

#endif
