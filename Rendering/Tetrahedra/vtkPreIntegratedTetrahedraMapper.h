/**
 * @class vtkPreIntegratedTetrahedraMapper
 * @brief GPU projected tetrahedra with partial pre-integration and isosurfaces.
 *
 * A vtkUnstructuredVolumeTetrahedralMapper: it prepares the mesh, visible list and order (Prepare),
 * syncs them to the GPU (Upload) and projects the tetrahedra (Draw); the bases do the rest.
 *
 * Renders a vtkUnstructuredGrid of tetrahedra with a point or cell scalar by cell projection on the GPU,
 * after "Volume and Isosurface Rendering with GPU-Accelerated Cell Projection" (Marroquim, Maximo,
 * Farias, Esperanca). Each frame the CPU only sorts the visible tetrahedra (parallel radix sort of
 * centroid distances, or the face order, redone only when the camera or the data changed) and
 * uploads that order. ProjectionRoute chooses how the GPU turns a tetrahedron into fragments:
 * - VERTEX_PULLING (default): 4 vertices per tetrahedron under a fixed index pattern of its faces,
 *   of which the rasteriser keeps the back faces, or the one front face where the outline is a
 *   triangle with three back faces behind it: 1 or 2 triangles per tetrahedron (3 where such a
 *   one crosses the near plane). Each
 *   fragment finds where its ray enters and leaves the tetrahedron from its barycentric coordinates
 *   (as vtkBarycentricShellMapper's cell projection does). Rays begin on the near clipping plane,
 *   which clips the back faces, so a camera inside the mesh sees it correctly.
 * - GEOMETRY_SHADER: the paper's projection: a geometry shader classifies each tetrahedron's
 *   projection (all classes, including the degenerate 3 and 4), finds its thick vertex and emits its
 *   fan of triangles, over which the segment's ends are interpolated; a tetrahedron crossing the near
 *   plane is ray-cast over its own screen rectangle from the plane on, and one wholly before it is
 *   not drawn.
 * The fragment shader integrates the ray segment and the result is composited back to front into a
 * float image that is blended into VTK's scene, clipped at the depth of opaque geometry.
 *
 * Ray casting (RenderMode; AUTOMATIC takes it for meshes of many tetrahedra per pixel, where
 * projecting pays the setup of millions of triangles of a few pixels each): no sort and no
 * triangles per tetrahedron. An entry pass finds, per pixel, the boundary face where the ray enters
 * (each face tested exactly), and a full-screen pass walks the ray from there through the
 * tetrahedra by face adjacency (vtkPreIntegratedTetrahedraWalk; uvTetrahedralWalk.h), integrating
 * each segment as the projected fragments do and compositing front to back until the ray leaves
 * the mesh or reaches OpacityThreshold. Exit faces come from Plücker products computed alike by
 * both tetrahedra of a face, so rays cannot slip between cells; where a ray leaves a non-convex
 * mesh, crosses a hole or a face two cells do not share, the next peel picks it up. The adjacency
 * (16 bytes per tetrahedron) matches faces by position, so seams of repeated points are crossed.
 *
 * Integration modes:
 * - PARTIAL_PRE_INTEGRATION (default): the segment is cut where its scalar crosses a transfer-
 *   function node and each piece is integrated with the Psi table of Moreland and Angel. This is the
 *   exact integral of the project's optical model (uvOpticalModel.h) for a linear scalar, up to the
 *   table's interpolation and float arithmetic (the tests bound both). Editing the transfer
 *   function costs a texture upload at most. SegmentIntegration (see the base) chooses between these
 *   cuts (EXACT) and one trilinear read of a table of whole segments by front scalar, back scalar and
 *   length (TABLE: 128 x 128 x 32 texels, lengths up to the mesh's longest edge, rebuilt on the CPU
 *   in parallel when the transfer function changes), whose cost per fragment does not grow with the
 *   nodes; AUTOMATIC (default) takes the table where its measured error is within
 *   TransferFunctionTolerance.
 * - AVERAGE_SCALAR: the transfer function at the segment's mean scalar (the paper's basic mode).
 *
 * Isosurfaces (any number, each with a colour and opacity) are drawn on top of either mode, lit
 * with the vtkVolumeProperty's ambient, diffuse, specular and specular power and the renderer's
 * first light, the normal interpolated between the vertex gradients at the segment's ends. The
 * gradients come from the point array named by GradientArrayName when the input has it, otherwise
 * vtkVertexGradientFilter computes them once per data change. They are not computed at all when
 * there is no isosurface and shading is off.
 *
 * Input: tetrahedra are drawn as they are; other linear 3D cells (hexahedra, voxels, wedges,
 * pyramids) are split once by vtkHexahedraToTetrahedra, with a warning; higher-order cells are
 * subdivided first at its default tolerances (vtkHigherOrderSubdivision; subdivide upstream to choose
 * them), and cells it takes neither way are an error (nothing drawn). The scalar is selected as the base describes (point or cell array,
 * magnitude or component); a cell scalar gives each tetrahedron points of its own, so the segment
 * through it is constant and integrated exactly. Tetrahedra touching a NaN scalar are not drawn (one
 * warning). An empty grid draws nothing.
 *
 * Skipping (SkipInvisibleCells, default on): tetrahedra whose whole scalar range has zero opacity
 * and holds no isovalue are never drawn; the list of the rest is rebuilt only when a transfer-
 * function edit changes the zero-opacity set. With skipping on and an OpacityThreshold below 1
 * (default 0.999), the order is composited front to back instead (the same sum, under rather than
 * over) in batches, and between batches an opacity mask marks the pixels whose opacity reached the
 * threshold, so the depth test discards their later fragments before they are shaded (the iSBVR
 * paper's pseudo early ray termination). Its error is at most 1 - OpacityThreshold. The order is
 * chosen per frame: front to back costs its mask passes (one full-screen pass per batch, at most
 * about 64 a frame) and, on CPU rasterisers, a slower blend and traversal of the order, and saves
 * only where pixels become opaque; so a frame counts (two occlusion-queried mask passes) the share
 * of the covered pixels it left opaque, and the next frame goes front to back when that share is at
 * least a quarter (the first frame does, to measure it). Under an eighth, the count is taken every
 * eighth frame only: so far from the choice it seldom turns at once. Back to front is kept where nothing
 * can be saved: threshold 1, skipping off, or a mesh of one batch (4096 tetrahedra or fewer).
 */
#ifndef vtkPreIntegratedTetrahedraMapper_h
#define vtkPreIntegratedTetrahedraMapper_h

#include "vtkUnstructuredVolumeTetrahedralMapper.h"
#include "vtkUnstructuredVolumeModule.h" // for export macro

#include <memory> // for std::unique_ptr

class vtkShaderProgram;

class VTKUNSTRUCTUREDVOLUME_EXPORT vtkPreIntegratedTetrahedraMapper : public vtkUnstructuredVolumeTetrahedralMapper
{
public:
  static vtkPreIntegratedTetrahedraMapper* New();
  vtkTypeMacro(vtkPreIntegratedTetrahedraMapper, vtkUnstructuredVolumeTetrahedralMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum IntegrationModes
  {
    AVERAGE_SCALAR = 0,
    PARTIAL_PRE_INTEGRATION = 1
  };
  ///@{
  /// How a segment's colour is integrated (see the class description).
  vtkSetClampMacro(IntegrationMode, int, AVERAGE_SCALAR, PARTIAL_PRE_INTEGRATION);
  vtkGetMacro(IntegrationMode, int);
  void SetIntegrationModeToAverageScalar() { this->SetIntegrationMode(AVERAGE_SCALAR); }
  void SetIntegrationModeToPartialPreIntegration() { this->SetIntegrationMode(PARTIAL_PRE_INTEGRATION); }
  ///@}

  enum RenderModes
  {
    PROJECTION = 0,
    RAY_CASTING = 1,
    AUTOMATIC = 2
  };
  ///@{
  /// How the GPU reaches the pixels (see the class description): PROJECTION draws every visible
  /// tetrahedron in visibility order; RAY_CASTING walks each pixel's ray through the tetrahedra by
  /// face adjacency, front to back, with no sort; AUTOMATIC (default) casts rays where the visible
  /// tetrahedra number at least half the viewport's pixels and none overlap (a folded face: tangled
  /// input cells, which the optical model adds up and a walk would see one of), and projects the
  /// rest. Frames that draw a cell scalar's isosurfaces, or whose near plane may cut the mesh's
  /// bounds, are projected whatever the mode. The statistic UsedRayCasting: what the last frame did;
  /// Peels: with ray casting, the walk passes the last frame ran (one per run of the mesh along the
  /// rays that cross it most often: a convex mesh takes one).
  vtkSetClampMacro(RenderMode, int, PROJECTION, AUTOMATIC);
  vtkGetMacro(RenderMode, int);
  void SetRenderModeToProjection() { this->SetRenderMode(PROJECTION); }
  void SetRenderModeToRayCasting() { this->SetRenderMode(RAY_CASTING); }
  void SetRenderModeToAutomatic() { this->SetRenderMode(AUTOMATIC); }
  ///@}

  ///@{
  /// With CountShadedFragments on (default off: an occlusion query per batch, each waited for), the
  /// statistic ShadedFragments counts the fragments that passed the opacity mask and were not
  /// discarded.
  vtkSetMacro(CountShadedFragments, bool);
  vtkGetMacro(CountShadedFragments, bool);
  ///@}

  /// Ids, points, gradients, order and face indices (not the screen-sized images).
  vtkIdType GetMeshMemoryInBytes() override;

  /// Bytes the mapper keeps in host memory beside its input between frames, as of the last frame:
  /// its copies of ids, positions and scalars, per-cell ranges, the drawn list, the order and the
  /// face adjacency (not the GPU buffers, nor a CPU rasteriser's copies of them, nor a split of
  /// non-tetrahedral input).
  vtkIdType GetHostMemoryInBytes();

protected:
  /// The statistics (GetFrameStatistics) the mapper adds besides UsedRayCasting and Peels (above)
  /// and the tetrahedral base's: since creation, MeshUploads, TransferFunctionUploads and VisibleListBuilds; the segment table's
  /// (SegmentIntegration) UsedSegmentTable (the last frame read it), SegmentTableBuilds and
  /// SegmentTableError, its largest error against the exact segments as last built (any channel of
  /// premultiplied colour and opacity; -1 before the first build); early termination's (see the
  /// class description) DrewFrontToBack, OpaquePixelShare (the share of covered pixels the last
  /// measured frame left opaque, which the next frame's order is chosen by; -1 where the order is
  /// not chosen; measured every frame from half the share that turns the order on, else every
  /// eighth frame), OpacityMaskRefreshes and ShadedFragments.
  void ReportStatistics(vtkUnstructuredVolumeFrameStatistics* statistics) override;

  vtkPreIntegratedTetrahedraMapper();
  ~vtkPreIntegratedTetrahedraMapper() override;

  bool Prepare(const vtkUnstructuredVolumeFrame& frame) override;
  bool Upload(const vtkUnstructuredVolumeFrame& frame) override;
  bool Draw(const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target) override;
  void ReleaseMapperGraphics() override;
  void ForgetMesh() override;
  vtkUnstructuredVolumeTetrahedralState& GetTetrahedralState() override;

  vtkShaderProgram* ReadyTetrahedraProgram(
    const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target);
  void UnbindTetrahedraResources(vtkUnstructuredVolumeFloatTarget& target);
  void DrawBackToFront(const vtkUnstructuredVolumeFrame& frame, vtkShaderProgram* program);
  bool DrawFrontToBack(
    const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target, vtkShaderProgram* program);
  bool ChooseSegmentTable(const vtkUnstructuredVolumeFrame& frame);
  bool ChooseRayCasting(const vtkUnstructuredVolumeFrame& frame);
  bool OrderIsChosen();
  bool ChooseFrontToBack();
  bool MeasureOpaqueShare(const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target);
  vtkShaderProgram* ReadyMaskProgram(const vtkUnstructuredVolumeFrame& frame);

  bool DrawByRayCasting(const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target);

  bool CountShadedFragments = false;
  int RenderMode = AUTOMATIC;
  int IntegrationMode = PARTIAL_PRE_INTEGRATION;

private:
  vtkPreIntegratedTetrahedraMapper(const vtkPreIntegratedTetrahedraMapper&) = delete;
  void operator=(const vtkPreIntegratedTetrahedraMapper&) = delete;

  class Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
