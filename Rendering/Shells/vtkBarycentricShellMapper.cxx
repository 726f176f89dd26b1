#include "vtkBarycentricShellMapper.h"

#include "uvBarycentricCellProjectionFS.h"
#include "uvBarycentricShellBlendFS.h"
#include "uvBarycentricShellIsosurfaceFS.h"
#include "uvBarycentricShellSliceFS.h"
#include "uvOpacityMaskFS.h"
#include "uvCellVisibility.h"
#include "uvCoincidentCells.h"
#include "uvHexahedralMesh.h"
#include "uvIsosurfaceList.h"
#include "uvPreIntegration.h"
#include "uvShellBuckets.h"
#include "uvTetrahedralWalk.h"
#include "vtkBarycentricShellBlendPass.h"
#include "vtkBarycentricShellSegmentTable.h"
#include "vtkUnstructuredVolumeTetrahedralState.h"
#include "vtkUnstructuredVolumeCellDrawer.h"
#include "vtkBarycentricShellCellProjectionPass.h"
#include "vtkBarycentricShellImageTexture.h"
#include "vtkBarycentricShellIsosurfacePeelPass.h"
#include "vtkBarycentricShellOpaqueDistancePass.h"
#include "vtkBarycentricShellPrograms.h"
#include "vtkBarycentricShellSlicePass.h"
#include "vtkUnstructuredVolumeBufferTexture.h"
#include "vtkUnstructuredVolumeFloatTarget.h"
#include "vtkUnstructuredVolumeFrame.h"
#include "vtkUnstructuredVolumeFrameStatistics.h"
#include "vtkUnstructuredVolumeOpacityMask.h"
#include "vtkUnstructuredVolumeOpenGL.h"
#include "vtkuvTetrahedralMesh.h"
#include "vtkUnstructuredVolumeTexture.h"
#include "vtkuvNormalisedTransferFunction.h"
#include "vtkUnstructuredVolumeTransferFunctionTexture.h"

#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader


#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkBarycentricShellMapper);

namespace
{
constexpr int MaximumShells = 4096;  // beyond it the sample distance is widened (with a warning)
constexpr float InsideTolerance = 1e-5f; // barycentric slack: no cracks between neighbours

/// An interactive frame samples along its rays as coarsely as across them: its sample distance is
/// widened by the image's reduction, rounded to a power of two so that the segment table, built per
/// sample distance, is rebuilt only when the reduction changes by twice or more.
double InteractiveSampling(const vtkUnstructuredVolumeFrame& frame)
{
  return frame.InteractiveReduction > 1.0 ? std::exp2(std::round(std::log2(frame.InteractiveReduction))) : 1.0;
}

} // namespace

class vtkBarycentricShellMapper::Internals : public vtkUnstructuredVolumeTetrahedralState
{
public:
  explicit Internals(vtkBarycentricShellMapper* self)
    : Self(self)
  {
  }
  vtkBarycentricShellMapper* Self; // reports the GL errors of its passes (the debug mode)

  // ---- CPU state besides the shared one (the mesh, its lists, order and buffers), each piece
  // versioned (or compared exactly) for its GPU copy.
  std::vector<glm::vec3> EyePoints;
  std::vector<glm::vec2> ScreenPoints; // normalised device coordinates (NaN: not in front of the eye)
  uv::RangedCells VolumeRanges, IsosurfaceRanges;
  uv::ShellLayout Layout;
  uv::ShellBuckets Buckets;
  struct
  {
    std::uint64_t TopologyVersion = 0;
    glm::dmat4 Matrix{ 0.0 };
    int SamplesAcross = 0;
    double Value = 0.0;
  } Automatic; // the automatic sample distance and what it was computed from
  // A bound image, sampled through the points' texture coordinates (SetTextureImage).
  vtkSmartPointer<vtkImageData> TextureImage;
  vtkDataArray *ImageScalars = nullptr, *TextureCoordinates = nullptr;
  struct
  {
    const void* Array = nullptr;
    vtkMTimeType Time = 0;
    std::uint64_t MeshVersion = 0, Version = 0;
  } Coordinates; // where the mesh's texture coordinates come from, and their version
  // Per tetrahedron, the coincident copies it stands for (uv::CoincidentCellDensities; 0: merged
  // into another; empty: none repeats). A shell sample holds one cell's value, so copies the optical
  // model superposes are drawn as one cell of their density.
  std::vector<float> Densities;
  std::uint64_t DensitiesBuiltFor = 0; // the mesh's CellsVersion
  std::vector<std::uint32_t> ShellCells; // the volume's cells less the merged copies (when any)

  // ---- What this frame draws (Prepare).
  struct
  {
    bool CellProjection = false, Textured = false, Shade = false, Lit = false;
    bool SegmentTable = false, Pulling = true;
    int Slices = 7, Targets = 2, Layers = 1;
    double SampleDistance = 0.0, ScalarOffset = 0.0, ScalarScale = 1.0;
  } Now;

  // ---- GPU state besides the shared buffers: the image's, then the passes.
  vtkUnstructuredVolumeBufferTexture PointCoordinates;
  vtkUnstructuredVolumeBufferTexture CellDensities; // the shells' Densities, when some cells coincide
  vtkBarycentricShellImageTexture Image;
  vtkBarycentricShellOpaqueDistancePass Opaque;
  vtkBarycentricShellIsosurfacePeelPass Peel;
  vtkBarycentricShellSlicePass Slices;
  vtkBarycentricShellBlendPass Blend;
  vtkBarycentricShellSegmentTable Table; // CPU side, built in Prepare
  vtkUnstructuredVolumeOpacityMask Mask;
  vtkBarycentricShellCellProjectionPass Projection;
  uv::PixelRectangle VolumeRectangle{ 0, 0, 0, 0 };

  // ---- What the last frame did.
  int Shells = 0, SkippedShells = 0, IsosurfaceLayers = 0;
  double LastSampleDistance = 0.0;

  void Release()
  {
    this->ReleaseTetrahedralGraphics();
    this->PointCoordinates.Release();
    this->CellDensities.Release();
    this->Image.Release();
    this->Opaque.Release();
    this->Peel.Release();
    this->Slices.Release();
    this->Blend.Release();
    this->Mask.Release();
    this->Projection.Release();
  }

  bool UpdateMesh(vtkBarycentricShellMapper* self, const vtkUnstructuredVolumeFrame& frame);
  bool UpdateTransferFunction(vtkBarycentricShellMapper* self, const vtkUnstructuredVolumeFrame& frame);
  void UpdateDensities();
  void UpdateGradients(vtkBarycentricShellMapper* self, const vtkUnstructuredVolumeFrame& frame);
  void UpdateSampleDistance(vtkBarycentricShellMapper* self, const vtkUnstructuredVolumeFrame& frame);
  bool UpdateShells(vtkBarycentricShellMapper* self, const vtkUnstructuredVolumeFrame& frame);

  void UploadData(vtkOpenGLRenderWindow* window);
  void UploadTextureCoordinates(vtkOpenGLRenderWindow* window);
  void UploadPasses(const vtkUnstructuredVolumeFrame& frame);

  std::string Defines(bool opaqueGeometry) const;
  /// Whether the shells draw merged copies (cell projection draws every copy itself).
  bool ShellDensities() const { return !this->Now.CellProjection && !this->Densities.empty(); }
  void SetCellUniforms(vtkShaderProgram* program, const vtkUnstructuredVolumeFrame& frame, bool opaqueGeometry);
  void SetIntegrationUniforms(vtkShaderProgram* program, const vtkUnstructuredVolumeFrame& frame, int isosurfaces);
  void UnbindResources(bool opaqueGeometry);
  void ScissorToVolume(const vtkUnstructuredVolumeFrame& frame, const vtkUnstructuredVolumeFloatTarget& target);
  bool DrawCellProjection(
    const vtkUnstructuredVolumeFrame& frame, const vtkBarycentricShellPrograms& programs, bool opaqueGeometry);
  struct ShellPrograms
  {
    vtkShaderProgram *Slice = nullptr, *Blend = nullptr, *Mask = nullptr;
    bool TerminateEarly = false;
  };
  bool ReadyShellPrograms(vtkBarycentricShellMapper* self, const vtkUnstructuredVolumeFrame& frame,
    const vtkBarycentricShellPrograms& programs, bool opaqueGeometry, int layers, ShellPrograms& shell);
  void DrawShell(int s, const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target,
    const vtkBarycentricShellPrograms& programs, const ShellPrograms& shell);
  bool DrawShells(vtkBarycentricShellMapper* self, const vtkUnstructuredVolumeFrame& frame,
    vtkUnstructuredVolumeFloatTarget& target, const vtkBarycentricShellPrograms& programs, bool opaqueGeometry);
  int DrawIsosurfaceLayers(const vtkUnstructuredVolumeFrame& frame, const vtkBarycentricShellPrograms& programs,
    bool opaqueGeometry, bool& failed);
};

// ---- Prepare's steps.

/// The input as tetrahedra: rebuilt when the cells or the scalar changed, positions only when the
/// points moved. With a bound image the mesh's own scalar is not drawn, and any point array will do.
bool vtkBarycentricShellMapper::Internals::UpdateMesh(
  vtkBarycentricShellMapper* self, const vtkUnstructuredVolumeFrame& frame)
{
  vtkUnstructuredGridBase* input = self->GetInput();
  vtkImageData* image = this->TextureImage;
  this->TextureCoordinates = image ? input->GetPointData()->GetTCoords() : nullptr;
  this->ImageScalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (image &&
    (!this->TextureCoordinates || this->TextureCoordinates->GetNumberOfComponents() != 3 || !this->ImageScalars))
  {
    vtkErrorWithObjectMacro(
      self, "a texture image needs point scalars, and the input 3-component point texture coordinates");
    return false;
  }
  this->Now.Textured = image != nullptr;
  vtkuv::RenderedScalar scalar;
  if (this->Now.Textured)
  {
    // Any point array carries the mesh through the split: the texture coordinates will do.
    scalar = vtkuv::FindRenderedScalar(input, self->GetScalarMode(), self->GetArrayAccessMode(),
      self->GetArrayId(), self->GetArrayName(), nullptr);
    if (!scalar || scalar.OnCells)
      scalar = vtkuv::RenderedScalar{ this->TextureCoordinates, false, 0 };
  }
  else if (!self->FindScalar(input, frame.Property, scalar))
  {
    return false;
  }
  return self->UpdateTetrahedralMesh(input, scalar);
}

/// Transfer function and isosurfaces, normalised like the drawn scalar (the image's own range when
/// one is bound).
bool vtkBarycentricShellMapper::Internals::UpdateTransferFunction(
  vtkBarycentricShellMapper* self, const vtkUnstructuredVolumeFrame& frame)
{
  this->Now.ScalarOffset = this->Mesh.Normalisation.Offset;
  this->Now.ScalarScale = this->Mesh.Normalisation.Scale;
  if (this->Now.Textured)
  {
    double range[2];
    this->ImageScalars->GetRange(range, 0);
    this->Now.ScalarOffset = range[0];
    this->Now.ScalarScale = range[1] > range[0] ? 1.0 / (range[1] - range[0]) : 1.0;
  }
  if (!self->CommitTransferFunction(frame.Property, this->Now.ScalarOffset, this->Now.ScalarScale,
        this->TransferFunction, this->DrawnIsosurfaces))
  {
    return false;
  }
  if (!this->Now.Textured)
    self->WarnCellScalarLimits(this->Mesh.Scalar, frame.Property->GetShade() != 0, true);
  if (this->Now.Textured && (!this->DrawnIsosurfaces.empty() || self->RenderMode == CELL_PROJECTION))
  {
    // The field inside a cell is the image's, not linear: no closed-form crossings or whole segments.
    self->WarnOnce("texture limits", "with a texture image only the shells are drawn: isosurfaces and cell "
                                     "projection need the mesh's own linear scalar");
    this->DrawnIsosurfaces.clear();
  }
  // A cell scalar's isosurfaces lie on faces between cells: cell projection draws them (exact for a
  // constant per cell), the shells do not sample them.
  self->CommitIsosurfaces(!this->Now.Textured && this->Mesh.OnCells());
  if (this->DrawCellSurfaces && self->RenderMode == SHELLS)
    self->WarnOnce("cell surfaces by projection", "isosurfaces of a cell scalar lie on the faces between cells: "
                                                  "drawn by cell projection (exact for a cell scalar), not by shells");
  return true;
}

/// Coincident copies among the tetrahedra, by position and field, once per set of cells.
void vtkBarycentricShellMapper::Internals::UpdateDensities()
{
  if (this->DensitiesBuiltFor == this->Mesh.CellsVersion)
    return;
  const auto sort = [](auto begin, auto end, auto less) { vtkSMPTools::Sort(begin, end, less); };
  const std::vector<std::uint32_t> samePoint = uv::CoincidentPointIds(this->Mesh.PointData, 4, sort);
  this->Densities =
    uv::CoincidentCellDensities<4>(this->Mesh.TetrahedronPoints, samePoint, this->Mesh.PointData, {}, sort);
  this->DensitiesBuiltFor = this->Mesh.CellsVersion;
}

/// Vertex gradients, for isosurfaces (both modes) and shading (cell projection), unless the cells'
/// own gradients light them.
void vtkBarycentricShellMapper::Internals::UpdateGradients(
  vtkBarycentricShellMapper* self, const vtkUnstructuredVolumeFrame& frame)
{
  this->Now.Shade = this->Now.CellProjection && frame.Property->GetShade() != 0 && !this->Mesh.OnCells();
  this->Now.Lit = this->Now.Shade || (!this->Isovalues.empty() && !this->DrawCellSurfaces); // faces light those
  self->UpdateGradients(this->Now.Lit && self->GradientMode == VERTEX_GRADIENTS);
}

/// SampleDistance, or the automatic one from the volume's bounds as of the last full build (or change
/// of the volume's matrix or of AutomaticSamplesAcross): a deforming mesh keeps its sample distance,
/// and so its segment table, and so does a time step of new values.
void vtkBarycentricShellMapper::Internals::UpdateSampleDistance(
  vtkBarycentricShellMapper* self, const vtkUnstructuredVolumeFrame& frame)
{
  this->Now.SampleDistance = self->SampleDistance * InteractiveSampling(frame);
  if (this->Now.SampleDistance > 0.0)
    return;
  // The matrix by value: ParaView sets the volume's matrix again whenever its data changes.
  const glm::dmat4& matrix = frame.VolumeToWorld;
  if (this->Automatic.TopologyVersion != this->Mesh.TopologyVersion || this->Automatic.Matrix != matrix ||
    this->Automatic.SamplesAcross != self->AutomaticSamplesAcross || !(this->Automatic.Value > 0.0))
  {
    double bounds[6];
    frame.Volume->GetBounds(bounds);
    const double diagonal = std::sqrt(std::pow(bounds[1] - bounds[0], 2) + std::pow(bounds[3] - bounds[2], 2) +
      std::pow(bounds[5] - bounds[4], 2));
    this->Automatic.Value = diagonal / self->AutomaticSamplesAcross;
    this->Automatic.TopologyVersion = this->Mesh.TopologyVersion;
    this->Automatic.Matrix = matrix;
    this->Automatic.SamplesAcross = self->AutomaticSamplesAcross;
  }
  this->Now.SampleDistance = this->Automatic.Value * InteractiveSampling(frame);
}

/// The shells, front to back, and the cells each holds (uvShellBuckets.h). False when no cell is in
/// front of the eye.
bool vtkBarycentricShellMapper::Internals::UpdateShells(
  vtkBarycentricShellMapper* self, const vtkUnstructuredVolumeFrame& frame)
{
  // Eye-space positions once per point, and their places on screen.
  const std::size_t pointCount = this->Mesh.PointData.size() / 4;
  this->EyePoints.resize(pointCount);
  this->ScreenPoints.resize(pointCount);
  const glm::mat4 toEye(frame.ModelToEye(this->Mesh.Center)), toClip(frame.EyeToClip);
  vtkuv::ParallelFor(pointCount, [&](std::size_t begin, std::size_t end) {
    for (std::size_t p = begin; p < end; ++p)
    {
      const float* x = &this->Mesh.PointData[4 * p];
      this->EyePoints[p] = glm::vec3(toEye * glm::vec4(x[0], x[1], x[2], 1.0f));
      const glm::vec4 clip = toClip * glm::vec4(this->EyePoints[p], 1.0f);
      this->ScreenPoints[p] =
        clip.w > 1e-6f ? glm::vec2(clip) / clip.w : glm::vec2(std::numeric_limits<float>::quiet_NaN());
    }
  });
  const std::vector<std::uint32_t>& tetrahedra = this->Mesh.TetrahedronPoints;
  this->UpdateDensities();
  const std::vector<std::uint32_t>* volume = &this->Lists.Volume();
  if (!this->Densities.empty())
  {
    this->ShellCells.clear();
    std::copy_if(volume->begin(), volume->end(), std::back_inserter(this->ShellCells),
      [this](std::uint32_t cell) { return this->Densities[cell] > 0.0f; });
    volume = &this->ShellCells;
  }
  this->VolumeRanges.Update(*volume, tetrahedra, this->EyePoints, frame.Parallel, vtkuv::ParallelFor);
  this->IsosurfaceRanges.Update(
    this->Lists.Isosurface, tetrahedra, this->EyePoints, frame.Parallel, vtkuv::ParallelFor);
  if (!uv::LayoutShells(this->VolumeRanges, this->IsosurfaceRanges, this->Now.SampleDistance, self->SlicesPerShell,
        MaximumShells, this->Layout))
  {
    return false;
  }
  if (this->Layout.Widened)
  {
    std::ostringstream message;
    message << "the sample distance would need more than " << MaximumShells << " shells here: widened to "
            << this->Layout.SampleDistance;
    self->WarnOnce("widened sample distance", message.str());
  }
  this->Now.SampleDistance = this->Layout.SampleDistance;
  this->Buckets.Update(this->Layout, this->VolumeRanges, this->IsosurfaceRanges,
    [&](std::uint32_t cell) { return uv::TetrahedronScreenBox(tetrahedra, cell, this->ScreenPoints); });
  return true;
}

// ---- Upload's steps.

/// The mesh's resources, the transfer function's and the image's, each uploaded only when its
/// version (or content) changed; a deforming mesh pays the points' upload and nothing else.
void vtkBarycentricShellMapper::Internals::UploadData(vtkOpenGLRenderWindow* window)
{
  this->UploadMesh(window);
  if (this->ShellDensities())
    this->CellDensities.Sync(window, this->Densities, 1, this->DensitiesBuiltFor);
  this->UploadTransferFunction(window);
  if (this->Now.Textured)
  {
    this->Image.Sync(
      window, this->TextureImage, this->ImageScalars, this->Now.ScalarOffset, this->Now.ScalarScale);
    this->UploadTextureCoordinates(window);
  }
}

/// The texture coordinates of the mesh's points (of the split grid when cells were split), when the
/// mesh, the array or its modification time changed (or the GPU copy was released).
void vtkBarycentricShellMapper::Internals::UploadTextureCoordinates(vtkOpenGLRenderWindow* window)
{
  vtkDataArray* coordinates = this->Mesh.Tetrahedra->GetPointData()->GetTCoords();
  if (!coordinates)
    coordinates = this->TextureCoordinates; // the input itself when nothing was split
  auto& source = this->Coordinates;
  if (coordinates != source.Array || coordinates->GetMTime() != source.Time || this->Mesh.Version != source.MeshVersion)
  {
    source.Array = coordinates;
    source.Time = coordinates->GetMTime();
    source.MeshVersion = this->Mesh.Version;
    ++source.Version;
  }
  if (this->PointCoordinates.Holds(source.Version))
    return;
  const vtkIdType count = coordinates->GetNumberOfTuples();
  std::vector<float> values(4 * count, 0.0f);
  vtkSMPTools::For(0, count, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType p = begin; p < end; ++p)
      for (int d = 0; d < 3; ++d)
        values[4 * p + d] = static_cast<float>(coordinates->GetComponent(p, d));
  });
  this->PointCoordinates.Sync(window, values, 4, source.Version);
}

/// What this frame's passes read: their cell lists (only the mode's own), the segment table, and
/// their screen-sized images.
void vtkBarycentricShellMapper::Internals::UploadPasses(const vtkUnstructuredVolumeFrame& frame)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  this->Cells.Sync(this->Now.Pulling);
  this->Opaque.Resize(window, frame.Width, frame.Height);
  this->Mask.Resize(window, frame.Width, frame.Height);
  if (this->Now.CellProjection)
  {
    this->Projection.SyncOrder(window, this->Order.Order, this->Order.Version);
    if (this->Now.SegmentTable)
      this->LengthTable.Sync(window);
    return;
  }
  this->Slices.SyncCells(window, this->Buckets.Cells, this->Buckets.Version);
  this->Peel.SyncCells(window, this->Lists.Isosurface, this->Lists.Version);
  if (this->Now.SegmentTable)
    this->Blend.SyncTable(window, this->Table);
  this->Slices.Resize(window, frame.Width, frame.Height, this->Now.Targets, this->Mask.GetDepth());
  this->Peel.Resize(window, frame.Width, frame.Height, this->Now.Layers);
}

// ---- Draw's steps.

std::string vtkBarycentricShellMapper::Internals::Defines(bool opaqueGeometry) const
{
  vtkBarycentricShellPrograms::Options options;
  options.Slices = this->Now.Slices;
  options.Targets = this->Now.Targets;
  options.Layers = this->Now.Layers;
  options.VertexGradients = this->NeedGradients;
  options.CellGradients = !this->NeedGradients && this->Now.Lit;
  options.SegmentTable = this->Now.SegmentTable;
  options.OpaqueGeometry = opaqueGeometry;
  options.Textured = this->Now.Textured;
  options.NodeTexture = uvgl::NodesNeedTexture(this->TransferFunction.Nodes);
  options.CellSurfaces = this->DrawCellSurfaces;
  options.CellDensities = this->ShellDensities();
  return vtkBarycentricShellPrograms::DefinesFor(options);
}

/// The uniforms (and textures) of every program over the tetrahedra: the geometry stage's and
/// uvBarycentricRayLib's. `program` must be bound.
void vtkBarycentricShellMapper::Internals::SetCellUniforms(
  vtkShaderProgram* program, const vtkUnstructuredVolumeFrame& frame, bool opaqueGeometry)
{
  uvgl::SetUniformMatrix(program, "modelToEye", frame.ModelToEye(this->Mesh.Center));
  uvgl::SetUniformMatrix(program, "eyeToClip", frame.EyeToClip);
  program->SetUniformi("parallelProjection", frame.Parallel ? 1 : 0);
  program->SetUniformf("nearDepth", static_cast<float>(frame.NearDepth));
  program->SetUniformf("insideTolerance", InsideTolerance);
  this->TetrahedronPoints.Bind(program, "tetrahedronPoints");
  this->Points.Bind(program, "pointData");
  if (opaqueGeometry)
    this->Opaque.Bind(program);
  if (this->Now.Textured)
  {
    this->PointCoordinates.Bind(program, "pointTextureCoordinates");
    this->Image.Bind(program);
  }
  if (this->NeedGradients)
  {
    this->PointGradients.Bind(program, "pointGradients");
    uvgl::SetUniformMatrix(program, "modelToEyeNormals", frame.ModelToEyeNormals(this->Mesh.Center));
  }
}

/// The uniforms of the programs that integrate segments (uvSegmentIntegrationLib.glsl).
void vtkBarycentricShellMapper::Internals::SetIntegrationUniforms(
  vtkShaderProgram* program, const vtkUnstructuredVolumeFrame& frame, int isosurfaces)
{
  this->Nodes.Bind(program);
  this->Isosurfaces.Bind(program, "isosurfaces");
  program->SetUniformi("isosurfaceCount", isosurfaces);
  program->SetUniformi("averageScalar", 0);
  program->SetUniformi("shadeVolume", this->Now.Shade ? 1 : 0);
  uvgl::SetPhongUniforms(program, frame.Renderer, frame.Property, frame.WorldToEye);
}

/// Releases the texture units SetCellUniforms and SetIntegrationUniforms bound (each once, whatever
/// the number of programs that bound it).
void vtkBarycentricShellMapper::Internals::UnbindResources(bool opaqueGeometry)
{
  this->UnbindMesh();
  if (opaqueGeometry)
    this->Opaque.Unbind();
  if (this->Now.Textured)
  {
    this->PointCoordinates.Unbind();
    this->Image.Unbind();
  }
  if (this->ShellDensities())
    this->CellDensities.Unbind();
}

/// Every later pass touches only the pixels the drawn bounds can cover (the full-screen ones too):
/// those the base cleared the target for.
void vtkBarycentricShellMapper::Internals::ScissorToVolume(
  const vtkUnstructuredVolumeFrame& frame, const vtkUnstructuredVolumeFloatTarget& target)
{
  this->VolumeRectangle = target.GetDrawnPixels();
  const uv::PixelRectangle& r = this->VolumeRectangle;
  vtkOpenGLState* state = frame.Window->GetState();
  state->vtkglScissor(r[0], r[1], r[2], r[3]);
  state->vtkglEnable(GL_SCISSOR_TEST);
}

bool vtkBarycentricShellMapper::Internals::DrawCellProjection(
  const vtkUnstructuredVolumeFrame& frame, const vtkBarycentricShellPrograms& programs, bool opaqueGeometry)
{
  vtkShaderProgram* program = programs.OverCells(uvBarycentricCellProjectionFS);
  if (!program)
    return false;
  this->SetCellUniforms(program, frame, opaqueGeometry);
  this->SetIntegrationUniforms(program, frame, static_cast<int>(this->Isovalues.size()));
  if (this->DrawCellSurfaces)
    this->NeighbourValues.Bind(program, "neighbourValues");
  if (this->Now.SegmentTable)
    this->LengthTable.Bind(program);
  this->Projection.Run(frame.Window->GetState(), program, this->Cells, this->Order.Order.size());
  this->Self->CheckGLErrors("the cell projection");
  this->DrawnTetrahedra = static_cast<vtkIdType>(this->Order.Order.size());
  if (this->Now.SegmentTable)
    this->LengthTable.Unbind();
  return true;
}

/// The isosurfaces' layers (none without isosurface cells); `failed` when the program does not compile.
int vtkBarycentricShellMapper::Internals::DrawIsosurfaceLayers(
  const vtkUnstructuredVolumeFrame& frame, const vtkBarycentricShellPrograms& programs, bool opaqueGeometry,
  bool& failed)
{
  failed = false;
  if (this->Lists.Isosurface.empty())
    return 0;
  vtkShaderProgram* program = programs.OverCells(uvBarycentricShellIsosurfaceFS);
  if (!program)
  {
    failed = true;
    return 0;
  }
  this->SetCellUniforms(program, frame, opaqueGeometry);
  this->Isosurfaces.Bind(program, "isosurfaces");
  program->SetUniformi("isosurfaceCount", static_cast<int>(this->Isovalues.size()));
  uvgl::SetPhongUniforms(program, frame.Renderer, frame.Property, frame.WorldToEye);
  this->IsosurfaceLayers = this->Peel.Run(frame.Window->GetState(), program, this->Cells,
    this->Lists.Isosurface.size(), this->DrawnTetrahedra,
    [this](const char* pass) { return this->Self->CheckGLErrors(pass); });
  return this->IsosurfaceLayers;
}

/// The slice, blend and mask programs, bound in turn and given the uniforms that hold for every
/// shell; false when one does not compile.
bool vtkBarycentricShellMapper::Internals::ReadyShellPrograms(vtkBarycentricShellMapper* self,
  const vtkUnstructuredVolumeFrame& frame, const vtkBarycentricShellPrograms& programs, bool opaqueGeometry,
  int layers, ShellPrograms& shell)
{
  shell.Slice = programs.OverCells(uvBarycentricShellSliceFS);
  shell.Blend = shell.Slice ? programs.FullScreen(uvBarycentricShellBlendFS) : nullptr;
  shell.Mask = shell.Blend ? programs.FullScreen(uvOpacityMaskFS) : nullptr;
  if (!shell.Mask)
    return false;
  programs.Use(shell.Slice);
  this->SetCellUniforms(shell.Slice, frame, opaqueGeometry);
  shell.Slice->SetUniformf("sampleDistance", static_cast<float>(this->Now.SampleDistance));
  if (this->ShellDensities())
    this->CellDensities.Bind(shell.Slice, "cellDensities");
  programs.Use(shell.Blend);
  this->SetIntegrationUniforms(shell.Blend, frame, 0); // isosurfaces come from their own pass
  this->Peel.BindLayers(shell.Blend);
  this->Blend.Begin(shell.Blend, layers, this->Now.SampleDistance, this->Now.SegmentTable);
  shell.TerminateEarly = self->OpacityThreshold < 1.0;
  if (shell.TerminateEarly)
  {
    programs.Use(shell.Mask);
    shell.Mask->SetUniformf("opacityThreshold", static_cast<float>(self->OpacityThreshold));
  }
  return true;
}

/// Shell s: its slices, their integration under the image, and (but after the last shell) the mask
/// of the pixels now opaque enough. Its passes, clears included, touch only its cells' rectangle
/// within the volume's.
void vtkBarycentricShellMapper::Internals::DrawShell(int s, const vtkUnstructuredVolumeFrame& frame,
  vtkUnstructuredVolumeFloatTarget& target, const vtkBarycentricShellPrograms& programs, const ShellPrograms& shell)
{
  vtkOpenGLState* state = frame.Window->GetState();
  const uv::PixelRectangle r = uv::IntersectPixels(
    uv::ScreenBoxPixels(this->Buckets.Screen[s], frame.Width, frame.Height), this->VolumeRectangle);
  state->vtkglScissor(r[0], r[1], r[2], r[3]);
  state->vtkglDepthMask(GL_FALSE); // the mask is only read, except by the mask pass
  const float start = this->Layout.Start(s);
  const std::uint32_t count = this->Buckets.CellCount(s);
  this->Slices.Run(state, programs, shell.Slice, this->Cells, this->Buckets.Offsets[s], count, start);
  this->Self->CheckGLErrors("the shells' slices");
  this->DrawnTetrahedra += count;
  this->Blend.Run(state, programs, shell.Blend, target, this->Slices, start);
  this->Self->CheckGLErrors("the shells' blend");
  if (shell.TerminateEarly && s + 1 < this->Buckets.Count())
  {
    this->Slices.BindTargets();
    programs.Use(shell.Mask);
    this->Mask.Run(state, shell.Mask, target.GetColor());
    this->Self->CheckGLErrors("the shells' opacity mask");
  }
}

/// Isosurface layers first, then each shell front to back; shells nothing overlaps are skipped.
bool vtkBarycentricShellMapper::Internals::DrawShells(vtkBarycentricShellMapper* self,
  const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target,
  const vtkBarycentricShellPrograms& programs, bool opaqueGeometry)
{
  bool failed = false;
  const int layers = this->DrawIsosurfaceLayers(frame, programs, opaqueGeometry, failed);
  ShellPrograms shell;
  if (failed || !this->ReadyShellPrograms(self, frame, programs, opaqueGeometry, layers, shell))
    return false;
  vtkOpenGLState* state = frame.Window->GetState();
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LESS);
  for (int s = 0; s < this->Buckets.Count(); ++s)
  {
    if (this->Buckets.IsEmpty(s))
    {
      ++this->SkippedShells;
      continue;
    }
    ++this->Shells;
    this->DrawShell(s, frame, target, programs, shell);
  }
  this->Blend.End();
  this->Peel.UnbindLayers();
  return true;
}

vtkBarycentricShellMapper::vtkBarycentricShellMapper()
  : Impl(new Internals(this))
{
  // Above the hexahedral mapper's 0.99, whose loss the benchmark found larger than the error of
  // fine sampling.
  this->OpacityThreshold = 0.999;
}

vtkBarycentricShellMapper::~vtkBarycentricShellMapper() = default;

void vtkBarycentricShellMapper::SetTextureImage(vtkImageData* image)
{
  if (this->Impl->TextureImage != image)
  {
    this->Impl->TextureImage = image;
    this->Modified();
  }
}

vtkImageData* vtkBarycentricShellMapper::GetTextureImage()
{
  return this->Impl->TextureImage;
}

void vtkBarycentricShellMapper::ReportStatistics(vtkUnstructuredVolumeFrameStatistics* statistics)
{
  this->Superclass::ReportStatistics(statistics);
  const Internals& impl = *this->Impl;
  statistics->SetValue("Shells", impl.Shells);
  statistics->SetValue("DrawnIsosurfaceLayers", impl.IsosurfaceLayers);
  statistics->SetValue("SkippedShells", impl.SkippedShells);
  statistics->SetValue("SampleDistance", impl.LastSampleDistance);
  statistics->SetValue("SegmentTableBuilds", impl.Table.Builds);
}

vtkIdType vtkBarycentricShellMapper::GetMeshMemoryInBytes()
{
  const Internals& impl = *this->Impl;
  return static_cast<vtkIdType>(impl.TetrahedronPoints.GetBytes() + impl.Points.GetBytes() +
    impl.PointGradients.GetBytes() + impl.PointCoordinates.GetBytes() + impl.Slices.GetBytes() +
    impl.Peel.GetBytes() + impl.Projection.GetBytes());
}

void vtkBarycentricShellMapper::ForgetMesh()
{
  // Prepare builds many products of the mesh, each keyed on what it was built from; one cut short
  // by running out of memory may hold its key and not its content. All are made anew (the base has
  // released the GPU objects first).
  this->Impl.reset(new Internals(this));
}

void vtkBarycentricShellMapper::ReleaseMapperGraphics()
{
  this->Impl->Release();
}

void vtkBarycentricShellMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderMode: " << (this->RenderMode == SHELLS ? "Shells" : "CellProjection") << "\n";
  os << indent << "SampleDistance: " << this->SampleDistance << "\n";
  os << indent << "AutomaticSamplesAcross: " << this->AutomaticSamplesAcross << "\n";
  os << indent << "SlicesPerShell: " << this->SlicesPerShell << "\n";
  os << indent << "IsosurfaceLayers: " << this->IsosurfaceLayers << "\n";
}

bool vtkBarycentricShellMapper::Prepare(const vtkUnstructuredVolumeFrame& frame)
{
  Internals& impl = *this->Impl;
  impl.Shells = impl.SkippedShells = impl.IsosurfaceLayers = 0;
  impl.DrawnTetrahedra = 0;
  if (!impl.UpdateMesh(this, frame) || !impl.UpdateTransferFunction(this, frame) ||
    !impl.UpdateLists(this->SkipInvisibleCells && !impl.Now.Textured))
  {
    return false;
  }
  impl.Now.CellProjection = (this->RenderMode == CELL_PROJECTION || impl.DrawCellSurfaces) && !impl.Now.Textured;
  impl.Now.Pulling = this->ProjectionRoute == VERTEX_PULLING;
  impl.Now.Slices = this->SlicesPerShell;
  impl.Now.Targets = (this->SlicesPerShell + 1 + 3) / 4;
  impl.Now.Layers = this->IsosurfaceLayers;
  impl.UpdateGradients(this, frame);
  impl.UpdateSampleDistance(this, frame);
  if (impl.Now.CellProjection)
  {
    this->UpdateOrder(frame, false); // back to front
  }
  else if (!impl.UpdateShells(this, frame))
  {
    return false;
  }
  // Shells integrate segments of one length, cell projection whole segments through tetrahedra: a
  // table lookup each, where reading the table costs no more accuracy than the transfer-function
  // tolerance allows (measured), or as the user chose. Isosurfaces and lighting need the cuts.
  impl.Now.SegmentTable = false;
  const bool cutsNeeded = impl.Now.CellProjection && (impl.Now.Lit || !impl.Isovalues.empty());
  if (this->SegmentIntegration != EXACT && !impl.Now.CellProjection)
  {
    impl.Table.Update(impl.TransferFunction.Nodes, impl.Now.SampleDistance);
    impl.Now.SegmentTable =
      this->SegmentIntegration == TABLE || impl.Table.Error <= this->TransferFunctionTolerance;
  }
  else if (impl.Now.CellProjection)
  {
    impl.Now.SegmentTable = this->ChooseLengthTable(frame, cutsNeeded);
  }
  impl.LastSampleDistance = impl.Now.SampleDistance;
  return true;
}

bool vtkBarycentricShellMapper::Upload(const vtkUnstructuredVolumeFrame& frame)
{
  Internals& impl = *this->Impl;
  impl.UploadData(frame.Window);
  impl.UploadPasses(frame);
  return true;
}

bool vtkBarycentricShellMapper::Draw(const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target)
{
  Internals& impl = *this->Impl;
  impl.Mask.AttachAndClear(target, frame.Window->GetState()); // nothing is opaque yet
  target.GetNoAttributes()->Bind(); // every pass pulls its vertices from buffer textures
  bool opaqueGeometry = false; // where nothing was drawn before the volume, the pass would find none
  bool drawn = !frame.OpaqueDepth || impl.Opaque.Run(frame, target, opaqueGeometry);
  this->CheckGLErrors("the shells' opaque distances");
  if (!drawn)
  {
    vtkErrorMacro("the opaque-distance shaders failed to compile or link");
  }
  else
  {
    const vtkBarycentricShellPrograms programs(frame.Window, impl.Defines(opaqueGeometry), impl.Now.Pulling);
    impl.ScissorToVolume(frame, target);
    drawn = impl.Now.CellProjection ? impl.DrawCellProjection(frame, programs, opaqueGeometry)
                                    : impl.DrawShells(this, frame, target, programs, opaqueGeometry);
    impl.UnbindResources(opaqueGeometry);
    if (!drawn)
      vtkErrorMacro("the barycentric shell shaders failed to compile or link");
  }
  target.GetNoAttributes()->Release();
  // The passes bound framebuffers of their own: the target again, for the base's read-back.
  target.GetFramebuffer()->Bind();
  target.GetFramebuffer()->ActivateDrawBuffers(1);
  return drawn;
}

vtkUnstructuredVolumeTetrahedralState& vtkBarycentricShellMapper::GetTetrahedralState()
{
  return *this->Impl;
}
