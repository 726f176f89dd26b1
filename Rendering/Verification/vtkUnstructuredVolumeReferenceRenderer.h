/**
 * @class   vtkUnstructuredVolumeReferenceRenderer
 * @brief   Exact CPU volume rendering of unstructured grids in double precision: the ground truth.
 *
 * Renders a point scalar on tetrahedra (linear), hexahedra/voxels (trilinear), wedges and pyramids
 * (VTK's isoparametric bases), or a cell scalar (constant in each cell, so each segment's integral is
 * closed-form), with
 * the project's optical model (see README, "Optical model"): every ray visits every cell it meets in
 * exact order (non-convex meshes, holes and re-entering rays included; a ray may enter a curved
 * hexahedron twice), each segment is cut where the scalar crosses a transfer-function node and
 * integrated by adaptive Gauss-Legendre quadrature to an absolute error below Tolerance. Shared faces
 * are intersected with the same arithmetic from both sides, so there are no cracks.
 *
 * Overlapping or tangled cells superpose (each cell holding a point adds its own extinction and
 * emission there; the README's optical model). Mesh and camera are recentred on the mesh's bounds in
 * double before anything else, so a mesh far from the origin renders as it does at the origin, and
 * the inverse isoparametric map converges relative to a cell's size (uvRayCellGeometry.h).
 * vtkLocatorRayMarcher, built on VTK's own locator and cell functions, checks all of this
 * independently on the project's real meshes (Testing/Python/test_reference_against_marcher.py).
 *
 * Rays start on the camera's near clipping plane (perspective and parallel projections). The output
 * is a float RGBA vtkImageData (array "RGBA", premultiplied, over a transparent background), row 0
 * at the bottom like VTK's windows. Multithreaded over pixels with vtkSMPTools.
 *
 * Pentagonal and hexagonal prisms and polyhedra are rendered as vtkHexahedraToTetrahedra splits them
 * (the field every mapper draws for them). Higher-order cells (quadratic, triquadratic and
 * biquadratic tetrahedra, hexahedra, wedges and pyramids; Lagrange and Bezier tetrahedra, hexahedra
 * and wedges up to order 3) are rendered exactly through VTK's own shape functions (quadratic cells)
 * or, for Lagrange and Bezier cells, the same bases written out (uvLatticeBasis.h; VTK 9.1's are
 * slow, per cell object, or give wrong derivatives), in uvCurvedCell.h: each curved face met by Newton, the field by the inverse isoparametric
 * map. Rational Bezier cells (a RationalWeights point array), Lagrange and Bezier pyramids (no VTK 9.1
 * class interpolates them) and other 3D cells are an error; 2D and 1D cells are ignored with a warning.
 * Cells touching a non-finite scalar are left out (transparent) with a warning.
 *
 * Isosurfaces of a cell scalar are drawn as the mappers draw them: the faces between cells on either
 * side of the value (uv::ForEachSurfaceBetweenCells; the mesh boundary holds none), composited with
 * their opacity where the ray crosses the face, unlit -- the colour times the volume property's
 * ambient plus diffuse, what the mappers' Phong gives a surface facing the light. Isosurfaces of a
 * point scalar are not drawn here (one warning).
 */
#ifndef vtkUnstructuredVolumeReferenceRenderer_h
#define vtkUnstructuredVolumeReferenceRenderer_h

#include "vtkAbstractMapper.h" // for VTK_SCALAR_MODE_*
#include "vtkObject.h"
#include "vtkUnstructuredVolumeModule.h" // for export macro

class vtkCamera;
namespace uv
{
class IsosurfaceList;
}
class vtkDataSet;
class vtkImageData;
class vtkVolumeProperty;
namespace vtkuv
{
struct RenderedScalar;
}

class VTKUNSTRUCTUREDVOLUME_EXPORT vtkUnstructuredVolumeReferenceRenderer : public vtkObject
{
public:
  static vtkUnstructuredVolumeReferenceRenderer* New();
  vtkTypeMacro(vtkUnstructuredVolumeReferenceRenderer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The mesh: a vtkUnstructuredGrid (or any vtkDataSet) of tetrahedra, hexahedra and voxels.
  void SetInputData(vtkDataSet* input);
  vtkGetObjectMacro(Input, vtkDataSet);

  ///@{
  /// The array to render, as VTK's mappers select it: ScalarMode VTK_SCALAR_MODE_DEFAULT (the
  /// default) takes the point array named ScalarArrayName, else the cell array of that name, and
  /// without a name the active point scalars, else the active cell scalars;
  /// ..._USE_POINT_FIELD_DATA / ..._USE_CELL_FIELD_DATA take the named (or active) point / cell
  /// array. Of a multi-component array the volume property's colour function selects the magnitude
  /// or a component (vtkScalarsToColors' vector mode and component), as for the mappers.
  vtkSetStringMacro(ScalarArrayName);
  vtkGetStringMacro(ScalarArrayName);
  vtkSetMacro(ScalarMode, int);
  vtkGetMacro(ScalarMode, int);
  void SetScalarModeToDefault() { this->SetScalarMode(VTK_SCALAR_MODE_DEFAULT); }
  void SetScalarModeToUsePointFieldData() { this->SetScalarMode(VTK_SCALAR_MODE_USE_POINT_FIELD_DATA); }
  void SetScalarModeToUseCellFieldData() { this->SetScalarMode(VTK_SCALAR_MODE_USE_CELL_FIELD_DATA); }
  ///@}

  void SetVolumeProperty(vtkVolumeProperty* property);
  vtkGetObjectMacro(VolumeProperty, vtkVolumeProperty);

  void SetCamera(vtkCamera* camera);
  vtkGetObjectMacro(Camera, vtkCamera);

  ///@{
  /// Isosurfaces, as vtkUnstructuredVolumeMapper takes them (drawn for a cell scalar only).
  void AddIsosurface(double value, double red, double green, double blue, double opacity);
  void RemoveAllIsosurfaces();
  int GetNumberOfIsosurfaces();
  ///@}

  vtkSetVector2Macro(ImageSize, int);
  vtkGetVector2Macro(ImageSize, int);

  /// Absolute error allowed per ray segment in colour and optical depth. Default 1e-7.
  vtkSetClampMacro(Tolerance, double, 1e-14, 1e-2);
  vtkGetMacro(Tolerance, double);

  /// Renders; returns false (with an error) on bad input.
  bool Render();

  /// The last rendered image: float RGBA, premultiplied.
  vtkImageData* GetOutput() { return this->Output; }

  /**
   * Writes a premultiplied float RGBA image as an 8-bit RGB PNG, composited over `background`.
   */
  static bool WritePNG(vtkImageData* premultipliedRGBA, const char* fileName, double backgroundRed = 0.0,
    double backgroundGreen = 0.0, double backgroundBlue = 0.0);

protected:
  vtkUnstructuredVolumeReferenceRenderer();
  ~vtkUnstructuredVolumeReferenceRenderer() override;

  vtkDataSet* Input = nullptr;
  char* ScalarArrayName = nullptr;
  int ScalarMode = VTK_SCALAR_MODE_DEFAULT;
  vtkVolumeProperty* VolumeProperty = nullptr;
  vtkCamera* Camera = nullptr;
  int ImageSize[2] = { 512, 512 };
  double Tolerance = 1e-7;
  vtkImageData* Output = nullptr;

private:
  uv::IsosurfaceList* Isosurfaces;
  vtkuv::RenderedScalar FindScalar(vtkDataSet* input);

  vtkUnstructuredVolumeReferenceRenderer(const vtkUnstructuredVolumeReferenceRenderer&) = delete;
  void operator=(const vtkUnstructuredVolumeReferenceRenderer&) = delete;
};

#endif
