/**
 * @class vtkUnstructuredVolumeMapper
 * @brief The base of this module's volume mappers: one frame as Prepare, Upload, Draw.
 *
 * What every mapper shares lives here, once: the rendered scalar's selection (FindScalar: a point
 * or cell array by the scalar mode and SelectScalarArray, the default taking point scalars, else
 * cell scalars; of a multi-component array its magnitude or one component, as the colour transfer
 * function's vector mode and component say, which ParaView's "Magnitude" / "X" entries set), the
 * isosurface list and the gradients that light them, the float image a test or the benchmark may
 * keep, the projection route of the tetrahedral mappers, the checks of the render call's arguments with one set of error messages,
 * the camera (vtkUnstructuredVolumeFrame), the premultiplied float target with the scene's depth
 * (vtkUnstructuredVolumeFloatTarget), the OpenGL state saved around the mapper's passes, the final
 * blend into VTK's scene, and releasing it all. A cell scalar is constant in each cell: no mapper
 * draws isosurfaces or shades the volume for it yet (one warning says so).
 *
 * Render is final and reads as the frame's steps:
 *   1. check the window, the volume's property and the input (an empty input draws nothing);
 *   2. Prepare: the mapper's CPU work (mesh, transfer function, visibility, order); false means
 *      nothing to draw, after the mapper reported any error;
 *   3. Upload: GPU resources brought to the versions Prepare produced;
 *   4. Draw: the mapper's passes into the bound float target, which the base cleared, with the
 *      scene's depth copied beside it (the far plane where no prop may have drawn any);
 *   5. read back (KeepFloatImage), blend into the scene, check for a GL error.
 * Each subclass implements those three steps, ReleaseMapperGraphics and GetMeshMemoryInBytes, and
 * calls CheckGLErrors after each of its passes (the GL-error debug mode, SetGLErrorChecks).
 */
#ifndef vtkUnstructuredVolumeMapper_h
#define vtkUnstructuredVolumeMapper_h

#include "vtkUnstructuredGridVolumeMapper.h"
#include "vtkUnstructuredVolumeModule.h" // for export macro

#include <cstdint>    // for std::uint64_t
#include <functional> // for std::function
#include <memory>     // for std::unique_ptr
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkDataArray;
class vtkDataSet;
class vtkImageData;
class vtkOpenGLRenderWindow;
class vtkVolumeProperty;
class vtkUnstructuredVolumeFloatTarget;
class vtkUnstructuredVolumeFrameStatistics;
struct vtkUnstructuredVolumeFrame;
namespace uv
{
struct Isosurface;
class IsosurfaceList;
}
namespace vtkuv
{
class NormalisedTransferFunction;
struct RenderedScalar;
struct VertexGradientCache;
}

class VTKUNSTRUCTUREDVOLUME_EXPORT vtkUnstructuredVolumeMapper : public vtkUnstructuredGridVolumeMapper
{
public:
  vtkTypeMacro(vtkUnstructuredVolumeMapper, vtkUnstructuredGridVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Isosurfaces: a scalar value, an RGB colour and an opacity in [0, 1] each (any number; equal
  /// values keep the order they were added in).
  void AddIsosurface(double value, double red, double green, double blue, double opacity);
  void RemoveAllIsosurfaces();
  int GetNumberOfIsosurfaces();
  ///@}

  ///@{
  /// Keep a copy of the last frame's premultiplied float RGBA image (for accuracy tests and the
  /// benchmark; costs a read-back per frame). GetFloatImage returns it, or null.
  vtkSetMacro(KeepFloatImage, bool);
  vtkGetMacro(KeepFloatImage, bool);
  vtkImageData* GetFloatImage();
  ///@}

  ///@{
  /// Pixels per ray along each image axis (as vtkGPUVolumeRayCastMapper's): 1 (default) casts a
  /// ray through every pixel; 2 draws an image of half the viewport's width and height, a quarter
  /// of the rays or fragments, and stretches it over the viewport with linear filtering. Trades
  /// error at edges and fine detail for speed (the benchmark measures both); opaque geometry clips
  /// the volume at the depth nearest each image pixel's centre. KeepFloatImage keeps the smaller
  /// image. Clamped to [1, 16].
  vtkSetClampMacro(ImageSampleDistance, double, 1.0, 16.0);
  vtkGetMacro(ImageSampleDistance, double);
  ///@}

  ///@{
  /// Automatic image sample distances, as VTK's own volume mappers have them (default on). A frame
  /// the renderer allows less than a second (vtkVolume's allocated render time, which follows the
  /// render window's DesiredUpdateRate: vtkRenderWindowInteractor raises it while the camera moves)
  /// is interactive: it draws a reduced image whose distance between rays, within
  /// [MinimumImageSampleDistance, MaximumImageSampleDistance] and never finer than
  /// ImageSampleDistance, is chosen from the last frames' times to fit the time allowed
  /// (uvAdaptiveImageSampleDistance.h). Still frames are drawn at ImageSampleDistance, exactly as
  /// with it off. The mapper waits for the GPU to finish each frame to time it (vtkVolume reads the
  /// time as the mapper's TimeToDraw). The statistics UsedImageSampleDistance, InteractiveFrame (it
  /// was drawn as interactive) and FrameSeconds: the last frame's.
  vtkSetMacro(AutoAdjustSampleDistances, bool);
  vtkGetMacro(AutoAdjustSampleDistances, bool);
  vtkBooleanMacro(AutoAdjustSampleDistances, bool);
  vtkSetClampMacro(MinimumImageSampleDistance, double, 1.0, 16.0);
  vtkGetMacro(MinimumImageSampleDistance, double);
  vtkSetClampMacro(MaximumImageSampleDistance, double, 1.0, 16.0);
  vtkGetMacro(MaximumImageSampleDistance, double);
  ///@}

  enum ProjectionRoutes
  {
    VERTEX_PULLING = 0,
    GEOMETRY_SHADER = 1
  };
  ///@{
  /// How the tetrahedral mappers turn tetrahedra into fragments: VERTEX_PULLING (default), vertices
  /// pulled from buffer textures under a fixed index pattern; GEOMETRY_SHADER, one point per
  /// tetrahedron and a geometry shader emitting its faces (the papers' route; llvmpipe runs geometry
  /// shaders slowly). Same image; the benchmark compares their speed. The hexahedral ray caster
  /// rasterises boundary faces and ignores it, but for the meshes of tetrahedra it hands over.
  vtkSetClampMacro(ProjectionRoute, int, VERTEX_PULLING, GEOMETRY_SHADER);
  vtkGetMacro(ProjectionRoute, int);
  void SetProjectionRouteToVertexPulling() { this->SetProjectionRoute(VERTEX_PULLING); }
  void SetProjectionRouteToGeometryShader() { this->SetProjectionRoute(GEOMETRY_SHADER); }
  ///@}

  ///@{
  /// Leave out the cells the transfer function makes invisible: those whose scalar range meets
  /// only zero extinction and holds no isovalue (uvCellVisibility.h). The tetrahedral mappers draw
  /// no such tetrahedron; the hexahedral ray caster walks only the visible cells, its rays entering
  /// at the visible region's front, leaving at its back and leaping over invisible runs between
  /// (uvVisibleRegion.h). The tetrahedra mapper also composites front to back then, so that pixels
  /// past OpacityThreshold stop being shaded (its image changes by at most 1 - OpacityThreshold;
  /// the others' not at all). Default on; off is for measuring what it saves.
  vtkSetMacro(SkipInvisibleCells, bool);
  vtkGetMacro(SkipInvisibleCells, bool);
  vtkBooleanMacro(SkipInvisibleCells, bool);
  ///@}

  ///@{
  /// Transfer-function nodes within this of the straight line between the nodes kept around them
  /// are dropped before the mappers cut segments at nodes (uvTransferFunctionSimplification.h):
  /// colour within it in each channel and extinction within it relatively, at every scalar, so a
  /// segment's colour and opacity change by at most about twice it. A sampled colour map (256 nodes)
  /// then costs what its curvature needs. Default 1e-3, under a display's 1/255; 0 keeps every node
  /// (reference-grade images). The statistic TransferFunctionNodes: the nodes the last frame used.
  vtkSetClampMacro(TransferFunctionTolerance, double, 0.0, 0.1);
  vtkGetMacro(TransferFunctionTolerance, double);
  ///@}

  enum SegmentIntegrations
  {
    AUTOMATIC = 0,
    TABLE = 1,
    EXACT = 2
  };
  ///@{
  /// How a segment along which the scalar is linear (a ray through a tetrahedron, or between two
  /// shell samples) is integrated. EXACT: cut at every transfer-function node crossed, each piece
  /// pre-integrated (reference-grade; the cost grows with the nodes crossed). TABLE: one filtered
  /// read of a table of whole segments, built on the CPU in parallel when the transfer function
  /// changes: one read whatever the nodes, but features narrower than a few of its texels blur.
  /// AUTOMATIC (default): the table where its largest error against the exact segments, measured
  /// when it is built, is within TransferFunctionTolerance; EXACT otherwise. Isosurfaces and
  /// shading need the cuts and always integrate exactly. The hexahedral ray caster, whose scalar
  /// is not linear along a ray, ignores it, but for the meshes of tetrahedra it hands over.
  vtkSetClampMacro(SegmentIntegration, int, AUTOMATIC, EXACT);
  vtkGetMacro(SegmentIntegration, int);
  void SetSegmentIntegrationToAutomatic() { this->SetSegmentIntegration(AUTOMATIC); }
  void SetSegmentIntegrationToTable() { this->SetSegmentIntegration(TABLE); }
  void SetSegmentIntegrationToExact() { this->SetSegmentIntegration(EXACT); }
  ///@}

  enum VisibilityOrders
  {
    CENTROID_ORDER = 0,
    FACE_ORDER = 1
  };
  ///@{
  /// The order tetrahedra are composited in where they are drawn one by one (the tetrahedra
  /// mapper, the shells' cell projection). CENTROID_ORDER: by the distance of their centroids from
  /// the eye, which is wrong for some pairs of long, twisted or nearby tetrahedra. FACE_ORDER: that
  /// order changed wherever two tetrahedra sharing a face are in the wrong order for the side of
  /// the face the eye is on (MPVO; uvFaceAdjacencyOrder.h), and where the mesh is not convex, for
  /// each pair of tetrahedra a pixel's ray leaves the mesh from and enters it again by
  /// (uvBoundaryGapOrder.h): exact along every pixel's ray unless the constraints form a cycle. It
  /// costs a face adjacency (16 bytes per tetrahedron, built once per mesh), a serial sweep per
  /// view and, on a non-convex mesh, the rays through its boundary faces per view.
  /// The statistics CyclesBroken: the tetrahedra drawn before a neighbour behind them because the
  /// constraints formed a cycle; GapConstraints: the pairs across gaps in the last order.
  vtkSetClampMacro(VisibilityOrder, int, CENTROID_ORDER, FACE_ORDER);
  vtkGetMacro(VisibilityOrder, int);
  void SetVisibilityOrderToCentroidOrder() { this->SetVisibilityOrder(CENTROID_ORDER); }
  void SetVisibilityOrderToFaceOrder() { this->SetVisibilityOrder(FACE_ORDER); }
  ///@}

  enum GradientModes
  {
    VERTEX_GRADIENTS = 0,
    CELL_GRADIENTS = 1
  };
  ///@{
  /// What lights isosurfaces of a point scalar (and the shells' shaded cell projection).
  /// VERTEX_GRADIENTS: per-vertex gradients (GradientArrayName, else vtkVertexGradientFilter on the
  /// rendered scalar, once per change of the mesh or its scalar) interpolated at each point: smooth.
  /// CELL_GRADIENTS: each cell's own exact gradient, nothing computed ahead: faceted where cells are
  /// coarse. The shells default to vertex gradients, the hexahedral ray caster to the cell's; the
  /// tetrahedra mapper lights with vertex gradients always and ignores it.
  vtkSetClampMacro(GradientMode, int, VERTEX_GRADIENTS, CELL_GRADIENTS);
  vtkGetMacro(GradientMode, int);
  void SetGradientModeToVertexGradients() { this->SetGradientMode(VERTEX_GRADIENTS); }
  void SetGradientModeToCellGradients() { this->SetGradientMode(CELL_GRADIENTS); }
  ///@}

  ///@{
  /// A 3-component point array of scalar gradients that vertex gradients are read from; when the
  /// input has no array of this name (default "Gradients"), vtkVertexGradientFilter computes them.
  vtkSetStringMacro(GradientArrayName);
  vtkGetStringMacro(GradientArrayName);
  ///@}

  ///@{
  /// Early ray termination: a pixel's ray stops once its accumulated opacity reaches this (1: never).
  /// The hexahedral caster stops each ray (default 0.999), the shells mask pixels between shells
  /// (default 0.999), the tetrahedra mapper between batches of its front-to-back order, with
  /// SkipInvisibleCells on (default 0.999). What is left out weighs at most 1 - threshold.
  vtkSetClampMacro(OpacityThreshold, double, 0.0, 1.0);
  vtkGetMacro(OpacityThreshold, double);
  ///@}

  /// What the mapper did in its last frame and since its mesh was built, as named numbers, for
  /// tests and the benchmark (filled when asked; owned by the mapper). Every mapper reports what
  /// its input's changes made it redo, recognised by content (a reader's time steps are new
  /// objects): MeshBuilds (new cells, another array), PointRefreshes (same cells, the points moved)
  /// and ValueRefreshes (same cells, new values; the points may have moved too), which keep the
  /// cells' split, adjacency and what depends on them; and TransferFunctionNodes, CyclesBroken and
  /// GapConstraints (above). Each mapper's header names what it adds.
  vtkUnstructuredVolumeFrameStatistics* GetFrameStatistics();

  /// Bytes of GPU buffers the mesh takes (not the screen-sized images), as of the last frame.
  virtual vtkIdType GetMeshMemoryInBytes() = 0;

  ///@{
  /// The GL-error debug mode, for every mapper of the process: after each named pass (uploads, each
  /// mapper's draw passes, the final blend) glGetError is checked and an error naming the pass and
  /// the GL error is reported (vtkErrorMacro), so that a test observing errors fails. Off by default;
  /// on from the start when the environment has UV_CHECK_GL_ERRORS=1 (read once). Off, a check costs
  /// one test of this flag; on, each check waits for the GPU.
  static void SetGLErrorChecks(bool on);
  static bool GetGLErrorChecks();
  ///@}

  void Render(vtkRenderer* renderer, vtkVolume* volume) final;
  /// Frees the GPU objects, in the context of the window they were made in; a window the mapper does
  /// not render in (the other of two sharing it) holds none, and is ignored.
  void ReleaseGraphicsResources(vtkWindow* window) final;

protected:
  vtkUnstructuredVolumeMapper();
  ~vtkUnstructuredVolumeMapper() override;

  /// CPU work of a frame; false when there is nothing to draw (errors reported by the mapper).
  virtual bool Prepare(const vtkUnstructuredVolumeFrame& frame) = 0;
  /// Brings GPU resources up to date (the context is current); false on failure.
  virtual bool Upload(const vtkUnstructuredVolumeFrame& frame) = 0;
  /// Draws into `target`, bound and cleared; must leave it bound. False on failure (reported).
  virtual bool Draw(const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target) = 0;
  /// Releases the mapper's own GPU resources (the base releases the float target).
  virtual void ReleaseMapperGraphics() = 0;
  /// Forgets the mesh the mapper built, so that the next frame builds it again: after memory ran
  /// out half-way through Prepare or Upload, what it holds is incomplete. Called after
  /// ReleaseMapperGraphics.
  virtual void ForgetMesh() = 0;
  /// The model-space bounds of what the mapper draws, after Prepare: by default the input's; a
  /// mapper that draws a subdivision of curved cells gives its points' (they can reach beyond the
  /// nodes'). The float target's clear and composite cover only the pixels these can project to.
  virtual void GetDrawnBounds(double bounds[6]);

  /// Runs a step of the frame. Host memory running out in it (std::bad_alloc, or a size no array can
  /// hold) is one error and a frame drawn as nothing, never a crash: the half-built mesh and GPU
  /// objects are forgotten, so that a later frame, with memory to spare, builds them again.
  bool WithinMemory(const char* step, const std::function<bool()>& run);

  /// The scalar the mapper is set to render on `data`: a point or cell array by scalar mode, array
  /// access, id or name; magnitude or a component by `property`'s colour function (VTK's vector
  /// mode). False after reporting why there is none.
  bool FindScalar(vtkDataSet* data, vtkVolumeProperty* property, vtkuv::RenderedScalar& scalar);

  /// For a cell scalar (constant in each cell): says once that shading, which needs a field varying
  /// inside cells, is off, and that isosurfaces are not drawn unless the mapper draws a cell scalar's
  /// (`facesBetweenCells`: the faces between cells on either side of the value). Returns true when
  /// the scalar is on cells.
  bool WarnCellScalarLimits(const vtkuv::RenderedScalar& scalar, bool shade, bool facesBetweenCells);

  /// Adds the mapper's statistics to `statistics` (GetFrameStatistics); an override adds its own
  /// after the superclass's.
  virtual void ReportStatistics(vtkUnstructuredVolumeFrameStatistics* statistics);

  /// The commit step of every Prepare, once its mesh knows the scalar's normalisation (a value v is
  /// drawn as (v - offset) * scale): the transfer function's nodes and the drawn isosurfaces,
  /// normalised alike, and NumberOfTransferFunctionNodes. `maximumNodes` (0: any number) bounds the
  /// nodes for a shader that reads them from uniforms (a warning when they are resampled). False,
  /// after an error, when the volume property has no scalar opacity function.
  bool CommitTransferFunction(vtkVolumeProperty* property, double offset, double scale,
    vtkuv::NormalisedTransferFunction& transferFunction, std::vector<uv::Isosurface>& drawnIsosurfaces,
    std::size_t maximumNodes = 0);

  /// Warns with `message` the first time this mapper is asked to under `key`, and never again under
  /// it: a render loop would repeat a warning every frame. True when it warned.
  bool WarnOnce(const std::string& key, const std::string& message);

  ///@{
  /// Delegation: a mapper that hands some inputs to a mapper of another kind, which draws them
  /// better (the hexahedral caster hands all-tetrahedra meshes to the tetrahedra mapper), runs that
  /// one's steps through these. PrepareThrough first gives it this mapper's input, scalar selection,
  /// isosurfaces and shared settings, and afterwards takes back its mesh-update counters; the
  /// delegate's errors and warnings reach this mapper's observers (ForwardMessagesOf, once).
  bool PrepareThrough(vtkUnstructuredVolumeMapper* delegate, const vtkUnstructuredVolumeFrame& frame);
  void ForwardMessagesOf(vtkUnstructuredVolumeMapper* delegate);
  static bool UploadThrough(vtkUnstructuredVolumeMapper* delegate, const vtkUnstructuredVolumeFrame& frame)
  {
    return delegate->Upload(frame);
  }
  static bool DrawThrough(vtkUnstructuredVolumeMapper* delegate, const vtkUnstructuredVolumeFrame& frame,
    vtkUnstructuredVolumeFloatTarget& target)
  {
    return delegate->Draw(frame, target);
  }
  static void ReleaseGraphicsOf(vtkUnstructuredVolumeMapper* delegate) { delegate->ReleaseMapperGraphics(); }
  static void ForgetMeshOf(vtkUnstructuredVolumeMapper* delegate) { delegate->ForgetMesh(); }
  static void DrawnBoundsOf(vtkUnstructuredVolumeMapper* delegate, double bounds[6])
  {
    delegate->GetDrawnBounds(bounds);
  }
  ///@}

  /// In the GL-error debug mode, reports the GL errors raised since the last check, naming `pass`;
  /// false when there was one. Does nothing (true) when the mode is off.
  bool CheckGLErrors(const char* pass) { return !GLErrorChecks || this->ReportGLErrors(pass); }

  /// The isosurfaces, in value order.
  const uv::IsosurfaceList& GetIsosurfaces() const;

  /// Brings `gradients` to the mesh of version `meshVersion`, built from `cells` and its rendered
  /// `scalar`: GradientArrayName's array, else computed. Warns when that array has not 3 components.
  void UpdateVertexGradients(vtkuv::VertexGradientCache& gradients, vtkDataSet* cells,
    const vtkuv::RenderedScalar& scalar, std::uint64_t meshVersion);

  bool KeepFloatImage = false;
  double ImageSampleDistance = 1.0;
  bool AutoAdjustSampleDistances = true;
  double MinimumImageSampleDistance = 1.0;
  double MaximumImageSampleDistance = 8.0;
  int ProjectionRoute = VERTEX_PULLING;
  bool SkipInvisibleCells = true;
  double OpacityThreshold = 1.0;
  double TransferFunctionTolerance = 1e-3;
  int SegmentIntegration = AUTOMATIC;
  int VisibilityOrder = FACE_ORDER;
  int GradientMode = VERTEX_GRADIENTS;
  char* GradientArrayName = nullptr;
  vtkIdType NumberOfCyclesBroken = 0;   ///< set by the mappers that order tetrahedra
  vtkIdType NumberOfGapConstraints = 0; ///< likewise
  struct
  {
    int Builds = 0, PointRefreshes = 0, ValueRefreshes = 0;
  } MeshUpdates; ///< set by the mapper after each update of its mesh
  int NumberOfTransferFunctionNodes = 0; ///< set by the mapper when it rebuilds its nodes

private:
  vtkUnstructuredVolumeMapper(const vtkUnstructuredVolumeMapper&) = delete;
  void operator=(const vtkUnstructuredVolumeMapper&) = delete;

  /// A frame that draws nothing (empty viewport, nothing visible, bad input) keeps a transparent
  /// float image of its size, not the last drawn one.
  void KeepTransparentImage(const vtkUnstructuredVolumeFrame& frame);

  static bool GLErrorChecks;
  bool ReportGLErrors(const char* pass);

  bool CheckArguments(vtkRenderer* renderer, vtkVolume* volume);
  double ChooseImageSampleDistance(double allowedSeconds);
  /// The frame's steps at image sample distance `distance` (`interactive`: reduced by the automatic
  /// adjustment); true when it used the GL context.
  bool RenderFrame(
    vtkRenderer* renderer, vtkVolume* volume, vtkOpenGLRenderWindow* window, double distance, bool interactive);
  void UseContext(vtkOpenGLRenderWindow* window);
  bool DrawAndComposite(const vtkUnstructuredVolumeFrame& frame);

  struct Shared;
  std::unique_ptr<Shared> Base;
};

#endif
