#include "vtkHexahedralRayCastMapper.h"

#include "uvIsosurfaceList.h"
#include "uvVisibleRegion.h"
#include "vtkHexahedralRayCastPrograms.h"
#include "vtkPreIntegratedTetrahedraMapper.h"
#include "vtkUnstructuredVolumeBufferTexture.h"
#include "vtkUnstructuredVolumeFloatTarget.h"
#include "vtkUnstructuredVolumeFrame.h"
#include "vtkUnstructuredVolumeFrameStatistics.h"
#include "vtkuvHexahedralMesh.h"
#include "vtkUnstructuredVolumeOpenGL.h"
#include "vtkUnstructuredVolumePeelImages.h"
#include "vtkUnstructuredVolumeTexture.h"
#include "vtkuvNormalisedTransferFunction.h"
#include "vtkUnstructuredVolumeTransferFunctionTexture.h"
#include "vtkuvVertexGradientCache.h"

#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkCellType.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdint>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkHexahedralRayCastMapper);

namespace
{
/// The automatic InvisibleRunLimit. Not zero: where a ray only grazes an edge or a corner of an
/// invisible cell between visible ones, the region's faces fold, and rasterising the fold's edge may
/// round either way, so no entry face would pick the ray up again. Not a few either: every peel adds
/// two passes over the screen and restarts each ray, which costs more than walking the gaps between
/// visible cells (past the visible cells' box a ray stops at once). About the cells across the mesh:
/// only a gap as long as the mesh is wide is worth a peel.
int InvisibleCellsWalked(std::size_t cells)
{
  return std::max(16, static_cast<int>(std::cbrt(static_cast<double>(cells))));
}

void SetMatrix(vtkShaderProgram* program, const char* name, const glm::dmat4& m)
{
  const glm::mat4 single(m);
  program->SetUniformMatrix4x4(name, const_cast<float*>(glm::value_ptr(single)));
}

/// Where the first peel's rays start when the near plane lies inside the mesh (the camera inside it,
/// or just outside with the near plane cutting it, where no entry face is left in front of the rays):
/// the cell holding a perspective eye, else the one holding the near plane's centre, or -1. Each ray
/// walks from it to its own near-plane point. Searched again only when the mesh or the points moved.
class RayStartCell
{
public:
  int Update(const vtkuv::HexahedralMesh& mesh, bool perspective, const glm::dvec3& eye, const glm::dvec3& nearCentre)
  {
    if (mesh.Version != this->MeshVersion || perspective != this->Perspective || eye != this->Eye ||
      nearCentre != this->NearCentre)
    {
      // Each search scans every cell: asked only for points within the mesh's box, so that a camera
      // moving outside the mesh costs nothing per frame.
      this->Cell =
        perspective && InBox(mesh, eye) ? uv::HexahedronHolding(mesh.CellPoints, mesh.Points.Values, eye) : -1;
      if (this->Cell < 0 && InBox(mesh, nearCentre))
        this->Cell = uv::HexahedronHolding(mesh.CellPoints, mesh.Points.Values, nearCentre);
      this->MeshVersion = mesh.Version;
      this->Perspective = perspective;
      this->Eye = eye;
      this->NearCentre = nearCentre;
    }
    return this->Cell;
  }

private:
  int Cell = -1;
  std::uint64_t MeshVersion = 0;
  bool Perspective = false;
  glm::dvec3 Eye{ 0.0 }, NearCentre{ 0.0 };

  /// Whether `x` (recentred, as the cells' corners) lies in the box of the mesh's points, widened by
  /// more than the rounding of their recentred float copies.
  static bool InBox(const vtkuv::HexahedralMesh& mesh, const glm::dvec3& x)
  {
    const double* b = mesh.Points.Bounds;
    const glm::dvec3 low(b[0], b[2], b[4]), high(b[1], b[3], b[5]);
    const glm::dvec3 slack(1e-6 * glm::length(high - low));
    const glm::dvec3 y = x + mesh.Points.Center;
    return glm::all(glm::greaterThanEqual(y, low - slack)) && glm::all(glm::lessThanEqual(y, high + slack));
  }
};

/// The faces where rays enter: the whole mesh's boundary, or with skipping the visible region's
/// (uvVisibleRegion.h), the front of the visible matter. Cell ranges are computed once per change of the mesh
/// (and isosurface kind); the region is rebuilt, and its version bumped for the GPU copy, only when
/// the set of visible cells changes.
class EntryFaces
{
public:
  std::uint64_t Version = 0; ///< of Boundary(), for the GPU copy
  int RegionBuilds = 0;

  /// True when the faces changed.
  bool Update(const vtkuv::HexahedralMesh& mesh, bool skip, const std::vector<uv::TransferFunction::Node>& nodes,
    const std::vector<uv::Isosurface>& isosurfaces)
  {
    const bool widen = !mesh.CellScalars.empty() && !isosurfaces.empty();
    if (skip && (mesh.Version != this->RangesMeshVersion || widen != this->RangesWidened))
    {
      uv::HexahedralCellRanges(mesh.CellPoints, mesh.Points.Values, mesh.CellScalars, mesh.Faces.Neighbours, widen,
        this->Low, this->High, vtkuv::ParallelFor);
      this->RangesMeshVersion = mesh.Version;
      this->RangesWidened = widen;
      this->Classified = false;
    }
    const bool newCells = mesh.CellsVersion != this->MeshCellsVersion;
    bool changed = skip != this->Skip || newCells;
    std::vector<double> isovalues;
    for (const uv::Isosurface& surface : isosurfaces)
      isovalues.push_back(surface.Value);
    std::sort(isovalues.begin(), isovalues.end());
    std::vector<std::pair<double, double>> zeroSet = uv::ZeroExtinctionIntervals(nodes);
    // Visibility is classified again only when the ranges, the zero set or the isovalues changed,
    // and the region rebuilt only when that changed which cells are visible (or the cells are new).
    if (skip && (!this->Classified || this->Visible.empty() || zeroSet != this->ZeroSet || isovalues != this->Isovalues))
    {
      std::vector<unsigned char> visible =
        uv::VisibleCells(this->Low, this->High, zeroSet, isovalues, vtkuv::ParallelFor);
      this->Box = uv::BoxOfCells(mesh.CellPoints, mesh.Points.Values, visible);
      this->ZeroSet = std::move(zeroSet);
      this->Isovalues = std::move(isovalues);
      this->Classified = true;
      if (visible != this->Visible || newCells)
      {
        this->Region = uv::MakeVisibleRegion(mesh.Faces, visible);
        this->VisibleBits.assign((visible.size() + 31) / 32, 0u);
        for (std::size_t cell = 0; cell < visible.size(); ++cell)
          this->VisibleBits[cell / 32] |= visible[cell] ? 1u << (cell % 32) : 0u;
        this->Visible = std::move(visible);
        ++this->RegionBuilds;
        changed = true;
      }
    }
    else if (!skip && !this->Visible.empty())
    {
      this->Visible.clear();
      this->VisibleBits.clear();
      this->Region = uv::VisibleRegion();
    }
    changed = this->AddFacesOfOverlappingCells(mesh, skip, changed) || changed;
    this->Skip = skip;
    this->MeshCellsVersion = mesh.CellsVersion;
    this->Mesh = &mesh;
    this->Version += changed ? 1 : 0;
    return changed;
  }

  const std::vector<std::int32_t>& Boundary() const
  {
    if (!this->WithOverlaps.empty())
      return this->WithOverlaps;
    return this->Skip || !this->Mesh ? this->Region.Boundary : this->Mesh->Faces.Boundary;
  }
  std::size_t BoundaryCount() const { return this->Boundary().size() / 4; }
  /// With skipping, the region's cells, one bit each (32 to a word), for the GPU copy.
  const std::vector<std::uint32_t>& VisibleCellBits() const { return this->VisibleBits; }
  bool Skipping() const { return this->Skip; }
  /// With skipping, a box holding every visible cell (low xyz, high xyz; none visible: a point).
  const std::array<float, 6>& VisibleBox() const { return this->Box; }
  /// (Before any frame, or after frames handed to the tetrahedra mapper only, none.)
  std::size_t VisibleCells() const
  {
    return this->Skip || !this->Mesh ? this->Region.VisibleCells : this->Mesh->CellCount();
  }

private:
  const vtkuv::HexahedralMesh* Mesh = nullptr;
  bool Skip = false;
  std::uint64_t MeshCellsVersion = 0, RangesMeshVersion = 0;
  bool RangesWidened = false, Classified = false;
  std::vector<float> Low, High;
  std::vector<std::pair<double, double>> ZeroSet; // what Visible was classified with
  std::vector<double> Isovalues;
  std::vector<unsigned char> Visible;
  std::vector<std::uint32_t> VisibleBits;
  std::array<float, 6> Box{};
  uv::VisibleRegion Region;
  std::uint64_t OverlapsMeshVersion = 0;
  std::vector<std::int32_t> WithOverlaps; // the entry faces and the faces of overlapping cells

  /// Where cells overlap, the entry faces and the faces of the overlapping (visible) cells inside the
  /// mesh, through which a fold can let a ray in before any boundary face (uvOverlappingCells.h);
  /// true when that list changed.
  bool AddFacesOfOverlappingCells(const vtkuv::HexahedralMesh& mesh, bool skip, bool changed)
  {
    if (!changed && mesh.Version == this->OverlapsMeshVersion)
      return false;
    this->OverlapsMeshVersion = mesh.Version;
    const bool had = !this->WithOverlaps.empty();
    this->WithOverlaps.clear();
    if (mesh.Overlaps.PairCount() == 0)
      return had;
    this->WithOverlaps = skip ? this->Region.Boundary : mesh.Faces.Boundary;
    const std::vector<std::int32_t> inside = uv::FacesOfOverlappingCells(mesh.Overlaps, mesh.Faces.Neighbours,
      [&](std::size_t cell) { return !skip || this->Visible[cell]; });
    this->WithOverlaps.insert(this->WithOverlaps.end(), inside.begin(), inside.end());
    return true;
  }
};

/// The GPU copies of the mesh, the transfer function and the isosurfaces.
struct GpuResources
{
  vtkUnstructuredVolumeBufferTexture CellPoints, Points, Neighbours, BoundaryFaces;
  vtkUnstructuredVolumeBufferTexture CellScalars; // cell data only
  vtkUnstructuredVolumeBufferTexture CellDensities; // only where cells coincide
  vtkUnstructuredVolumeBufferTexture VisibleCells; // skipping only
  vtkUnstructuredVolumeBufferTexture PointGradients; // vertex-gradient lighting only
  vtkUnstructuredVolumeBufferTexture OverlapPartners; // folded cells only
  vtkUnstructuredVolumeTransferFunctionTexture TransferFunction;
  vtkUnstructuredVolumeTexture Isosurfaces;

  void Release()
  {
    for (vtkUnstructuredVolumeBufferTexture* texture : { &this->CellPoints, &this->Points, &this->Neighbours,
           &this->BoundaryFaces, &this->CellScalars, &this->CellDensities, &this->VisibleCells,
           &this->PointGradients, &this->OverlapPartners })
      texture->Release();
    this->TransferFunction.Release();
    this->Isosurfaces.Release();
  }
};

using PeelImages = vtkUnstructuredVolumePeelImages;

/// What both passes of a frame read: the camera in the mesh's recentred model space and the
/// frame's GL objects.
struct PassFrame
{
  const vtkUnstructuredVolumeFrame* Frame = nullptr;
  vtkOpenGLVertexArrayObject* NoAttributes = nullptr;
  glm::dmat4 ModelToClip{ 1.0 }, ClipToModel{ 1.0 }, ModelToEye{ 1.0 };
  glm::dmat3 NormalToEye{ 1.0 };
  double MeshRadius = 1.0; // half the diagonal of the points' bounds, about `center`

  static PassFrame Make(const vtkUnstructuredVolumeFrame& frame, const glm::dvec3& center, const double bounds[6],
    vtkOpenGLVertexArrayObject* noAttributes)
  {
    PassFrame pass;
    const glm::dvec3 diagonal(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]);
    pass.MeshRadius = std::max(0.5 * glm::length(diagonal), std::numeric_limits<double>::min());
    pass.Frame = &frame;
    pass.NoAttributes = noAttributes;
    pass.ModelToEye = frame.ModelToEye(center);
    pass.ModelToClip = frame.ModelToClip(center);
    pass.ClipToModel = glm::inverse(pass.ModelToClip);
    pass.NormalToEye = frame.ModelToEyeNormals(center);
    return pass;
  }

  /// The eye rays (uvEyeRayLib.glsl) and the clip-to-model matrix.
  void SetRayUniforms(vtkShaderProgram* program) const
  {
    uvgl::SetEyeRayUniforms(program, this->ClipToModel, this->Frame->Width, this->Frame->Height);
    SetMatrix(program, "clipToModel", this->ClipToModel);
  }
};

/// Per peel, the nearest boundary face where each pixel's ray enters the mesh beyond where the
/// previous peel left it: the boundary faces rasterised (12 vertices each, pulled from the mesh's
/// buffer textures) into Entry, depth-tested.
class EntryPass
{
public:
  /// False when the program failed; `entered` tells whether any ray entered the mesh. `foldedCells`:
  /// the mesh has some, whose faces a ray may enter by any crossing (the test runs only then).
  bool Draw(const PassFrame& pass, PeelImages& images, GpuResources& gpu, std::size_t boundaryCount, bool firstPeel,
    bool foldedCells, bool& entered)
  {
    vtkOpenGLRenderWindow* window = pass.Frame->Window;
    vtkOpenGLState* state = window->GetState();
    images.BeginEntryPass(state);
    vtkShaderProgram* program = uvgl::ReadyProgram(window, this->Sources);
    if (program)
    {
      gpu.BoundaryFaces.Bind(program, "boundaryFaces");
      gpu.CellPoints.Bind(program, "cellPoints");
      gpu.Points.Bind(program, "pointData");
      images.Exit->Activate();
      program->SetUniformi("previousExit", images.Exit->GetTextureUnit());
      program->SetUniformi("firstPeel", firstPeel ? 1 : 0);
      program->SetUniformi("foldedCells", foldedCells ? 1 : 0);
      program->SetUniformf("meshRadius", static_cast<float>(pass.MeshRadius));
      SetMatrix(program, "modelToClip", pass.ModelToClip);
      pass.SetRayUniforms(program);
      pass.NoAttributes->Bind();
      entered = uvgl::SamplesPassed([&] {
        uvgl::DrawItemsInChunks(program, "faceOffset", GL_TRIANGLES, boundaryCount, 12);
      }) > 0;
      pass.NoAttributes->Release();
      images.Exit->Deactivate();
      gpu.BoundaryFaces.Unbind();
      gpu.CellPoints.Unbind();
      gpu.Points.Unbind();
    }
    images.Framebuffer->RemoveDepthAttachment();
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_FALSE);
    return program != nullptr;
  }

private:
  const uvgl::ProgramSources Sources = vtkHexahedralRayCastPrograms::Entry();
};

/// The mapper's settings the traversal reads, and where its rays start.
struct TraversalSettings
{
  int IntegrationMode = 0, FixedSteps = 8;
  bool ExactEnds = true;
  float OpacityThreshold = 0.999f;
  int MaximumCells = 0; // bounds the walk (and any cycle in it)
  int InvisibleRunLimit = 16; // with skipping: invisible cells in a row before the next peel
  std::array<float, 6> VisibleBox{}; // with skipping: past it an invisible cell ends the ray
  int StartCell = -1;   // where the first peel's rays start (RayStartCell), or -1
  int IsosurfaceCount = 0;
  bool CellScalars = false;    // the mesh's scalar is per cell (uploaded to GpuResources::CellScalars)
  bool CellDensities = false;  // some cells stand for coincident copies (GpuResources::CellDensities)
  bool SkipInvisibleCells = false; // rays enter and leave at the visible region (GpuResources::VisibleCells)
  bool VertexGradients = false;    // isosurfaces lit by GpuResources::PointGradients
  int CellGeometry = 0;            // what every cell is (uv::MeshCellGeometry)
  bool TangledCells = false;       // some cells fold over themselves (uv::IsTangledHexahedron)
  bool LastPeel = false;           // no peel is left to pick a ray up
};

/// Per peel, full screen: walks each ray from its entry through the cells, integrating them, and
/// composites front to back over `accumulated` into `into`; writes where each ray left the mesh into
/// Exit, for the next peel's entry pass.
class TraversePass
{
public:
  /// False when the program failed.
  bool Draw(const PassFrame& pass, PeelImages& images, GpuResources& gpu, const TraversalSettings& settings,
    vtkTextureObject* sceneDepth, vtkTextureObject* accumulated, vtkTextureObject* into)
  {
    images.Framebuffer->AddColorAttachment(0, into);
    images.Framebuffer->AddColorAttachment(1, images.Exit);
    images.Framebuffer->ActivateDrawBuffers(2);
    const bool cellScalars = settings.CellScalars, skip = settings.SkipInvisibleCells;
    const bool vertexGradients = settings.VertexGradients, densities = settings.CellDensities;
    const bool folded = settings.TangledCells && settings.CellGeometry == 0; // the program's UV_TANGLED_CELLS
    vtkShaderProgram* program = this->Ready(pass.Frame->Window,
      { uvgl::NodesNeedTexture(gpu.TransferFunction.GetNodes()), cellScalars, skip, vertexGradients, densities,
        settings.IntegrationMode, settings.CellGeometry, settings.TangledCells });
    if (program)
    {
      images.Entry->Activate();
      accumulated->Activate();
      sceneDepth->Activate();
      program->SetUniformi("entry", images.Entry->GetTextureUnit());
      program->SetUniformi("accumulated", accumulated->GetTextureUnit());
      program->SetUniformi("opaqueDepth", sceneDepth->GetTextureUnit());
      gpu.BoundaryFaces.Bind(program, "boundaryFaces");
      gpu.CellPoints.Bind(program, "cellPoints");
      gpu.Neighbours.Bind(program, "cellNeighbours");
      gpu.Points.Bind(program, "pointData");
      if (cellScalars)
        gpu.CellScalars.Bind(program, "cellScalars");
      if (densities)
        gpu.CellDensities.Bind(program, "cellDensities");
      if (skip)
        gpu.VisibleCells.Bind(program, "visibleCells");
      if (vertexGradients)
        gpu.PointGradients.Bind(program, "pointGradients");
      if (folded)
        gpu.OverlapPartners.Bind(program, "overlapPartners");
      gpu.TransferFunction.Bind(program);
      gpu.Isosurfaces.Bind(program, "isosurfaces");
      SetUniforms(program, pass, settings);
      pass.NoAttributes->Bind();
      glDrawArrays(GL_TRIANGLES, 0, 3);
      pass.NoAttributes->Release();
      for (vtkTextureObject* texture : { images.Entry.Get(), accumulated, sceneDepth })
        texture->Deactivate();
      for (vtkUnstructuredVolumeBufferTexture* texture : { &gpu.BoundaryFaces, &gpu.CellPoints, &gpu.Neighbours,
             &gpu.Points })
        texture->Unbind();
      if (cellScalars)
        gpu.CellScalars.Unbind();
      if (densities)
        gpu.CellDensities.Unbind();
      if (skip)
        gpu.VisibleCells.Unbind();
      if (vertexGradients)
        gpu.PointGradients.Unbind();
      if (folded)
        gpu.OverlapPartners.Unbind();
      gpu.TransferFunction.Unbind();
      gpu.Isosurfaces.Unbind();
    }
    images.Framebuffer->RemoveColorAttachment(1);
    images.Framebuffer->ActivateDrawBuffers(1);
    return program != nullptr;
  }

private:
  vtkHexahedralRayCastPrograms::TraversalOptions Options;
  uvgl::ProgramSources Sources;

  /// The program for these options (built again only when they change).
  vtkShaderProgram* Ready(vtkOpenGLRenderWindow* window, const vtkHexahedralRayCastPrograms::TraversalOptions& options)
  {
    if (!(options == this->Options) || this->Sources.Fragment.empty())
    {
      this->Sources = vtkHexahedralRayCastPrograms::Traversal(options);
      this->Options = options;
    }
    return uvgl::ReadyProgram(window, this->Sources);
  }

  static void SetUniforms(vtkShaderProgram* program, const PassFrame& pass, const TraversalSettings& settings)
  {
    const vtkUnstructuredVolumeFrame& frame = *pass.Frame;
    program->SetUniformi("isosurfaceCount", settings.IsosurfaceCount);
    SetMatrix(program, "modelToEye", pass.ModelToEye);
    const glm::mat3 normals(pass.NormalToEye);
    program->SetUniformMatrix3x3("normalToEye", const_cast<float*>(glm::value_ptr(normals)));
    program->SetUniformi("parallelProjection", frame.Parallel ? 1 : 0);
    uvgl::SetPhongUniforms(program, frame.Renderer, frame.Property, frame.WorldToEye);
    pass.SetRayUniforms(program);
    program->SetUniformi("fixedSteps", settings.FixedSteps);
    program->SetUniformi("exactEnds", settings.ExactEnds ? 1 : 0);
    program->SetUniformf("opacityThreshold", settings.OpacityThreshold);
    program->SetUniformi("maximumCells", settings.MaximumCells);
    // The last peel walks on through invisible runs: no peel is left to pick the ray up.
    if (settings.SkipInvisibleCells)
    {
      program->SetUniformi("invisibleCellLimit",
        settings.LastPeel ? settings.MaximumCells : settings.InvisibleRunLimit);
      program->SetUniform3f("visibleLow", settings.VisibleBox.data());
      program->SetUniform3f("visibleHigh", settings.VisibleBox.data() + 3);
    }
    program->SetUniformi("startCell", settings.StartCell);
  }
};

/// Cells the tetrahedra mapper takes as tetrahedra (higher-order ones subdivided as here).
bool IsTetrahedron(int type)
{
  return type == VTK_TETRA || type == VTK_QUADRATIC_TETRA || type == VTK_LAGRANGE_TETRAHEDRON ||
    type == VTK_BEZIER_TETRAHEDRON;
}
} // namespace

class vtkHexahedralRayCastMapper::Internals
{
public:
  explicit Internals(vtkHexahedralRayCastMapper* self)
    : Self(self)
  {
  }
  vtkHexahedralRayCastMapper* Self; // reports the GL errors of its passes (the debug mode)

  // CPU state, versioned for the GPU copies.
  vtkuv::HexahedralMesh Mesh;
  vtkuv::VertexGradientCache Gradients;
  bool NeedGradients = false; // this frame lights isosurfaces with vertex gradients
  vtkuv::NormalisedTransferFunction TransferFunction;
  std::vector<uv::Isosurface> DrawnIsosurfaces; // normalised like the scalar
  EntryFaces Entries;
  RayStartCell Start;
  int StartCellOfFrame = -1; // where the first peel's rays start (RayStartCell), or -1
  int Peels = 0;

  // Meshes of tetrahedra alone go to the tetrahedra mapper (DelegateTetrahedralMeshes).
  vtkSmartPointer<vtkPreIntegratedTetrahedraMapper> Tetrahedra; // made on the first handed-over frame
  bool Delegated = false;                                       // this frame is handed over
  vtkDataSet* TypesCheckedOf = nullptr; // AllTetrahedra is of this input at this time
  vtkMTimeType TypesCheckedAt = 0;
  bool AllTetrahedra = false;

  /// The input holds tetrahedra and nothing else, linear or of higher order (which both mappers
  /// subdivide alike); asked again only when it changes.
  bool OnlyTetrahedra(vtkDataSet* input)
  {
    if (input != this->TypesCheckedOf || input->GetMTime() != this->TypesCheckedAt)
    {
      this->TypesCheckedOf = input;
      this->TypesCheckedAt = input->GetMTime();
      auto* grid = vtkUnstructuredGrid::SafeDownCast(input);
      const vtkIdType cells = input->GetNumberOfCells();
      this->AllTetrahedra = grid && cells > 0;
      for (vtkIdType c = 0; c < cells && this->AllTetrahedra; ++c)
        this->AllTetrahedra = IsTetrahedron(grid->GetCellType(c));
    }
    return this->AllTetrahedra;
  }

  vtkPreIntegratedTetrahedraMapper* TetrahedraMapper()
  {
    if (!this->Tetrahedra)
    {
      this->Tetrahedra = vtkSmartPointer<vtkPreIntegratedTetrahedraMapper>::New();
      this->Self->ForwardMessagesOf(this->Tetrahedra);
    }
    return this->Tetrahedra;
  }

  // GPU state.
  GpuResources Gpu;
  PeelImages Images{ true }; // with the second accumulation image
  EntryPass Entry;
  TraversePass Traverse;

  /// Up to `maximumPeels` entry and traversal passes, each traversal compositing over the previous
  /// one's image: the target's colour (cleared) and Images.Accumulation in turns, the result ending
  /// in the target's. False when a program failed. Images' framebuffer must be bound.
  bool Peel(const PassFrame& pass, TraversalSettings& settings, vtkUnstructuredVolumeFloatTarget& target,
    int maximumPeels)
  {
    vtkTextureObject* accumulation[2] = { target.GetColor(), this->Images.Accumulation };
    int last = 0;
    for (int peel = 0; peel < maximumPeels; ++peel)
    {
      bool entered = false;
      if (!this->Entry.Draw(
            pass, this->Images, this->Gpu, this->Entries.BoundaryCount(), peel == 0, settings.TangledCells, entered))
        return false;
      this->Self->CheckGLErrors("the hexahedral entry pass");
      const bool fromStartCell = peel == 0 && this->StartCellOfFrame >= 0;
      if (!entered && !fromStartCell)
        break; // no ray enters the mesh again
      ++this->Peels;
      settings.StartCell = fromStartCell ? this->StartCellOfFrame : -1;
      settings.LastPeel = peel == maximumPeels - 1;
      if (!this->Traverse.Draw(pass, this->Images, this->Gpu, settings, target.GetSceneDepth(), accumulation[last],
            accumulation[1 - last]))
        return false;
      this->Self->CheckGLErrors("the hexahedral traversal pass");
      last = 1 - last;
    }
    if (last == 1)
    {
      this->Images.CopyAccumulationInto(target);
      this->Self->CheckGLErrors("the hexahedral accumulation copy");
    }
    return true;
  }
};

vtkHexahedralRayCastMapper::vtkHexahedralRayCastMapper()
  : Impl(new Internals(this))
{
  this->OpacityThreshold = 0.999;
  // The exact field's own gradient needs nothing computed ahead; the plugin picks vertex gradients.
  this->GradientMode = CELL_GRADIENTS;
}

vtkHexahedralRayCastMapper::~vtkHexahedralRayCastMapper() = default;

void vtkHexahedralRayCastMapper::ReportStatistics(vtkUnstructuredVolumeFrameStatistics* statistics)
{
  this->Superclass::ReportStatistics(statistics);
  const Internals& impl = *this->Impl;
  statistics->SetValue("Delegated", impl.Delegated ? 1.0 : 0.0);
  statistics->SetValue("Cells", static_cast<double>(impl.Mesh.CellCount()));
  statistics->SetValue("TangledCells", static_cast<double>(impl.Mesh.TangledCells));
  statistics->SetValue("OverlappingPairs", static_cast<double>(impl.Mesh.Overlaps.PairCount()));
  statistics->SetValue("BoundaryFaces", static_cast<double>(impl.Mesh.BoundaryCount()));
  statistics->SetValue("Peels", impl.Peels);
  statistics->SetValue("GradientComputations", impl.Gradients.Computations);
  statistics->SetValue("VisibleCells", static_cast<double>(impl.Entries.VisibleCells()));
  statistics->SetValue("EntryFaces", static_cast<double>(impl.Entries.BoundaryCount()));
  statistics->SetValue("VisibleRegionBuilds", impl.Entries.RegionBuilds);
}
vtkIdType vtkHexahedralRayCastMapper::GetMeshMemoryInBytes()
{
  if (this->Impl->Delegated)
    return this->Impl->Tetrahedra->GetMeshMemoryInBytes();
  return static_cast<vtkIdType>(this->Impl->Mesh.Bytes() + sizeof(float) * this->Impl->Gradients.Values.size());
}
void vtkHexahedralRayCastMapper::SetInputData(vtkDataSet* input)
{
  this->SetInputDataInternal(0, input);
}

int vtkHexahedralRayCastMapper::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  return 1;
}

void vtkHexahedralRayCastMapper::ForgetMesh()
{
  this->Impl->Mesh.Invalidate();
  if (this->Impl->Tetrahedra)
    ForgetMeshOf(this->Impl->Tetrahedra);
}

void vtkHexahedralRayCastMapper::ReleaseMapperGraphics()
{
  this->Impl->Gpu.Release();
  this->Impl->Images.Release();
  if (this->Impl->Tetrahedra)
    ReleaseGraphicsOf(this->Impl->Tetrahedra);
}

void vtkHexahedralRayCastMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const char* modes[] = { "Accurate", "Fast", "FixedSteps" };
  os << indent << "IntegrationMode: " << modes[this->IntegrationMode] << "\n";
  os << indent << "FixedSteps: " << this->FixedSteps << "\n";
  os << indent << "ExactSegmentEnds: " << this->ExactSegmentEnds << "\n";
  os << indent << "MaximumPeels: " << this->MaximumPeels << "\n";
  os << indent << "InvisibleRunLimit: " << this->InvisibleRunLimit << "\n";
  os << indent << "DelegateTetrahedralMeshes: " << this->DelegateTetrahedralMeshes << "\n";
}

bool vtkHexahedralRayCastMapper::UpdateMesh(vtkDataSet* input, const vtkuv::RenderedScalar& scalar)
{
  vtkuv::HexahedralMesh& mesh = this->Impl->Mesh;
  bool built = false;
  const std::string error =
    mesh.Update(input, scalar, [this](double progress) { this->UpdateProgress(progress); }, built);
  this->MeshUpdates = { mesh.Builds, mesh.PointRefreshes, mesh.ValueRefreshes };
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return false;
  }
  if (built && mesh.TangledCells > 0)
  {
    vtkWarningMacro(<< mesh.TangledCells << " hexahedra are tangled (their Jacobian changes sign, as in a "
                    << "crushed mesh): rendered as the reference takes them, by slower steps where they overlap other "
                    << "cells");
  }
  if (built && mesh.FlatCells > 0)
  {
    vtkWarningMacro(<< mesh.FlatCells << " cells are not 3D (vertices, lines, polygons) and are left out");
  }
  if (built && mesh.NaNCells > 0)
  {
    this->WarnOnce("NaN cells",
      std::to_string(mesh.NaNCells) + " cells touch a NaN scalar and are left out (holes in the mesh)");
  }
  return mesh.CellCount() > 0 && mesh.BoundaryCount() > 0;
}

bool vtkHexahedralRayCastMapper::HandsOver(vtkDataSet* input, const vtkuv::RenderedScalar& scalar)
{
  if (!this->DelegateTetrahedralMeshes || this->IntegrationMode == FIXED_STEPS ||
    !this->Impl->OnlyTetrahedra(input))
  {
    return false;
  }
  // Isosurfaces only where the other mapper draws and lights them as this one would.
  return this->GetNumberOfIsosurfaces() == 0 || (!scalar.OnCells && this->GradientMode == VERTEX_GRADIENTS);
}

bool vtkHexahedralRayCastMapper::Prepare(const vtkUnstructuredVolumeFrame& frame)
{
  Internals& impl = *this->Impl;
  impl.Peels = 0;
  vtkDataSet* input = this->GetDataSetInput();
  vtkuv::RenderedScalar scalar;
  if (!this->FindScalar(input, frame.Property, scalar))
    return false;
  impl.Delegated = this->HandsOver(input, scalar);
  if (impl.Delegated)
    return this->PrepareThrough(impl.TetrahedraMapper(), frame);
  if (!this->UpdateMesh(input, scalar))
    return false;
  // The traversal reads its nodes from uniforms only.
  const uv::ScalarNormalisation& normalisation = impl.Mesh.Points.Normalisation;
  if (!this->CommitTransferFunction(frame.Property, normalisation.Offset, normalisation.Scale, impl.TransferFunction,
        impl.DrawnIsosurfaces, static_cast<std::size_t>(uvgl::MaximumUniformNodes)))
    return false;
  // A cell scalar's isosurfaces are faces between cells (the walk draws them as it crosses); the
  // volume is unlit anyway (the shader lights only isosurfaces).
  this->WarnCellScalarLimits(scalar, false, true);
  impl.NeedGradients = this->GradientMode == VERTEX_GRADIENTS && !scalar.OnCells && !impl.DrawnIsosurfaces.empty();
  if (impl.NeedGradients)
    this->UpdateVertexGradients(impl.Gradients, impl.Mesh.Drawn, impl.Mesh.DrawnScalar, impl.Mesh.Version);
  impl.Entries.Update(impl.Mesh, this->SkipInvisibleCells, impl.TransferFunction.Nodes, impl.DrawnIsosurfaces);
  const glm::dvec3& center = impl.Mesh.Points.Center;
  // Also in an invisible cell: with skipping, the walk leaves its rays to the next peel's entry faces
  // after a few invisible cells.
  const glm::dvec4 nearCentre = glm::inverse(frame.ModelToClip(center)) * glm::dvec4(0.0, 0.0, -1.0, 1.0);
  impl.StartCellOfFrame =
    impl.Start.Update(impl.Mesh, !frame.Parallel, frame.EyeInModel(center), glm::dvec3(nearCentre) / nearCentre.w);
  return true;
}

bool vtkHexahedralRayCastMapper::Upload(const vtkUnstructuredVolumeFrame& frame)
{
  Internals& impl = *this->Impl;
  // Whichever of the two draws holds GPU memory, not both (the context is current here).
  if (impl.Delegated)
  {
    impl.Gpu.Release();
    impl.Images.Release();
    return UploadThrough(impl.Tetrahedra, frame);
  }
  if (impl.Tetrahedra)
  {
    ReleaseGraphicsOf(impl.Tetrahedra);
    impl.Tetrahedra = nullptr;
  }
  vtkOpenGLRenderWindow* window = frame.Window;
  const vtkuv::HexahedralMesh& mesh = impl.Mesh;
  impl.Gpu.CellPoints.Sync(window, mesh.CellPoints, 4, mesh.CellsVersion);
  impl.Gpu.Points.Sync(window, mesh.Points.Values, 4, mesh.Version);
  impl.Gpu.Neighbours.Sync(window, mesh.Faces.Neighbours, 4, mesh.CellsVersion);
  impl.Gpu.BoundaryFaces.Sync(window, impl.Entries.Boundary(), 4, impl.Entries.Version);
  if (impl.Entries.Skipping())
    impl.Gpu.VisibleCells.Sync(window, impl.Entries.VisibleCellBits(), 1, impl.Entries.Version);
  if (!mesh.CellScalars.empty())
    impl.Gpu.CellScalars.Sync(window, mesh.CellScalars, 1, mesh.Version);
  if (!mesh.CellDensities.empty())
    impl.Gpu.CellDensities.Sync(window, mesh.CellDensities, 1, mesh.CellsVersion);
  if (!mesh.PackedOverlaps.empty())
    impl.Gpu.OverlapPartners.Sync(window, mesh.PackedOverlaps, 1, mesh.Version);
  if (impl.NeedGradients)
    impl.Gpu.PointGradients.Sync(window, impl.Gradients.Values, 4, impl.Gradients.Version);
  impl.Gpu.TransferFunction.Sync(window, impl.TransferFunction.Nodes);
  impl.Gpu.Isosurfaces.Sync(window, uv::IsosurfaceList::TexelColumns(impl.DrawnIsosurfaces), 2, 4,
    uv::IsosurfaceList::Texels(impl.DrawnIsosurfaces));
  return true;
}

bool vtkHexahedralRayCastMapper::Draw(const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target)
{
  Internals& impl = *this->Impl;
  if (impl.Delegated)
    return DrawThrough(impl.Tetrahedra, frame, target);
  impl.Images.Resize(frame.Window, frame.Width, frame.Height);
  const PassFrame pass =
    PassFrame::Make(frame, impl.Mesh.Points.Center, impl.Mesh.Points.Bounds, target.GetNoAttributes());
  TraversalSettings settings;
  settings.IntegrationMode = this->IntegrationMode;
  settings.FixedSteps = this->FixedSteps;
  settings.ExactEnds = this->ExactSegmentEnds;
  settings.OpacityThreshold = static_cast<float>(this->OpacityThreshold);
  settings.MaximumCells = static_cast<int>(std::min<std::size_t>(impl.Mesh.CellCount() + 8, 1 << 20));
  settings.InvisibleRunLimit =
    this->InvisibleRunLimit > 0 ? this->InvisibleRunLimit : InvisibleCellsWalked(impl.Mesh.CellCount());
  settings.SkipInvisibleCells = impl.Entries.Skipping();
  settings.VisibleBox = impl.Entries.VisibleBox();
  settings.IsosurfaceCount = static_cast<int>(impl.DrawnIsosurfaces.size());
  settings.CellScalars = !impl.Mesh.CellScalars.empty();
  settings.CellDensities = !impl.Mesh.CellDensities.empty();
  settings.VertexGradients = impl.NeedGradients;
  settings.CellGeometry = static_cast<int>(impl.Mesh.Geometry);
  settings.TangledCells = impl.Mesh.TangledCells > 0;

  impl.Images.Framebuffer->SaveCurrentBindingsAndBuffers();
  impl.Images.Framebuffer->Bind();
  frame.Window->GetState()->vtkglDisable(GL_BLEND);
  const bool drawn = impl.Peel(pass, settings, target, this->MaximumPeels);
  impl.Images.Framebuffer->RestorePreviousBindingsAndBuffers();
  if (!drawn)
  {
    vtkErrorMacro("the hexahedral ray-casting shaders failed to compile or link");
  }
  return drawn;
}

void vtkHexahedralRayCastMapper::GetDrawnBounds(double bounds[6])
{
  if (this->Impl->Delegated)
  {
    DrawnBoundsOf(this->Impl->Tetrahedra, bounds);
    return;
  }
  const double* drawn = this->Impl->Mesh.Points.Bounds;
  if (drawn[0] <= drawn[1])
    std::copy(drawn, drawn + 6, bounds);
  else
    this->Superclass::GetDrawnBounds(bounds);
}
