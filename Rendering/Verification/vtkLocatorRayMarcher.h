/**
 * @class   vtkLocatorRayMarcher
 * @brief   Independent brute-force check of the reference renderer: fine uniform steps along each
 *          pixel's ray, every sample located with VTK's own cell locator and cell functions.
 *
 * Shares no code with vtkUnstructuredVolumeReferenceRenderer. Each pixel's ray runs from the near
 * plane towards the far plane (the camera's composite projection matrix for the image's aspect,
 * inverted and applied to the pixel centre at NDC depth -1 and +1) and is cut to the input's
 * bounding box; that part is split into NumberOfSteps uniform steps. At the middle of each step
 * every cell that contains the sample (vtkStaticCellLocator::FindCellsWithinBounds on a tiny box,
 * then vtkCell::EvaluatePosition == 1 with pcoords strictly in the cell's parametric domain) adds
 * its own extinction tau(s) and emission c(s) tau(s), s being the point scalar interpolated with
 * the cell's weights (or the cell's own value, for a cell scalar): overlapping cells superpose (a point on a face between two cells belongs to
 * one of them: membership is decided 1e-9 of the bounds' diagonal away, in a fixed generic
 * direction). A step whose ends differ in "inside the mesh" is cut at the boundary (bisection)
 * and only its inside part is integrated; so is a step whose ends agree but whose middle does not
 * (a thin part of the mesh, or a thin gap). Transmittance is updated exactly per step
 * (emission-absorption, premultiplied colour).
 *
 * Transfer function (component 0 of the vtkVolumeProperty): at the sorted union of the opacity
 * and colour nodes, tau = -ln(1 - min(alpha, 1 - 1e-9)) / ScalarOpacityUnitDistance and c = the
 * colour there; between those nodes tau and c are linear in s, outside them constant. Only plain
 * functions are accepted: RGB colour space, linear scale, no discretisation, every node with
 * midpoint 0.5 and sharpness 0, 1D transfer-function mode.
 *
 * Pentagonal and hexagonal prisms and polyhedra, whose parametric coordinates VTK spans over the
 * cell's bounding box, count a sample as inside when it is behind every face's plane (so they must
 * be convex); their weights are VTK's (mean value coordinates for polyhedra).
 *
 * Cells that are not 3D, or that have a point (for a cell scalar: a value) with a non-finite scalar,
 * are ignored. The locator is built once per input (rebuilt when the input's MTime changes). Pixels run in parallel
 * (vtkSMPTools). Gradient opacity and shading are ignored.
 */
#ifndef vtkLocatorRayMarcher_h
#define vtkLocatorRayMarcher_h

#include "vtkObject.h"
#include "vtkSmartPointer.h"             // for ivars
#include "vtkTimeStamp.h"                // for ivars
#include "vtkUnstructuredVolumeModule.h" // for export macro

#include <vector> // for ivars

class vtkCamera;
class vtkDataSet;
class vtkDataArray;
class vtkFloatArray;
class vtkIdTypeArray;
class vtkStaticCellLocator;
class vtkVolumeProperty;

class VTKUNSTRUCTUREDVOLUME_EXPORT vtkLocatorRayMarcher : public vtkObject
{
public:
  static vtkLocatorRayMarcher* New();
  vtkTypeMacro(vtkLocatorRayMarcher, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The mesh (any vtkDataSet; its 3D cells are used).
  void SetInputData(vtkDataSet* input);
  vtkDataSet* GetInput();
  ///@}

  ///@{
  /// The array to render: the point (CellScalars off, the default) or cell array of that name; the
  /// active point or cell scalars when unset. ScalarComponent: the component rendered (default 0),
  /// or -1 for the magnitude (Euclidean norm of the tuple). Set explicitly here, unlike the
  /// renderers, so that the check does not share their selection code.
  vtkSetStringMacro(ScalarArrayName);
  vtkGetStringMacro(ScalarArrayName);
  vtkSetMacro(CellScalars, bool);
  vtkGetMacro(CellScalars, bool);
  vtkBooleanMacro(CellScalars, bool);
  vtkSetClampMacro(ScalarComponent, int, -1, VTK_INT_MAX);
  vtkGetMacro(ScalarComponent, int);
  ///@}

  ///@{
  void SetVolumeProperty(vtkVolumeProperty* property);
  vtkVolumeProperty* GetVolumeProperty();
  void SetCamera(vtkCamera* camera);
  vtkCamera* GetCamera();
  ///@}

  ///@{
  /// Image width and height in pixels (the camera's aspect is width / height).
  vtkSetVector2Macro(ImageSize, int);
  vtkGetVector2Macro(ImageSize, int);
  ///@}

  ///@{
  /// Uniform steps per ray across the part of the ray inside the input's bounding box.
  vtkSetClampMacro(NumberOfSteps, int, 1, VTK_INT_MAX);
  vtkGetMacro(NumberOfSteps, int);
  ///@}

  /**
   * Marches the rays of the given pixels (index p: x = p % width, y = p / width, y counting from
   * the bottom row) and fills `rgba` with one 4-component tuple per pixel: premultiplied R, G, B
   * and opacity. False (with an error) on bad input.
   */
  bool MarchPixels(vtkIdTypeArray* pixels, vtkFloatArray* rgba);

protected:
  vtkLocatorRayMarcher();
  ~vtkLocatorRayMarcher() override;

  /// Builds the locator and the cell bounds when the input changed.
  void UpdateLocator();
  /// The scalar array to march once every setting and argument checks out; null (with an error)
  /// otherwise.
  vtkDataArray* ValidatedScalars(vtkIdTypeArray* pixels, vtkFloatArray* rgba);

  vtkSmartPointer<vtkDataSet> Input;
  vtkSmartPointer<vtkVolumeProperty> VolumeProperty;
  vtkSmartPointer<vtkCamera> Camera;
  char* ScalarArrayName = nullptr;
  bool CellScalars = false;
  int ScalarComponent = 0;
  int ImageSize[2] = { 0, 0 };
  int NumberOfSteps = 4000;

  vtkSmartPointer<vtkStaticCellLocator> Locator; // holds the input it was built for
  vtkTimeStamp LocatorBuildTime;
  std::vector<double> CellBounds; // 6 per cell, from the locator's input (curved cells: their shape's)
  double CurvedReach = 0.0;       // how far curved cells reach past their points' bounds

private:
  vtkLocatorRayMarcher(const vtkLocatorRayMarcher&) = delete;
  void operator=(const vtkLocatorRayMarcher&) = delete;
};

#endif
