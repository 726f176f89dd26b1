/**
 * @class vtkBarycentricShellMapper
 * @brief Tetrahedra sampled in barycentric coordinates on spherical shells; no preprocessing.
 *
 * After "A Generic and Scalable Pipeline for GPU Tetrahedral Grid Rendering" (Georgii and
 * Westermann). Nothing is computed per tetrahedron ahead of a frame: on the GPU each tetrahedron's
 * eye-to-barycentric transform is computed (only the eye's coordinates b_eye are needed) and its back
 * faces are rasterised with each vertex's coordinates and barycentric ray direction (by vertex
 * pulling or by a geometry shader fed one point per tetrahedron: see ProjectionRoute); a fragment then
 * walks its ray inside the tetrahedron without leaving barycentric space (uvBarycentricShell.h is the
 * math, unit-tested). A mesh whose points move every frame (vtkWarpVector, simulation output)
 * therefore costs what a static one does: only the positions are refreshed and uploaded.
 *
 * Render modes:
 * - SHELLS (default): the space in front of the eye is cut into spherical shells (planar slabs under
 *   parallel projection) of SlicesPerShell sample distances each, processed front to back. For each
 *   shell the tetrahedra overlapping it (bucketed on the CPU by their eye-distance range every frame,
 *   uvShellBuckets.h) sample the shell's slices into float render targets (four slices each) blended
 *   with MAX, a slice holding the scalar + 1 where it is inside the mesh and 0 outside; a full-screen
 *   pass then integrates each pixel's samples front to back (the scalar linear between samples, each
 *   segment pre-integrated) and blends them under the image. Error falls with SampleDistance.
 * - CELL_PROJECTION: every visible tetrahedron, sorted back to front, integrates its whole segment:
 *   entry and exit points found in barycentric coordinates from the back face, integrated exactly as
 *   vtkPreIntegratedTetrahedraMapper does (the same shader library). Needs the sort, not the shells.
 *
 * Isosurfaces (vtkUnstructuredVolumeMapper::AddIsosurface): in SHELLS mode, passes over the
 * tetrahedra that hold an isovalue find each pixel's crossings in closed form per tetrahedron,
 * nearest first, one per pass (depth peeling, up to IsosurfaceLayers, stopping when a pass finds
 * none), Phong-lit with the vertex gradients interpolated at the hit (GradientMode's default here;
 * computed again each frame a deforming mesh moves) or the tetrahedron's own gradient, computed on
 * the GPU; the shells composite each at its exact distance. In CELL_PROJECTION every
 * crossing is drawn. Volume shading (vtkVolumeProperty::Shade) applies to CELL_PROJECTION only.
 *
 * Skipped work: tetrahedra the transfer function makes transparent (and holding no isovalue) are in
 * no shell; shells nothing overlaps are skipped; between shells, pixels whose opacity reached
 * OpacityThreshold are masked in the depth buffer so later shells neither sample nor blend them.
 *
 * Input, errors and opaque geometry as vtkPreIntegratedTetrahedraMapper: tetrahedra with a point or
 * cell scalar (the base's selection); other linear cells split once with a warning; NaN tetrahedra
 * left out. Cell projection integrates a cell scalar exactly; the shells sample it, so the jumps
 * between cells are placed to within a sample.
 * The frame's steps, the float image and the final blend are vtkUnstructuredVolumeMapper's.
 */
#ifndef vtkBarycentricShellMapper_h
#define vtkBarycentricShellMapper_h

#include "vtkUnstructuredVolumeTetrahedralMapper.h"
#include "vtkUnstructuredVolumeModule.h" // for export macro

#include <memory> // for std::unique_ptr

class vtkImageData;

class VTKUNSTRUCTUREDVOLUME_EXPORT vtkBarycentricShellMapper : public vtkUnstructuredVolumeTetrahedralMapper
{
public:
  static vtkBarycentricShellMapper* New();
  vtkTypeMacro(vtkBarycentricShellMapper, vtkUnstructuredVolumeTetrahedralMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum RenderModes
  {
    SHELLS = 0,
    CELL_PROJECTION = 1
  };
  ///@{
  vtkSetClampMacro(RenderMode, int, SHELLS, CELL_PROJECTION);
  vtkGetMacro(RenderMode, int);
  void SetRenderModeToShells() { this->SetRenderMode(SHELLS); }
  void SetRenderModeToCellProjection() { this->SetRenderMode(CELL_PROJECTION); }
  ///@}

  ///@{
  /// Distance between samples along a ray in SHELLS mode, in world units. 0 (default): automatic,
  /// AutomaticSamplesAcross (default 128) samples across the mesh's bounding box diagonal, kept while
  /// only the points move (a deforming mesh keeps its segment table). The default was chosen where the
  /// benchmark's error-against-time curve bends (benchmark.py measures both). Interactive frames
  /// (AutoAdjustSampleDistances) widen it by their image's reduction, to the nearest power of two:
  /// fewer shells, each drawing its tetrahedra once.
  vtkSetClampMacro(SampleDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SampleDistance, double);
  vtkSetClampMacro(AutomaticSamplesAcross, int, 2, 100000);
  vtkGetMacro(AutomaticSamplesAcross, int);
  ///@}

  ///@{
  /// Sample distances per shell (3 to 31, default 7): each shell writes SlicesPerShell + 1 slices
  /// (its last is the next shell's first) into (SlicesPerShell + 4) / 4 float render targets. More
  /// means fewer passes and fewer tetrahedra drawn twice, but more targets blended per fragment; the
  /// default was the fastest in the benchmark.
  vtkSetClampMacro(SlicesPerShell, int, 3, 31);
  vtkGetMacro(SlicesPerShell, int);
  ///@}


  ///@{
  /// SHELLS mode: how many isosurface crossings per pixel are drawn at most, nearest first (1 to 8,
  /// default 4). Crossings beyond are left out (behind translucent surfaces only).
  vtkSetClampMacro(IsosurfaceLayers, int, 1, 8);
  vtkGetMacro(IsosurfaceLayers, int);
  ///@}

  ///@{
  /// An image (point scalars, first component) to render instead of the mesh's own scalar, sampled
  /// (trilinearly) through the input's 3-component point texture coordinates, 0 to 1 across the
  /// image's points: the mesh carries the image, so deforming the mesh deforms the image (a
  /// registration, a warped volume). SHELLS only: the field inside a cell is then the image's, not
  /// linear, so isosurfaces and cell projection are left out (a warning) and no cell is skipped as
  /// invisible. The transfer function applies to the image's values. Null (default): the mesh's scalar.
  void SetTextureImage(vtkImageData* image);
  vtkImageData* GetTextureImage();
  ///@}

  /// Tetrahedra, points, gradients, texture coordinates and the cell lists on the GPU (not the
  /// screen-sized images), as of the last frame.
  vtkIdType GetMeshMemoryInBytes() override;

protected:
  /// The statistics (GetFrameStatistics) the shells add to the tetrahedral base's (DrawnTetrahedra
  /// here summed over passes; Sorts by cell projection only, when the view, the points or the drawn
  /// cells change): of the last frame, Shells processed and SkippedShells (empty),
  /// DrawnIsosurfaceLayers (passes that found a crossing), the SampleDistance used; since creation,
  /// SegmentTableBuilds.
  void ReportStatistics(vtkUnstructuredVolumeFrameStatistics* statistics) override;

  vtkBarycentricShellMapper();
  ~vtkBarycentricShellMapper() override;

  bool Prepare(const vtkUnstructuredVolumeFrame& frame) override;
  bool Upload(const vtkUnstructuredVolumeFrame& frame) override;
  bool Draw(const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target) override;
  void ReleaseMapperGraphics() override;
  void ForgetMesh() override;
  vtkUnstructuredVolumeTetrahedralState& GetTetrahedralState() override;

  int RenderMode = SHELLS;
  double SampleDistance = 0.0;
  int AutomaticSamplesAcross = 128;
  int SlicesPerShell = 7;
  int IsosurfaceLayers = 4;

private:
  vtkBarycentricShellMapper(const vtkBarycentricShellMapper&) = delete;
  void operator=(const vtkBarycentricShellMapper&) = delete;

  class Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
