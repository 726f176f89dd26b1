#include "vtkPreIntegratedTetrahedraMapper.h"

#include "uvCellVisibility.h"
#include "uvHexahedralMesh.h"
#include "uvIsosurfaceList.h"
#include "uvOpacityMaskFS.h"
#include "uvFullScreenTriangleVS.h"
#include "vtkUnstructuredVolumeCellDrawer.h"
#include "vtkPreIntegratedTetrahedraPrograms.h"
#include "vtkPreIntegratedTetrahedraWalk.h"
#include "vtkUnstructuredVolumeBufferTexture.h"
#include "vtkUnstructuredVolumeFloatTarget.h"
#include "vtkUnstructuredVolumeFrame.h"
#include "vtkUnstructuredVolumeFrameStatistics.h"
#include "vtkUnstructuredVolumeIndexBuffer.h"
#include "vtkUnstructuredVolumeOpacityMask.h"
#include "vtkUnstructuredVolumeOpenGL.h"
#include "vtkuvTetrahedralMesh.h"
#include "vtkUnstructuredVolumeTexture.h"
#include "vtkUnstructuredVolumeTetrahedralState.h"
#include "vtkuvNormalisedTransferFunction.h"
#include "vtkUnstructuredVolumeTransferFunctionTexture.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPreIntegratedTetrahedraMapper);

namespace
{
void SetMatrix(vtkShaderProgram* program, const char* name, const glm::dmat4& m)
{
  const glm::mat4 single(m);
  program->SetUniformMatrix4x4(name, const_cast<float*>(glm::value_ptr(single)));
}

/// The fragment stage's rayX and rayY: the eye ray at pixel (x, y) of the frame's image is affine in
/// (x, y) (VTK's projections keep the near plane at one eye depth), so three pixels fix it: in
/// perspective its direction (z = -1), in parallel projection its origin (z = 0).
void SetPixelRays(vtkShaderProgram* program, const vtkUnstructuredVolumeFrame& frame)
{
  const glm::dmat4 clipToEye = glm::inverse(frame.EyeToClip);
  const auto rayAt = [&](double x, double y) {
    const glm::dvec4 ndc(2.0 * x / frame.Width - 1.0, 2.0 * y / frame.Height - 1.0, -1.0, 1.0);
    const glm::dvec4 near = clipToEye * ndc;
    const glm::dvec3 point = glm::dvec3(near) / near.w;
    return frame.Parallel ? glm::dvec2(point) : glm::dvec2(point) / -point.z;
  };
  const glm::dvec2 origin = rayAt(0.0, 0.0), alongX = rayAt(1.0, 0.0) - origin, alongY = rayAt(0.0, 1.0) - origin;
  const float rayX[3] = { static_cast<float>(alongX.x), static_cast<float>(alongY.x), static_cast<float>(origin.x) };
  const float rayY[3] = { static_cast<float>(alongX.y), static_cast<float>(alongY.y), static_cast<float>(origin.y) };
  program->SetUniform3f("rayX", rayX);
  program->SetUniform3f("rayY", rayY);
}

/// The pulled faces' parallel-projection eye depth from the window depth (uvBarycentricRayLib.glsl's
/// FaceDepth): z_ndc = P22 z_eye + P32 and window depth (z_ndc + 1) / 2, so depth = -z_eye is affine in it.
void SetWindowDepthToEyeDepth(vtkShaderProgram* program, const vtkUnstructuredVolumeFrame& frame)
{
  const double p22 = frame.EyeToClip[2][2], p32 = frame.EyeToClip[3][2];
  const float toDepth[2] = { static_cast<float>(-2.0 / p22), static_cast<float>((1.0 + p32) / p22) };
  program->SetUniform2f("windowDepthToEyeDepth", toDepth);
}

/// Front to back pays for its mask passes and, on CPU rasterisers, for a slower blend and order
/// (the benchmark measured both orders) only where pixels become opaque: it is chosen when at least
/// this share of the covered pixels reached the opacity threshold in the last frame.
constexpr double FrontToBackOpaqueShare = 0.25;

/// The share is measured every frame near or above that, but only every this many frames while the
/// last measure was under half of it: far from the choice, a view seldom turns it at once, and the
/// order only changes the frame time, not the image.
constexpr int FramesBetweenDistantMeasures = 8;

/// AUTOMATIC casts rays from this many visible tetrahedra per pixel of the viewport on. A walk step
/// costs more than a projected fragment, a projected tetrahedron costs its triangles' setup however
/// few pixels it covers: the benchmark's scenes cross over near one tetrahedron per pixel (a mesh
/// rarely covers the whole viewport).
constexpr double RayCastingTetrahedraPerPixel = 0.5;

/// Tetrahedra drawn between two refreshes of the opacity mask when compositing front to back: a
/// refresh is one full-screen pass, so at most about 64 of them a frame, and none more often than
/// every 4096 tetrahedra.
std::size_t MaskedBatchSize(std::size_t count)
{
  return std::max<std::size_t>(4096, (count + 63) / 64);
}
}

class vtkPreIntegratedTetrahedraMapper::Internals : public vtkUnstructuredVolumeTetrahedralState
{
public:
  // The shared state (the mesh, its lists, order and buffers) is the base's; this mapper adds:
  bool Shade = false;
  bool UseTable = false; // whole segments from one read of the length table
  // The mesh's bounding box (recentred model space).
  glm::dvec3 Low{ 0.0 }, High{ 0.0 };
  std::uint64_t BoundsFor = 0; // the mesh's Version

  // GPU state besides the shared buffers.
  vtkUnstructuredVolumeBufferTexture DrawOrder;
  vtkUnstructuredVolumeIndexBuffer OrderIndices; // geometry-shader route: one point per tetrahedron
  vtkUnstructuredVolumeOpacityMask Mask;
  vtkPreIntegratedTetrahedraWalk Walk; // the ray-casting route
  bool RayCasting = false;             // this frame's route
  int Peels = 0;                       // walk passes of the last frame

  // This frame's compositing: front to back under the opacity mask, or back to front; chosen by the
  // share of covered pixels the last frame left opaque (negative: not measured yet).
  bool FrontToBack = false;
  double OpaqueShare = -1.0;
  int FramesSinceMeasure = 0;

  /// Whether this frame measures the opaque share (FramesBetweenDistantMeasures).
  bool MeasureIsDue()
  {
    if (this->OpaqueShare < 0.0 || this->OpaqueShare >= 0.5 * FrontToBackOpaqueShare ||
      ++this->FramesSinceMeasure >= FramesBetweenDistantMeasures)
    {
      this->FramesSinceMeasure = 0;
      return true;
    }
    return false;
  }

  int MeshUploads = 0, TransferFunctionUploads = 0, MaskRefreshes = 0;
  std::uint64_t ShadedFragments = 0;

  void Release()
  {
    this->ReleaseTetrahedralGraphics();
    this->DrawOrder.Release();
    this->OrderIndices.Release();
    this->Mask.Release();
    this->Walk.Release();
  }

  /// The mesh's bounds, when the mesh changed.
  void UpdateBounds()
  {
    if (this->BoundsFor == this->Mesh.Version)
      return;
    const std::vector<float>& points = this->Mesh.PointData;
    this->Low = glm::dvec3(std::numeric_limits<double>::infinity());
    this->High = -this->Low;
    for (std::size_t p = 0; p + 3 < points.size(); p += 4)
    {
      const glm::dvec3 position(points[p], points[p + 1], points[p + 2]);
      this->Low = glm::min(this->Low, position);
      this->High = glm::max(this->High, position);
    }
    this->BoundsFor = this->Mesh.Version;
  }

  /// Whether the near plane may cut a tetrahedron: some corner of the mesh's bounds lies before the
  /// plane or on it (a relative margin for rounding). Where none does, the programs leave the
  /// near-plane ray casting out.
  bool NearPlaneMayCut(const vtkUnstructuredVolumeFrame& frame)
  {
    this->UpdateBounds();
    const glm::dmat4 modelToEye = frame.ModelToEye(this->Mesh.Center);
    for (int corner = 0; corner < 8; ++corner)
    {
      const double depth = -(modelToEye * glm::dvec4(this->BoundsCorner(corner), 1.0)).z;
      if (!(depth > frame.NearDepth + 1e-3 * (std::abs(frame.NearDepth) + std::abs(depth))))
        return true;
    }
    return false;
  }

  /// Corner `corner` (bits x, y, z: high or low) of the mesh's bounds, as UpdateBounds left them.
  glm::dvec3 BoundsCorner(int corner) const
  {
    return glm::dvec3((corner & 1) ? this->High.x : this->Low.x, (corner & 2) ? this->High.y : this->Low.y,
      (corner & 4) ? this->High.z : this->Low.z);
  }

  /// What of the view volume may cut the mesh: the near plane (NearPlaneMayCut), else its sides or
  /// far plane where some point lies beyond one of them or on it (a relative margin for rounding),
  /// else nothing. The corners of the mesh's bounds are tried first: inside, so is every point.
  vtkPreIntegratedTetrahedraPrograms::Clipping ClippingOf(const vtkUnstructuredVolumeFrame& frame)
  {
    using Clipping = vtkPreIntegratedTetrahedraPrograms::Clipping;
    if (this->NearPlaneMayCut(frame)) // which updates the bounds
      return Clipping::NearPlane;
    const glm::dmat4 modelToClip = frame.ModelToClip(this->Mesh.Center);
    const auto inside = [&modelToClip](const glm::dvec3& p) {
      const glm::dvec4 clip = modelToClip * glm::dvec4(p, 1.0);
      const double limit = (1.0 - 1e-3) * clip.w;
      return std::abs(clip.x) < limit && std::abs(clip.y) < limit && clip.z < limit;
    };
    bool boxInside = true;
    for (int corner = 0; corner < 8 && boxInside; ++corner)
      boxInside = inside(this->BoundsCorner(corner));
    if (boxInside)
      return Clipping::None;
    const std::vector<float>& points = this->Mesh.PointData;
    std::atomic<bool> allInside(true);
    vtkuv::ParallelFor(points.size() / 4, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end && allInside.load(std::memory_order_relaxed); ++i)
        if (!inside(glm::dvec3(points[4 * i], points[4 * i + 1], points[4 * i + 2])))
          allInside = false;
    });
    return allInside ? Clipping::None : Clipping::Sides;
  }

  /// Draws the tetrahedra in draw places [first, first + count) of the order with `program` (bound).
  void DrawPlaces(vtkOpenGLState* state, vtkShaderProgram* program, bool pulling, std::size_t first, std::size_t count)
  {
    if (pulling)
      this->Cells.Draw(state, program, this->DrawOrder, first, count);
    else
      this->OrderIndices.Draw(GL_POINTS, count, first);
  }
};

vtkPreIntegratedTetrahedraMapper::vtkPreIntegratedTetrahedraMapper()
  : Impl(new Internals)
{
  this->OpacityThreshold = 0.999;
}

vtkPreIntegratedTetrahedraMapper::~vtkPreIntegratedTetrahedraMapper() = default;

void vtkPreIntegratedTetrahedraMapper::ReportStatistics(vtkUnstructuredVolumeFrameStatistics* statistics)
{
  this->Superclass::ReportStatistics(statistics);
  const Internals& impl = *this->Impl;
  statistics->SetValue("UsedRayCasting", impl.RayCasting ? 1.0 : 0.0);
  statistics->SetValue("Peels", impl.RayCasting ? impl.Peels : 0);
  statistics->SetValue("MeshUploads", impl.MeshUploads);
  statistics->SetValue("TransferFunctionUploads", impl.TransferFunctionUploads);
  statistics->SetValue("VisibleListBuilds", impl.Lists.Builds);
  statistics->SetValue("UsedSegmentTable", impl.UseTable ? 1.0 : 0.0);
  statistics->SetValue("SegmentTableBuilds", impl.LengthTable.Builds);
  statistics->SetValue("SegmentTableError", impl.LengthTable.Builds > 0 ? impl.LengthTable.Error : -1.0);
  statistics->SetValue("DrewFrontToBack", impl.FrontToBack ? 1.0 : 0.0);
  statistics->SetValue("OpaquePixelShare", impl.OpaqueShare);
  statistics->SetValue("OpacityMaskRefreshes", impl.MaskRefreshes);
  statistics->SetValue("ShadedFragments", static_cast<double>(impl.ShadedFragments));
}

vtkIdType vtkPreIntegratedTetrahedraMapper::GetMeshMemoryInBytes()
{
  const Internals& impl = *this->Impl;
  std::size_t bytes = sizeof(std::uint32_t) * (impl.Mesh.TetrahedronPoints.size() + impl.Order.Order.size()) +
    sizeof(float) * impl.Mesh.PointData.size() + impl.Cells.GetBytes() + impl.Walk.GetGpuBytes();
  bytes += impl.PointGradients.GetBytes();
  return static_cast<vtkIdType>(bytes);
}

vtkIdType vtkPreIntegratedTetrahedraMapper::GetHostMemoryInBytes()
{
  const Internals& impl = *this->Impl;
  const auto bytes = [](const auto& vector) { return sizeof(vector[0]) * vector.capacity(); };
  const uv::TetrahedronFaceNeighbours& surfaces = impl.CellSurfaces;
  return static_cast<vtkIdType>(impl.Mesh.GetBytes() + impl.Lists.GetBytes() + impl.Order.GetBytes() +
    impl.Walk.GetBytes() + bytes(impl.Gradients.Values) + bytes(surfaces.Values) + bytes(surfaces.Low) +
    bytes(surfaces.High));
}

void vtkPreIntegratedTetrahedraMapper::ForgetMesh()
{
  this->Impl->Mesh.Invalidate();
}

void vtkPreIntegratedTetrahedraMapper::ReleaseMapperGraphics()
{
  this->Impl->Release();
}

void vtkPreIntegratedTetrahedraMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IntegrationMode: "
     << (this->IntegrationMode == AVERAGE_SCALAR ? "AverageScalar" : "PartialPreIntegration") << "\n";
  os << indent << "CountShadedFragments: " << this->CountShadedFragments << "\n";
  const char* modes[] = { "Projection", "RayCasting", "Automatic" };
  os << indent << "RenderMode: " << modes[this->RenderMode] << " (last frame "
     << (this->Impl->RayCasting ? "ray-cast" : "projected") << ")\n";
}

bool vtkPreIntegratedTetrahedraMapper::Prepare(const vtkUnstructuredVolumeFrame& frame)
{
  Internals& impl = *this->Impl;
  impl.DrawnTetrahedra = 0;
  impl.ShadedFragments = 0;
  impl.MaskRefreshes = 0;
  // The mesh, when the input or its scalar changed.
  vtkUnstructuredGridBase* input = this->GetInput();
  vtkVolumeProperty* property = frame.Property;
  vtkuv::RenderedScalar scalar;
  if (!this->FindScalar(input, property, scalar))
  {
    return false;
  }
  if (!this->UpdateTetrahedralMesh(input, scalar))
  {
    return false;
  }

  // Transfer function and isosurfaces, normalised like the scalar (a cell scalar's are faces between
  // cells).
  const bool onCells = this->WarnCellScalarLimits(scalar, property->GetShade() != 0, true);
  if (!this->CommitTransferFunction(property, impl.Mesh.Normalisation.Offset, impl.Mesh.Normalisation.Scale,
        impl.TransferFunction, impl.DrawnIsosurfaces))
  {
    return false;
  }
  this->CommitIsosurfaces(onCells);
  if (!impl.UpdateLists(this->SkipInvisibleCells))
  {
    return false;
  }

  // Gradients, only when something is lit (a face's normal lights a cell scalar's surfaces).
  impl.Shade = property->GetShade() != 0 && !onCells;
  this->UpdateGradients(!onCells && (impl.Shade || !impl.Isovalues.empty()));

  impl.UseTable = this->ChooseSegmentTable(frame);

  // Ray casting needs no order: rays walk front to back by adjacency.
  impl.RayCasting = this->ChooseRayCasting(frame);
  if (impl.RayCasting)
  {
    impl.FrontToBack = false;
    return true;
  }

  // Visibility order by centroid distance, when the view or the list changed: front to back when
  // pixels that became opaque can stop being shaded (skipping on and a threshold below 1), else
  // back to front, which needs no mask passes.
  impl.FrontToBack = this->ChooseFrontToBack();
  this->UpdateOrder(frame, impl.FrontToBack);
  return true;
}

bool vtkPreIntegratedTetrahedraMapper::Upload(const vtkUnstructuredVolumeFrame& frame)
{
  Internals& impl = *this->Impl;
  vtkOpenGLRenderWindow* window = frame.Window;
  if (impl.UploadMesh(window))
    ++impl.MeshUploads;
  if (impl.UploadTransferFunction(window))
    ++impl.TransferFunctionUploads;
  if (impl.UseTable)
    impl.LengthTable.Sync(window);
  if (impl.RayCasting)
    impl.Walk.Sync(window);
  else if (this->ProjectionRoute == VERTEX_PULLING)
  {
    impl.DrawOrder.Sync(window, impl.Order.Order, 1, impl.Order.Version);
    impl.Cells.Sync(true);
  }
  else
  {
    impl.OrderIndices.Sync(impl.Order.Order, impl.Order.Version);
  }
  return true;
}

bool vtkPreIntegratedTetrahedraMapper::Draw(
  const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target)
{
  Internals& impl = *this->Impl;
  if (impl.RayCasting)
    return this->DrawByRayCasting(frame, target);
  vtkShaderProgram* program = this->ReadyTetrahedraProgram(frame, target);
  if (!program)
  {
    vtkErrorMacro("the projected-tetrahedra shaders failed to compile or link");
    return false;
  }
  this->CheckGLErrors("the projected tetrahedra's program and textures");
  target.GetNoAttributes()->Bind();
  bool drawn = true;
  if (impl.FrontToBack)
    drawn = this->DrawFrontToBack(frame, target, program);
  else
    this->DrawBackToFront(frame, program);
  this->CheckGLErrors("the projected tetrahedra");
  if (drawn && this->OrderIsChosen() && impl.MeasureIsDue())
  {
    drawn = this->MeasureOpaqueShare(frame, target);
    this->CheckGLErrors("the tetrahedra's opaque-share measure");
  }
  target.GetNoAttributes()->Release();
  this->UnbindTetrahedraResources(target);
  impl.DrawnTetrahedra = static_cast<vtkIdType>(impl.Order.Order.size());
  return drawn;
}

/// The projection program for this frame's options, bound, with its uniforms and textures.
vtkShaderProgram* vtkPreIntegratedTetrahedraMapper::ReadyTetrahedraProgram(
  const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target)
{
  Internals& impl = *this->Impl;
  vtkPreIntegratedTetrahedraPrograms::Options options;
  options.VertexPulling = this->ProjectionRoute == VERTEX_PULLING;
  options.Gradients = impl.NeedGradients;
  options.NodeTexture = uvgl::NodesNeedTexture(impl.TransferFunction.Nodes);
  options.CellSurfaces = impl.DrawCellSurfaces;
  options.SegmentTable = impl.UseTable;
  // Rays are cast only where the near plane cuts nothing, and their programs take no clipped faces.
  options.Clips = impl.RayCasting ? vtkPreIntegratedTetrahedraPrograms::Clipping::Sides : impl.ClippingOf(frame);
  options.OpaqueDepth = frame.OpaqueDepth;
  options.RayCasting = impl.RayCasting;
  vtkShaderProgram* program =
    uvgl::ReadyProgram(frame.Window, vtkPreIntegratedTetrahedraPrograms::Sources(options));
  if (!program)
    return nullptr;

  const glm::dvec3 center = impl.Mesh.Center;
  SetMatrix(program, "modelToEye", frame.ModelToEye(center));
  SetMatrix(program, "eyeToClip", frame.EyeToClip);
  if (impl.NeedGradients)
  {
    const glm::mat3 normals(frame.ModelToEyeNormals(center));
    program->SetUniformMatrix3x3("modelToEyeNormals", const_cast<float*>(glm::value_ptr(normals)));
  }
  // Tetrahedra crossing the near plane (where rays begin) are ray-cast, in both projections.
  program->SetUniformf("nearDepth", static_cast<float>(frame.NearDepth));
  program->SetUniformf("zeroTolerance", 1e-6f);
  program->SetUniformi("parallelProjection", frame.Parallel ? 1 : 0);
  SetPixelRays(program, frame);
  SetWindowDepthToEyeDepth(program, frame);
  program->SetUniformi("averageScalar", this->IntegrationMode == AVERAGE_SCALAR ? 1 : 0);
  program->SetUniformi("shadeVolume", impl.Shade ? 1 : 0);
  program->SetUniformi("isosurfaceCount", static_cast<int>(impl.Isovalues.size()));
  program->SetUniformf("opacityThreshold", static_cast<float>(this->OpacityThreshold));
  uvgl::SetPhongUniforms(program, frame.Renderer, frame.Property, frame.WorldToEye);

  impl.BindMesh(program);
  if (impl.UseTable)
    impl.LengthTable.Bind(program);
  if (options.OpaqueDepth)
  {
    vtkTextureObject* sceneDepth = target.GetSceneDepth();
    sceneDepth->Activate();
    program->SetUniformi("opaqueDepth", sceneDepth->GetTextureUnit());
    SetMatrix(program, "clipToEye", glm::inverse(frame.EyeToClip));
    SetMatrix(program, "clipToModel", glm::inverse(frame.ModelToClip(center)));
    const float viewport[2] = { static_cast<float>(frame.Width), static_cast<float>(frame.Height) };
    program->SetUniform2f("viewportSize", viewport);
  }
  return program;
}

void vtkPreIntegratedTetrahedraMapper::UnbindTetrahedraResources(vtkUnstructuredVolumeFloatTarget& target)
{
  Internals& impl = *this->Impl;
  impl.UnbindMesh();
  if (impl.UseTable)
    impl.LengthTable.Unbind();
  target.GetSceneDepth()->Deactivate();
}

/// Whether this frame reads whole segments from the table: partial pre-integration with nothing
/// that needs the cuts (isosurfaces, shading), and the table chosen or, AUTOMATIC, within the
/// tolerance. The table is brought up to date first (only when the nodes or the longest segment
/// changed).
bool vtkPreIntegratedTetrahedraMapper::ChooseSegmentTable(const vtkUnstructuredVolumeFrame& frame)
{
  const Internals& impl = *this->Impl;
  return this->ChooseLengthTable(
    frame, this->IntegrationMode != PARTIAL_PRE_INTEGRATION || !impl.Isovalues.empty() || impl.Shade);
}

/// Whether this frame walks rays (RenderMode): it can unless a cell scalar's isosurfaces are drawn or
/// the near plane may cut the mesh; AUTOMATIC where the visible tetrahedra are many for the pixels
/// and no tetrahedra overlap (folded faces: a walk would see one of them where they add up). The
/// adjacency is brought up to date here.
bool vtkPreIntegratedTetrahedraMapper::ChooseRayCasting(const vtkUnstructuredVolumeFrame& frame)
{
  Internals& impl = *this->Impl;
  if (this->RenderMode == PROJECTION || impl.DrawCellSurfaces || impl.NearPlaneMayCut(frame))
    return false;
  const double pixels = static_cast<double>(frame.Width) * frame.Height;
  if (this->RenderMode == AUTOMATIC &&
    static_cast<double>(impl.Lists.Drawn.size()) < RayCastingTetrahedraPerPixel * pixels)
    return false;
  impl.Walk.Update(impl.Mesh);
  return this->RenderMode == RAY_CASTING || impl.Walk.FoldedFaces() == 0;
}

/// Whether the order depends on the scene: skipping on, a threshold below 1, and more than one
/// batch of tetrahedra (a single batch has no mask to refresh).
bool vtkPreIntegratedTetrahedraMapper::OrderIsChosen()
{
  const std::size_t count = this->Impl->Lists.Drawn.size();
  return this->SkipInvisibleCells && this->OpacityThreshold < 1.0 && count > MaskedBatchSize(count);
}

/// Front to back where the order is chosen and the last frame left enough pixels opaque, or has not
/// been measured (the first frame, or the first after the order began to depend on the scene).
bool vtkPreIntegratedTetrahedraMapper::ChooseFrontToBack()
{
  Internals& impl = *this->Impl;
  if (!this->OrderIsChosen())
  {
    impl.OpaqueShare = -1.0;
    return false;
  }
  return impl.OpaqueShare < 0.0 || impl.OpaqueShare >= FrontToBackOpaqueShare;
}

/// The share of the covered pixels whose opacity reached the threshold, by two mask passes counted
/// with occlusion queries (their result is waited for, once a frame), for the next frame's order.
bool vtkPreIntegratedTetrahedraMapper::MeasureOpaqueShare(
  const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target)
{
  Internals& impl = *this->Impl;
  vtkShaderProgram* mask = this->ReadyMaskProgram(frame);
  if (!mask)
    return false;
  vtkOpenGLState* state = frame.Window->GetState();
  impl.Mask.Resize(frame.Window, frame.Width, frame.Height);
  state->vtkglEnable(GL_DEPTH_TEST);
  GLuint counted[2] = { 0, 0 };
  const float thresholds[2] = { static_cast<float>(this->OpacityThreshold), 1e-6f }; // opaque, covered
  for (int k = 0; k < 2; ++k)
  {
    mask->SetUniformf("opacityThreshold", thresholds[k]);
    counted[k] = uvgl::SamplesPassed([&] { impl.Mask.RunAlone(state, mask, target.GetColor()); });
  }
  state->vtkglDisable(GL_DEPTH_TEST);
  impl.OpaqueShare = counted[1] > 0 ? double(counted[0]) / counted[1] : 0.0;
  return true;
}

/// The opacity-mask program, bound; null (reported) when it does not compile.
vtkShaderProgram* vtkPreIntegratedTetrahedraMapper::ReadyMaskProgram(const vtkUnstructuredVolumeFrame& frame)
{
  const uvgl::ProgramSources maskSources{ uvgl::ShaderSource(uvFullScreenTriangleVS, ""),
    uvgl::ShaderSource(uvOpacityMaskFS, ""), "" };
  vtkShaderProgram* mask = uvgl::ReadyProgram(frame.Window, maskSources);
  if (!mask)
    vtkErrorMacro("the opacity-mask shaders failed to compile or link");
  return mask;
}

/// Every tetrahedron of the order, composited over what is behind it (ONE, ONE_MINUS_SRC_ALPHA).
void vtkPreIntegratedTetrahedraMapper::DrawBackToFront(
  const vtkUnstructuredVolumeFrame& frame, vtkShaderProgram* program)
{
  Internals& impl = *this->Impl;
  vtkOpenGLState* state = frame.Window->GetState();
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  const std::size_t count = impl.Order.Order.size();
  const bool pulling = this->ProjectionRoute == VERTEX_PULLING;
  if (this->CountShadedFragments)
    impl.ShadedFragments = uvgl::SamplesPassed([&] { impl.DrawPlaces(state, program, pulling, 0, count); });
  else
    impl.DrawPlaces(state, program, pulling, 0, count);
}

/// The order front to back in batches, composited under what is in front (ONE_MINUS_DST_ALPHA,
/// ONE: the same sum as back to front), the opacity mask refreshed between batches so that the
/// depth test discards the fragments of pixels already opaque before they are shaded.
bool vtkPreIntegratedTetrahedraMapper::DrawFrontToBack(
  const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target, vtkShaderProgram* program)
{
  Internals& impl = *this->Impl;
  vtkOpenGLState* state = frame.Window->GetState();
  vtkShaderProgram* mask = this->ReadyMaskProgram(frame);
  if (!mask)
    return false;
  mask->SetUniformf("opacityThreshold", static_cast<float>(this->OpacityThreshold));
  impl.Mask.Resize(frame.Window, frame.Width, frame.Height);
  impl.Mask.AttachAndClear(target, state); // nothing is opaque yet
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LESS); // the tetrahedra's fragments lie at depths in [0, 1): masked ones fail
  state->vtkglDepthMask(GL_FALSE);

  const std::size_t count = impl.Order.Order.size(), batch = MaskedBatchSize(count);
  const bool pulling = this->ProjectionRoute == VERTEX_PULLING;
  vtkOpenGLShaderCache* shaders = frame.Window->GetShaderCache();
  for (std::size_t first = 0; first < count; first += batch)
  {
    const std::size_t n = std::min(batch, count - first);
    shaders->ReadyShaderProgram(program);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ONE_MINUS_DST_ALPHA, GL_ONE);
    if (this->CountShadedFragments)
      impl.ShadedFragments += uvgl::SamplesPassed([&] { impl.DrawPlaces(state, program, pulling, first, n); });
    else
      impl.DrawPlaces(state, program, pulling, first, n);
    if (first + n < count)
    {
      shaders->ReadyShaderProgram(mask);
      impl.Mask.RunAlone(state, mask, target.GetColor());
      this->CheckGLErrors("the tetrahedra's opacity mask");
      ++impl.MaskRefreshes;
    }
  }
  state->vtkglDisable(GL_DEPTH_TEST);
  return true;
}

/// Peels of the ray-casting route (vtkPreIntegratedTetrahedraWalk): an entry pass, then, while
/// some ray enters the mesh again, a walk pass compositing under the earlier peels.
bool vtkPreIntegratedTetrahedraMapper::DrawByRayCasting(
  const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target)
{
  Internals& impl = *this->Impl;
  impl.Walk.Resize(frame.Window, frame.Width, frame.Height);
  impl.Peels = 0;
  const glm::dvec3 center = impl.Mesh.Center;
  impl.UpdateBounds();
  const glm::dvec3 bounds[2] = { impl.Low, impl.High };
  // Every tetrahedron at most once a ray, and a margin (the walk ends at the boundary anyway).
  const int maximumSteps = static_cast<int>(std::min<std::size_t>(impl.Mesh.Size() + 8, 1 << 24));
  // After the first peel, rays can enter again only by faces off the mesh's hull: none, no peel.
  const int peels = impl.Walk.ReentryFaces() > 0 ? vtkPreIntegratedTetrahedraWalk::MaximumPeels : 1;
  for (int peel = 0; peel < peels; ++peel)
  {
    const long entered =
      impl.Walk.DrawEntries(frame, center, target, impl.TetrahedronPoints, impl.Points, bounds, peel == 0);
    this->CheckGLErrors("the tetrahedra's entry pass");
    if (entered < 0)
    {
      vtkErrorMacro("the tetrahedra's entry shaders failed to compile or link");
      return false;
    }
    if (entered == 0)
      break;
    vtkShaderProgram* program = this->ReadyTetrahedraProgram(frame, target);
    if (!program)
    {
      vtkErrorMacro("the tetrahedra's ray-casting shaders failed to compile or link");
      return false;
    }
    impl.Walk.DrawWalks(frame, center, target, program, maximumSteps);
    ++impl.Peels;
    this->UnbindTetrahedraResources(target);
    this->CheckGLErrors("the tetrahedra's walk pass");
  }
  impl.DrawnTetrahedra = static_cast<vtkIdType>(impl.Lists.Drawn.size());
  return true;
}

vtkUnstructuredVolumeTetrahedralState& vtkPreIntegratedTetrahedraMapper::GetTetrahedralState()
{
  return *this->Impl;
}
