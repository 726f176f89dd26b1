/**
 * @class vtkHexahedralRayCastMapper
 * @brief GPU ray casting of hexahedral meshes with the exact trilinear field along each ray.
 *
 * After "Volume rendering of unstructured hexahedral meshes" (Miranda and Celes). No split into
 * tetrahedra: each ray walks the hexahedra by face adjacency on the GPU (mesh in buffer textures),
 * starting from the boundary faces an entry pass rasterises; depth peeling picks rays up again
 * where they leave a non-convex mesh and re-enter it. Faces are two triangles split along the
 * diagonal through their smallest point id, in every pass and every cell, so the walk is watertight.
 *
 * Along a ray inside a cell the scalar is the exact cubic of the trilinear field in the cell's
 * affine frame (exact for any parallelepiped, in any orientation; for curved cells an approximation
 * whose error the tests and benchmark measure). The integral is split at the cubic's extrema and at
 * transfer-function nodes (safeguarded Newton per monotonic interval), then:
 * - ACCURATE: Gauss-Legendre on each piece, exact optical depth (the paper's Hexa_ACC);
 * - FAST: the scalar linear between split points, pre-integrated with the Psi table (Hexa_FAST);
 * - FIXED_STEPS: FixedSteps constant steps per cell (Hexa_CONST), for comparison.
 * The math is uvHexahedronRay.h (unit-tested); Shaders/uvHexahedralTraverseFS.glsl is its GPU twin.
 *
 * Isosurfaces (any number, each with a colour and opacity) are further split points: where the
 * cubic crosses an isovalue the surface is composited, Phong-lit from the vtkVolumeProperty and the
 * renderer's first light with the exact gradient of the cell's trilinear field (no gradient array).
 *
 * Skipped work: rays stop once their opacity reaches OpacityThreshold (default 0.99); pixels no
 * boundary face covers cost nothing beyond the entry pass; a cell whose scalar range the transfer
 * function makes transparent (and holding no isovalue) costs one range test, no integration.
 *
 * Input: any vtkDataSet of hexahedra and voxels with a point scalar: vtkUnstructuredGrid, and
 * vtkStructuredGrid (blanked cells left out), vtkImageData and vtkRectilinearGrid as they are, with
 * no conversion. Other cells are an error: split mixed meshes with vtkHexahedraToTetrahedra and
 * render them with vtkPreIntegratedTetrahedraMapper.
 */
#ifndef vtkHexahedralRayCastMapper_h
#define vtkHexahedralRayCastMapper_h

#include "vtkUnstructuredGridVolumeMapper.h"
#include "vtkUnstructuredVolumeModule.h" // for export macro

#include <memory> // for std::unique_ptr

class vtkImageData;

class VTKUNSTRUCTUREDVOLUME_EXPORT vtkHexahedralRayCastMapper : public vtkUnstructuredGridVolumeMapper
{
public:
  static vtkHexahedralRayCastMapper* New();
  vtkTypeMacro(vtkHexahedralRayCastMapper, vtkUnstructuredGridVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum IntegrationModes
  {
    ACCURATE = 0,
    FAST = 1,
    FIXED_STEPS = 2
  };
  ///@{
  vtkSetClampMacro(IntegrationMode, int, ACCURATE, FIXED_STEPS);
  vtkGetMacro(IntegrationMode, int);
  void SetIntegrationModeToAccurate() { this->SetIntegrationMode(ACCURATE); }
  void SetIntegrationModeToFast() { this->SetIntegrationMode(FAST); }
  void SetIntegrationModeToFixedSteps() { this->SetIntegrationMode(FIXED_STEPS); }
  ///@}

  ///@{
  /// Steps per cell in FIXED_STEPS mode (default 8).
  vtkSetClampMacro(FixedSteps, int, 1, 1024);
  vtkGetMacro(FixedSteps, int);
  ///@}

  ///@{
  /// Curved cells: map each segment's ends and two inner points (a quarter from each end) into
  /// the cell by the isoparametric inverse (Newton) rather than the affine frame (default on). The
  /// field along the ray is then exact at every face crossing, so continuous from cell to cell,
  /// and between them the cubic through the four exact values. Parallelepipeds (no bilinear terms)
  /// skip this: their frame is exact. Off is the frame alone on every cell (cheaper).
  vtkSetMacro(ExactSegmentEnds, bool);
  vtkGetMacro(ExactSegmentEnds, bool);
  vtkBooleanMacro(ExactSegmentEnds, bool);
  ///@}

  ///@{
  /// Early ray termination: a ray stops when its opacity reaches this (default 0.99; 1 disables).
  vtkSetClampMacro(OpacityThreshold, double, 0.0, 1.0);
  vtkGetMacro(OpacityThreshold, double);
  ///@}

  ///@{
  /// Depth-peeling passes at most (non-convex meshes, holes); default 8.
  vtkSetClampMacro(MaximumPeels, int, 1, 64);
  vtkGetMacro(MaximumPeels, int);
  ///@}

  ///@{
  /// Isosurfaces: a scalar value, an RGB colour and an opacity in [0, 1] each.
  void AddIsosurface(double value, double red, double green, double blue, double opacity);
  void RemoveAllIsosurfaces();
  int GetNumberOfIsosurfaces();
  ///@}

  ///@{
  /// Keep the last frame's premultiplied float RGBA image (tests and benchmark).
  vtkSetMacro(KeepFloatImage, bool);
  vtkGetMacro(KeepFloatImage, bool);
  vtkImageData* GetFloatImage();
  ///@}

  ///@{
  /// What the last frame did: cells in the mesh, boundary faces, peels run, mesh builds, and the
  /// cells found tangled (folded over themselves; warned about once per mesh build).
  vtkIdType GetNumberOfCells();
  vtkIdType GetNumberOfTangledCells();
  /// Bytes of GPU buffers the mesh takes (cells, points, adjacency, boundary faces; not the
  /// screen-sized images).
  vtkIdType GetMeshMemoryInBytes();
  vtkIdType GetNumberOfBoundaryFaces();
  int GetNumberOfPeels();
  int GetNumberOfMeshBuilds();
  ///@}

  /// Any vtkDataSet (the superclass takes vtkUnstructuredGridBase only).
  using Superclass::SetInputData;
  void SetInputData(vtkDataSet* input) override;

  void Render(vtkRenderer* renderer, vtkVolume* volume) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkHexahedralRayCastMapper();
  ~vtkHexahedralRayCastMapper() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  int IntegrationMode = ACCURATE;
  int FixedSteps = 8;
  bool ExactSegmentEnds = true;
  double OpacityThreshold = 0.99;
  int MaximumPeels = 8;
  bool KeepFloatImage = false;

private:
  vtkHexahedralRayCastMapper(const vtkHexahedralRayCastMapper&) = delete;
  void operator=(const vtkHexahedralRayCastMapper&) = delete;

  class Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
