#include "vtkBarycentricShellMapper.h"

#include "uvBarycentricCellProjectionFS.h"
#include "uvBarycentricOpaqueDistanceFS.h"
#include "uvBarycentricRayLib.h"
#include "uvBarycentricShellBlendFS.h"
#include "uvBarycentricCellListVS.h"
#include "uvBarycentricPullVS.h"
#include "uvBarycentricShellGS.h"
#include "uvBarycentricTetrahedronLib.h"
#include "uvBarycentricShellIsosurfaceFS.h"
#include "uvBarycentricShellMaskFS.h"
#include "uvBarycentricShellSliceFS.h"
#include "uvFullScreenTriangleVS.h"
#include "vtkUnstructuredVolumeOpenGL.h"
#include "uvSegmentIntegrationLib.h"
#include "vtkUnstructuredVolumeTetrahedralMesh.h"
#include "vtkUnstructuredVolumeTransferFunction.h"
#include "uvTransferFunctionLib.h"
#include "uvVisibilitySort.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtk_glew.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkBarycentricShellMapper);

namespace
{
constexpr int MaximumTargets = 8;    // slices: four per target (OpenGL 3.2 guarantees 8 draw buffers)
constexpr int MaximumShells = 4096;  // beyond it the sample distance is widened (with a warning)
constexpr float InsideTolerance = 1e-5f; // barycentric slack: no cracks between neighbours
constexpr int PullChunk = 16384;         // tetrahedra per draw of the vertex-pulling route
constexpr int SegmentTableSize = 256;    // texels per side of the fixed-length segment table
constexpr double TableTexelsPerNodeGap = 4.0; // AUTOMATIC: the table when every node gap spans this many

/// The four faces of tetrahedron q as vertices 4q + k, wound outwards when v1 - v0, v2 - v0, v3 - v0
/// are positively oriented (so the rasteriser can cull front faces).
std::vector<std::uint32_t> FaceIndexPattern(int tetrahedra)
{
  static const int faces[12] = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 };
  std::vector<std::uint32_t> indices(12 * static_cast<std::size_t>(tetrahedra));
  for (int q = 0; q < tetrahedra; ++q)
    for (int i = 0; i < 12; ++i)
      indices[12 * q + i] = static_cast<std::uint32_t>(4 * q + faces[i]);
  return indices;
}

/// The range of eye distances a tetrahedron covers (a lower bound and its maximum): under perspective,
/// |x| >= x.u for the unit u towards the centroid, and x.u is smallest at a vertex; |x| is largest at
/// one. Under parallel projection the depth -z, exact at the vertices.
void DistanceRange(const std::array<glm::vec3, 4>& v, bool parallel, float& low, float& high)
{
  if (parallel)
  {
    low = std::min({ -v[0].z, -v[1].z, -v[2].z, -v[3].z });
    high = std::max({ -v[0].z, -v[1].z, -v[2].z, -v[3].z });
    return;
  }
  const glm::vec3 centroid = 0.25f * (v[0] + v[1] + v[2] + v[3]);
  const float centroidLength = glm::length(centroid);
  high = 0.0f;
  low = std::numeric_limits<float>::infinity();
  for (const glm::vec3& p : v)
  {
    high = std::max(high, glm::length(p));
    low = centroidLength > 0.0f ? std::min(low, glm::dot(p, centroid) / centroidLength) : 0.0f;
  }
  low = std::max(low, 0.0f);
}

/// Normalised device coordinates (low x, low y, high x, high y) to pixels (x, y, width, height) of a
/// width x height viewport, a pixel of margin around.
std::array<int, 4> PixelRectangle(const glm::dvec4& ndc, int width, int height)
{
  const int x0 = std::clamp(static_cast<int>(std::floor((ndc[0] + 1.0) * 0.5 * width)) - 1, 0, width);
  const int y0 = std::clamp(static_cast<int>(std::floor((ndc[1] + 1.0) * 0.5 * height)) - 1, 0, height);
  const int x1 = std::clamp(static_cast<int>(std::ceil((ndc[2] + 1.0) * 0.5 * width)) + 1, 0, width);
  const int y1 = std::clamp(static_cast<int>(std::ceil((ndc[3] + 1.0) * 0.5 * height)) + 1, 0, height);
  return { x0, y0, std::max(x1 - x0, 0), std::max(y1 - y0, 0) };
}

/// The pixels the box `bounds` (world) can cover: its corners projected. The whole viewport when a
/// corner is not in front of the eye.
std::array<int, 4> ScreenRectangle(const double bounds[6], const glm::dmat4& worldToClip, int width, int height)
{
  double low[2] = { 1.0, 1.0 }, high[2] = { -1.0, -1.0 };
  for (int corner = 0; corner < 8; ++corner)
  {
    const glm::dvec4 clip =
      worldToClip * glm::dvec4(bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + (corner >> 2)], 1.0);
    if (!(clip.w > 1e-12))
    {
      return { 0, 0, width, height };
    }
    for (int axis = 0; axis < 2; ++axis)
    {
      low[axis] = std::min(low[axis], clip[axis] / clip.w);
      high[axis] = std::max(high[axis], clip[axis] / clip.w);
    }
  }
  return PixelRectangle(glm::dvec4(low[0], low[1], high[0], high[1]), width, height);
}
} // namespace

class vtkBarycentricShellMapper::Internals
{
public:
  uvvtk::TetrahedralMesh Mesh;
  std::vector<std::uint32_t> OrientedPoints; // Mesh.TetrahedronPoints, each positively oriented

  uvvtk::NormalisedTransferFunction TransferFunction;
  const std::vector<uv::TransferFunction::Node>& Nodes = TransferFunction.Nodes; // normalised scalars
  uv::IsosurfaceList Isosurfaces;
  vtkMTimeType IsosurfaceTime = 0, UploadedIsosurfaceTime = 0;

  // Which tetrahedra matter: the volume's (some extinction in their range), the isosurfaces'
  // (an isovalue in their range) and either (cell projection).
  std::string ListKey;
  std::vector<std::uint32_t> VolumeCells, IsosurfaceCells, DrawnCells;

  uvvtk::VertexGradientCache Gradients;

  // Per frame.
  std::vector<glm::vec3> EyePoints;
  std::vector<glm::vec2> ScreenPoints;   // normalised device coordinates (NaN: behind the eye)
  std::vector<glm::dvec4> ShellScreen;   // per shell: low x, low y, high x, high y in device coordinates
  std::vector<float> Low, High;                     // eye-distance range per volume cell
  std::vector<std::uint32_t> ShellOffsets, ShellCells; // volume cells per shell, concatenated
  std::vector<unsigned char> ShellHasIsosurface;
  std::vector<uv::TransferFunction::Node> SegmentTableNodes; // what the uploaded table is for
  double SegmentTableLength = 0.0;
  std::string AutomaticDistanceKey;
  double AutomaticDistance = 0.0;
  int SegmentTableBuilds = 0;
  uvvtk::CentroidOrder Order; // cell projection
  bool OrderUploaded = false;

  // GPU state, for one context.
  vtkOpenGLRenderWindow* Context = nullptr;
  vtkNew<vtkOpenGLBufferObject> TetrahedronBuffer, PointBuffer, GradientBuffer, ShellBuffer, IsosurfaceCellBuffer,
    OrderBuffer, FaceIndexBuffer;
  vtkNew<vtkTextureObject> TetrahedronTexture, PointTexture, GradientTexture, TransferTexture, IsosurfaceTexture,
    PsiTexture, SceneDepth, MaskDepth, Accumulation, IsosurfaceColor, IsosurfaceDistance, IsosurfaceDepth,
    PreviousLayer, ShellList, IsosurfaceList, OrderList, SegmentTableTexture, OpaqueDistances;
  std::array<vtkNew<vtkTextureObject>, MaximumTargets> Slices;
  vtkNew<vtkOpenGLFramebufferObject> SliceFramebuffer, AccumulationFramebuffer, IsosurfaceFramebuffer,
    OpaqueFramebuffer;
  vtkNew<vtkOpenGLVertexArrayObject> NoAttributes;
  bool MeshOnGpu = false, PointsOnGpu = false, GradientsOnGpu = false, TransferFunctionOnGpu = false,
       IsosurfaceCellsOnGpu = false, FaceIndicesOnGpu = false;
  int ImageSize[2] = { 0, 0 };
  int AllocatedTargets = 0, AllocatedLayers = 0;

  vtkSmartPointer<vtkImageData> FloatImage;
  int Shells = 0, SkippedShells = 0, IsosurfaceLayers = 0;
  vtkIdType DrawnTetrahedra = 0;
  double LastSampleDistance = 0.0;
  uvvtk::MeshWarnings Warned;
  bool WarnedMultisample = false, WarnedShells = false, WarnedTexture = false;

  // An image sampled through the points' texture coordinates (SetTextureImage).
  vtkSmartPointer<vtkImageData> TextureImage;
  std::string TextureKey, TextureCoordinatesKey;
  vtkNew<vtkTextureObject> VolumeTexture, TextureCoordinateTexture;
  vtkNew<vtkOpenGLBufferObject> TextureCoordinateBuffer;

  void ReleaseGraphics()
  {
    if (this->Context)
    {
      for (vtkTextureObject* texture : { this->TetrahedronTexture.Get(), this->PointTexture.Get(),
             this->GradientTexture.Get(), this->TransferTexture.Get(), this->IsosurfaceTexture.Get(),
             this->PsiTexture.Get(), this->SceneDepth.Get(), this->MaskDepth.Get(), this->Accumulation.Get(),
             this->IsosurfaceColor.Get(), this->IsosurfaceDistance.Get(), this->IsosurfaceDepth.Get(),
             this->PreviousLayer.Get(), this->ShellList.Get(), this->IsosurfaceList.Get(), this->OrderList.Get(),
             this->SegmentTableTexture.Get(), this->OpaqueDistances.Get(), this->VolumeTexture.Get(),
             this->TextureCoordinateTexture.Get() })
      {
        texture->ReleaseGraphicsResources(this->Context);
      }
      for (auto& slice : this->Slices)
        slice->ReleaseGraphicsResources(this->Context);
      for (vtkOpenGLBufferObject* buffer : { this->TetrahedronBuffer.Get(), this->PointBuffer.Get(),
             this->GradientBuffer.Get(), this->ShellBuffer.Get(), this->IsosurfaceCellBuffer.Get(),
             this->OrderBuffer.Get(), this->FaceIndexBuffer.Get(), this->TextureCoordinateBuffer.Get() })
      {
        buffer->ReleaseGraphicsResources();
      }
      for (vtkOpenGLFramebufferObject* framebuffer :
        { this->SliceFramebuffer.Get(), this->AccumulationFramebuffer.Get(), this->IsosurfaceFramebuffer.Get(),
          this->OpaqueFramebuffer.Get() })
      {
        framebuffer->ReleaseGraphicsResources(this->Context);
      }
      this->NoAttributes->ReleaseGraphicsResources();
    }
    this->Context = nullptr;
    this->MeshOnGpu = this->PointsOnGpu = this->GradientsOnGpu = this->TransferFunctionOnGpu = false;
    this->IsosurfaceCellsOnGpu = this->FaceIndicesOnGpu = false;
    this->UploadedIsosurfaceTime = 0;
    this->SegmentTableNodes.clear();
    this->SegmentTableLength = 0.0;
    this->OrderUploaded = false;
    this->TextureKey.clear();
    this->TextureCoordinatesKey.clear();
    this->ImageSize[0] = this->ImageSize[1] = 0;
    this->AllocatedTargets = this->AllocatedLayers = 0;
  }

  /// Rebuilds the three cell lists when the mesh, the zero-extinction set or the isovalues changed.
  void UpdateLists(bool skipInvisible, const std::vector<double>& isovalues)
  {
    const auto zeroSet = skipInvisible ? uv::ZeroExtinctionIntervals(this->Nodes)
                                       : std::vector<std::pair<double, double>>();
    std::string key = this->Mesh.Key() + "|";
    for (const auto& [begin, end] : zeroSet)
      key += std::to_string(begin) + "," + std::to_string(end) + ";";
    key += "|";
    for (double value : isovalues)
      key += std::to_string(value) + ";";
    if (key == this->ListKey)
    {
      return;
    }
    const std::size_t count = this->Mesh.Size();
    std::vector<unsigned char> flags(count, 0);
    vtkSMPTools::For(0, static_cast<vtkIdType>(count), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType t = begin; t < end; ++t)
      {
        const double low = this->Mesh.ScalarLow[t], high = this->Mesh.ScalarHigh[t];
        flags[t] = (uv::RangeHasZeroExtinction(low, high, zeroSet) ? 0 : 1) |
          (uv::RangeHoldsIsovalue(low, high, isovalues) ? 2 : 0);
      }
    });
    this->VolumeCells.clear();
    this->IsosurfaceCells.clear();
    this->DrawnCells.clear();
    for (std::size_t t = 0; t < count; ++t)
    {
      const auto id = static_cast<std::uint32_t>(t);
      if (flags[t] & 1)
        this->VolumeCells.push_back(id);
      if (flags[t] & 2)
        this->IsosurfaceCells.push_back(id);
      if (flags[t])
        this->DrawnCells.push_back(id);
    }
    this->ListKey = key;
    this->IsosurfaceCellsOnGpu = false;
    this->Order.Invalidate();
  }

  /// (Re)creates the screen-sized textures and the framebuffers around them.
  void EnsureImages(vtkOpenGLRenderWindow* window, int width, int height, int targets, int layers)
  {
    if (this->ImageSize[0] == width && this->ImageSize[1] == height && this->AllocatedTargets == targets &&
      this->AllocatedLayers == layers)
    {
      return;
    }
    auto floatImage = [&](vtkTextureObject* texture, int components) {
      texture->SetContext(window);
      texture->SetMinificationFilter(vtkTextureObject::Nearest);
      texture->SetMagnificationFilter(vtkTextureObject::Nearest);
      texture->Allocate2D(width, height, components, VTK_FLOAT);
    };
    for (vtkTextureObject* depth : { this->SceneDepth.Get(), this->MaskDepth.Get(), this->IsosurfaceDepth.Get() })
    {
      depth->SetContext(window);
      depth->AllocateDepth(width, height, vtkTextureObject::Float32);
    }
    floatImage(this->Accumulation, 4);
    floatImage(this->PreviousLayer, 1);
    floatImage(this->OpaqueDistances, 1);
    for (auto [texture, components] : { std::make_pair(this->IsosurfaceColor.Get(), 4),
           std::make_pair(this->IsosurfaceDistance.Get(), 1) })
    {
      // One layer per isosurface peel.
      texture->SetContext(window);
      texture->SetMinificationFilter(vtkTextureObject::Nearest);
      texture->SetMagnificationFilter(vtkTextureObject::Nearest);
      texture->Allocate3D(width, height, layers, components, VTK_FLOAT);
    }
    for (int t = 0; t < targets; ++t)
      floatImage(this->Slices[t], 4);

    auto assemble = [&](vtkOpenGLFramebufferObject* framebuffer, std::vector<vtkTextureObject*> colors,
                      vtkTextureObject* depth) {
      framebuffer->SetContext(window);
      framebuffer->SaveCurrentBindingsAndBuffers();
      framebuffer->Bind();
      framebuffer->RemoveColorAttachments(MaximumTargets);
      for (std::size_t c = 0; c < colors.size(); ++c)
        framebuffer->AddColorAttachment(static_cast<unsigned int>(c), colors[c]);
      framebuffer->AddDepthAttachment(depth);
      framebuffer->ActivateDrawBuffers(static_cast<unsigned int>(colors.size()));
      framebuffer->RestorePreviousBindingsAndBuffers();
    };
    std::vector<vtkTextureObject*> slices;
    for (int t = 0; t < targets; ++t)
      slices.push_back(this->Slices[t]);
    assemble(this->SliceFramebuffer, slices, this->MaskDepth);
    assemble(this->AccumulationFramebuffer, { this->Accumulation }, this->MaskDepth);
    assemble(this->OpaqueFramebuffer, { this->OpaqueDistances }, this->IsosurfaceDepth);
    this->IsosurfaceFramebuffer->SetContext(window); // its layers are attached pass by pass
    this->ImageSize[0] = width;
    this->ImageSize[1] = height;
    this->AllocatedTargets = targets;
    this->AllocatedLayers = layers;
  }
};

vtkBarycentricShellMapper::vtkBarycentricShellMapper()
  : Impl(new Internals)
{
  this->SetGradientArrayName("Gradients");
}

vtkBarycentricShellMapper::~vtkBarycentricShellMapper()
{
  this->SetGradientArrayName(nullptr);
}

void vtkBarycentricShellMapper::AddIsosurface(double value, double red, double green, double blue, double opacity)
{
  this->Impl->Isosurfaces.Add(value, red, green, blue, opacity);
  this->Modified();
  this->Impl->IsosurfaceTime = this->GetMTime();
}

void vtkBarycentricShellMapper::RemoveAllIsosurfaces()
{
  if (this->Impl->Isosurfaces.Clear())
  {
    this->Modified();
    this->Impl->IsosurfaceTime = this->GetMTime();
  }
}

int vtkBarycentricShellMapper::GetNumberOfIsosurfaces()
{
  return this->Impl->Isosurfaces.Size();
}

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

vtkImageData* vtkBarycentricShellMapper::GetFloatImage()
{
  return this->Impl->FloatImage;
}

int vtkBarycentricShellMapper::GetNumberOfShells()
{
  return this->Impl->Shells;
}
int vtkBarycentricShellMapper::GetNumberOfDrawnIsosurfaceLayers()
{
  return this->Impl->IsosurfaceLayers;
}
int vtkBarycentricShellMapper::GetNumberOfSkippedShells()
{
  return this->Impl->SkippedShells;
}
vtkIdType vtkBarycentricShellMapper::GetNumberOfDrawnTetrahedra()
{
  return this->Impl->DrawnTetrahedra;
}
double vtkBarycentricShellMapper::GetLastSampleDistance()
{
  return this->Impl->LastSampleDistance;
}
int vtkBarycentricShellMapper::GetNumberOfSegmentTableBuilds()
{
  return this->Impl->SegmentTableBuilds;
}
int vtkBarycentricShellMapper::GetNumberOfSorts()
{
  return this->Impl->Order.Sorts;
}
int vtkBarycentricShellMapper::GetNumberOfGradientComputations()
{
  return this->Impl->Gradients.Computations;
}
int vtkBarycentricShellMapper::GetNumberOfMeshBuilds()
{
  return this->Impl->Mesh.Builds;
}
int vtkBarycentricShellMapper::GetNumberOfPointRefreshes()
{
  return this->Impl->Mesh.PointRefreshes;
}
vtkIdType vtkBarycentricShellMapper::GetMeshMemoryInBytes()
{
  const Internals& impl = *this->Impl;
  std::size_t bytes = sizeof(std::uint32_t) * impl.Mesh.TetrahedronPoints.size() +
    sizeof(float) * impl.Mesh.PointData.size() +
    sizeof(std::uint32_t) * (impl.ShellCells.size() + impl.IsosurfaceCells.size() + impl.Order.Order.size());
  if (impl.GradientsOnGpu)
    bytes += sizeof(float) * impl.Gradients.Values.size();
  return static_cast<vtkIdType>(bytes);
}

void vtkBarycentricShellMapper::ReleaseGraphicsResources(vtkWindow*)
{
  this->Impl->ReleaseGraphics();
}

void vtkBarycentricShellMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderMode: " << (this->RenderMode == SHELLS ? "Shells" : "CellProjection") << "\n";
  os << indent << "ProjectionRoute: " << (this->ProjectionRoute == VERTEX_PULLING ? "VertexPulling" : "GeometryShader") << "\n";
  os << indent << "SampleDistance: " << this->SampleDistance << "\n";
  os << indent << "AutomaticSamplesAcross: " << this->AutomaticSamplesAcross << "\n";
  os << indent << "SlicesPerShell: " << this->SlicesPerShell << "\n";
  os << indent << "SegmentIntegration: "
     << (this->SegmentIntegration == AUTOMATIC ? "Automatic" : this->SegmentIntegration == TABLE ? "Table" : "Exact")
     << "\n";
  os << indent << "OpacityThreshold: " << this->OpacityThreshold << "\n";
  os << indent << "IsosurfaceLayers: " << this->IsosurfaceLayers << "\n";
  os << indent << "GradientMode: " << (this->GradientMode == VERTEX_GRADIENTS ? "VertexGradients" : "CellGradients")
     << "\n";
  os << indent << "Isosurfaces: " << this->Impl->Isosurfaces.Size() << "\n";
  os << indent << "GradientArrayName: " << (this->GradientArrayName ? this->GradientArrayName : "(none)") << "\n";
  os << indent << "SkipInvisibleCells: " << this->SkipInvisibleCells << "\n";
  os << indent << "KeepFloatImage: " << this->KeepFloatImage << "\n";
}

void vtkBarycentricShellMapper::Render(vtkRenderer* renderer, vtkVolume* volume)
{
  Internals& impl = *this->Impl;
  impl.Shells = impl.SkippedShells = impl.IsosurfaceLayers = 0;
  impl.DrawnTetrahedra = 0;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  vtkUnstructuredGridBase* input = this->GetInput();
  if (!window || !volume || !volume->GetProperty())
  {
    vtkErrorMacro("needs an OpenGL render window and a volume with a property");
    return;
  }
  if (!input)
  {
    vtkErrorMacro("no input");
    return;
  }
  if (input->GetNumberOfCells() == 0 || input->GetNumberOfPoints() == 0)
  {
    return; // an empty grid draws nothing
  }

  // ---- A bound image: sampled through the points' texture coordinates instead of a point scalar.
  vtkImageData* image = impl.TextureImage;
  vtkDataArray* textureCoordinates = image ? input->GetPointData()->GetTCoords() : nullptr;
  vtkDataArray* imageScalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (image && (!textureCoordinates || textureCoordinates->GetNumberOfComponents() != 3 || !imageScalars))
  {
    vtkErrorMacro("a texture image needs point scalars, and the input 3-component point texture coordinates");
    return;
  }
  const bool textured = image != nullptr;

  // ---- The mesh: rebuilt when the cells or the scalar changed, positions only when the points moved.
  int cellFlag = 0;
  vtkDataArray* inputScalars = uvvtk::MapperScalars(this, input, cellFlag);
  if (textured && (!inputScalars || cellFlag != 0))
  {
    inputScalars = textureCoordinates; // the mesh's own scalar is not drawn: any point array will do
    cellFlag = 0;
  }
  if (!inputScalars)
  {
    vtkErrorMacro("the input has no point scalar to render (set one, or select an array with SelectScalarArray)");
    return;
  }
  if (cellFlag != 0)
  {
    vtkErrorMacro("cell scalars are not supported: convert them to point data (vtkCellDataToPointData)");
    return;
  }
  uvvtk::TetrahedralMesh::Change change;
  const std::string error = impl.Mesh.Update(
    input, inputScalars,
    [this](vtkDataSet* split) {
      int flag = 0;
      return uvvtk::MapperScalars(this, split, flag);
    },
    [this](double progress) { this->UpdateProgress(progress); }, change);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return;
  }
  if (change == uvvtk::TetrahedralMesh::Change::All)
  {
    impl.MeshOnGpu = false;
    for (const std::string& warning : impl.Warned.New(impl.Mesh, input->GetNumberOfCells()))
      vtkWarningMacro(<< warning);
  }
  if (change == uvvtk::TetrahedralMesh::Change::Points)
  {
    impl.PointsOnGpu = false;
  }
  if (change != uvvtk::TetrahedralMesh::Change::Nothing)
  {
    // Vertex order with a positive orientation, for the pulling route's culling; moving points can
    // turn a tetrahedron inside out, so this is redone (and re-uploaded only if it changed).
    std::vector<std::uint32_t> oriented = impl.Mesh.TetrahedronPoints;
    const std::vector<float>& points = impl.Mesh.PointData;
    vtkSMPTools::For(0, static_cast<vtkIdType>(impl.Mesh.Size()), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType t = begin; t < end; ++t)
      {
        glm::vec3 v[4];
        for (int k = 0; k < 4; ++k)
          v[k] = glm::make_vec3(&points[4 * oriented[4 * t + k]]);
        if (glm::determinant(glm::mat3(v[1] - v[0], v[2] - v[0], v[3] - v[0])) < 0.0f)
          std::swap(oriented[4 * t + 1], oriented[4 * t + 2]);
      }
    });
    if (oriented != impl.OrientedPoints)
    {
      impl.OrientedPoints.swap(oriented);
      impl.MeshOnGpu = false;
    }
  }
  if (impl.Mesh.Size() == 0)
  {
    return;
  }

  // ---- Transfer function and isosurfaces, normalised like the scalar.
  vtkVolumeProperty* property = volume->GetProperty();
  double scalarOffset = impl.Mesh.ScalarOffset, scalarScale = impl.Mesh.ScalarScale;
  if (textured)
  {
    // The image's values normalised by its own range (uploaded that way below).
    double range[2];
    imageScalars->GetRange(range, 0);
    scalarOffset = range[0];
    scalarScale = range[1] > range[0] ? 1.0 / (range[1] - range[0]) : 1.0;
  }
  if (impl.TransferFunction.Update(property, scalarOffset, scalarScale))
  {
    impl.TransferFunctionOnGpu = false;
    impl.UploadedIsosurfaceTime = 0; // isovalues are normalised the same way
  }
  if (impl.Nodes.empty())
  {
    vtkErrorMacro("the volume property has no scalar opacity function");
    return;
  }
  std::vector<uv::Isosurface> drawnIsosurfaces = impl.Isosurfaces.Drawn(scalarOffset, scalarScale);
  if (textured && (!drawnIsosurfaces.empty() || this->RenderMode == CELL_PROJECTION))
  {
    // The field inside a cell is the image's, not linear: no closed-form crossings or whole segments.
    if (!impl.WarnedTexture)
    {
      vtkWarningMacro("with a texture image only the shells are drawn: isosurfaces and cell projection "
                      "need the mesh's own linear scalar");
      impl.WarnedTexture = true;
    }
    drawnIsosurfaces.clear();
  }
  std::vector<double> isovalues;
  for (const uv::Isosurface& s : drawnIsosurfaces)
    isovalues.push_back(s.Value);
  // With an image, a cell's range is not its vertices' range: none is skipped.
  impl.UpdateLists(this->SkipInvisibleCells && !textured, isovalues);
  const bool cellProjection = this->RenderMode == CELL_PROJECTION && !textured;
  if (impl.DrawnCells.empty())
  {
    return;
  }

  // ---- Camera, in the recentred model frame.
  vtkCamera* camera = renderer->GetActiveCamera();
  int width, height, originX, originY;
  renderer->GetTiledSizeAndOrigin(&width, &height, &originX, &originY);
  if (width < 1 || height < 1)
  {
    return;
  }
  const double aspect = static_cast<double>(width) / height;
  const glm::dmat4 modelToWorld =
    uvgl::ToGlm(volume->GetMatrix()) * glm::translate(glm::dmat4(1.0), impl.Mesh.Center);
  const glm::dmat4 worldToEye = uvgl::ToGlm(camera->GetModelViewTransformMatrix());
  const glm::dmat4 eyeToClip = uvgl::ToGlm(camera->GetProjectionTransformMatrix(aspect, -1, 1));
  const glm::dmat4 modelToEye = worldToEye * modelToWorld;
  const bool parallel = camera->GetParallelProjection() != 0;

  // ---- Gradients, for isosurfaces (both modes) and shading (cell projection).
  const bool shade = cellProjection && property->GetShade() != 0;
  const bool lit = shade || !isovalues.empty();
  const bool needGradients = lit && this->GradientMode == VERTEX_GRADIENTS;
  if (needGradients)
  {
    bool ignoredArray = false;
    if (impl.Gradients.Update(impl.Mesh, this->GradientArrayName, ignoredArray))
      impl.GradientsOnGpu = false;
    if (ignoredArray)
      vtkWarningMacro("the gradient array '" << this->GradientArrayName << "' does not have 3 components; computing gradients");
  }

  // ---- Shells (front to back) and the volume cells overlapping each, or the back-to-front order.
  const int slicesPerShell = this->SlicesPerShell;
  const int targets = (slicesPerShell + 1 + 3) / 4;
  double sampleDistance = this->SampleDistance;
  if (!(sampleDistance > 0.0))
  {
    // From the bounds as of the last full build (or a change of the volume's matrix): a deforming
    // mesh keeps its sample distance, and so its segment table.
    const std::string key =
      std::to_string(volume->GetMatrix()->GetMTime()) + ":" + std::to_string(this->AutomaticSamplesAcross);
    if (change == uvvtk::TetrahedralMesh::Change::All || key != impl.AutomaticDistanceKey || !(impl.AutomaticDistance > 0.0))
    {
      double bounds[6];
      volume->GetBounds(bounds);
      const double diagonal = std::sqrt(std::pow(bounds[1] - bounds[0], 2) + std::pow(bounds[3] - bounds[2], 2) +
        std::pow(bounds[5] - bounds[4], 2));
      impl.AutomaticDistance = diagonal / this->AutomaticSamplesAcross;
      impl.AutomaticDistanceKey = key;
    }
    sampleDistance = impl.AutomaticDistance;
  }
  double firstDistance = 0.0;
  int shellCount = 0;
  if (!cellProjection)
  {
    // Eye-space positions once per point, then each cell's distance range.
    const std::size_t pointCount = impl.Mesh.PointData.size() / 4;
    impl.EyePoints.resize(pointCount);
    const glm::mat4 toEye(modelToEye);
    vtkSMPTools::For(0, static_cast<vtkIdType>(pointCount), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType p = begin; p < end; ++p)
      {
        const float* x = &impl.Mesh.PointData[4 * p];
        impl.EyePoints[p] = glm::vec3(toEye * glm::vec4(x[0], x[1], x[2], 1.0f));
      }
    });
    // Each point's place on screen (normalised device coordinates), for each shell's rectangle; a
    // point not in front of the eye makes its cells' rectangles the whole screen.
    const glm::mat4 toClip(eyeToClip);
    impl.ScreenPoints.resize(pointCount);
    vtkSMPTools::For(0, static_cast<vtkIdType>(pointCount), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType p = begin; p < end; ++p)
      {
        const glm::vec4 clip = toClip * glm::vec4(impl.EyePoints[p], 1.0f);
        impl.ScreenPoints[p] = clip.w > 1e-6f ? glm::vec2(clip) / clip.w : glm::vec2(std::numeric_limits<float>::quiet_NaN());
      }
    });
    auto ranges = [&](const std::vector<std::uint32_t>& cells, std::vector<float>& low, std::vector<float>& high) {
      low.resize(cells.size());
      high.resize(cells.size());
      vtkSMPTools::For(0, static_cast<vtkIdType>(cells.size()), [&](vtkIdType begin, vtkIdType end) {
        std::array<glm::vec3, 4> v;
        for (vtkIdType i = begin; i < end; ++i)
        {
          for (int k = 0; k < 4; ++k)
            v[k] = impl.EyePoints[impl.Mesh.TetrahedronPoints[4 * cells[i] + k]];
          DistanceRange(v, parallel, low[i], high[i]);
        }
      });
    };
    std::vector<float> isoLow, isoHigh;
    ranges(impl.VolumeCells, impl.Low, impl.High);
    ranges(impl.IsosurfaceCells, isoLow, isoHigh);
    float nearest = std::numeric_limits<float>::infinity(), farthest = -nearest;
    for (const auto* range : { &impl.Low, &isoLow })
      for (float d : *range)
        nearest = std::min(nearest, d);
    for (const auto* range : { &impl.High, &isoHigh })
      for (float d : *range)
        farthest = std::max(farthest, d);
    if (!(farthest >= nearest))
    {
      return;
    }
    double thickness = slicesPerShell * sampleDistance;
    if ((farthest - nearest) / thickness > MaximumShells - 1)
    {
      thickness = (farthest - nearest) / (MaximumShells - 1);
      sampleDistance = thickness / slicesPerShell;
      if (!impl.WarnedShells)
      {
        vtkWarningMacro("the sample distance would need more than " << MaximumShells
                                                                    << " shells here: widened to " << sampleDistance);
        impl.WarnedShells = true;
      }
    }
    // Samples at whole multiples of the sample distance from the eye: the same places whatever the
    // nearest cell, so frames (and ranks of a parallel render, each with its own piece) agree.
    firstDistance = std::floor(nearest / sampleDistance) * sampleDistance;
    shellCount = std::max(1, static_cast<int>(std::ceil((farthest - firstDistance) / thickness)));
    auto shellOf = [&](float d) {
      return std::clamp(static_cast<int>(std::floor((d - firstDistance) / thickness)), 0, shellCount - 1);
    };
    // A cell goes into every shell its range overlaps (slack of a thousandth of a shell at the ends).
    const float slack = static_cast<float>(1e-3 * thickness);
    impl.ShellOffsets.assign(shellCount + 1, 0);
    for (std::size_t i = 0; i < impl.VolumeCells.size(); ++i)
      for (int s = shellOf(impl.Low[i] - slack); s <= shellOf(impl.High[i] + slack); ++s)
        ++impl.ShellOffsets[s + 1];
    for (int s = 0; s < shellCount; ++s)
      impl.ShellOffsets[s + 1] += impl.ShellOffsets[s];
    impl.ShellCells.resize(impl.ShellOffsets[shellCount]);
    std::vector<std::uint32_t> fill(impl.ShellOffsets.begin(), impl.ShellOffsets.end() - 1);
    // Each shell's screen rectangle: the union of its cells' (its full-screen passes cover no more).
    const glm::dvec4 empty(1.0, 1.0, -1.0, -1.0), whole(-1.0, -1.0, 1.0, 1.0);
    impl.ShellScreen.assign(shellCount, empty);
    auto addScreen = [&](std::uint32_t cell, int shell) {
      glm::dvec4& box = impl.ShellScreen[shell];
      for (int k = 0; k < 4; ++k)
      {
        const glm::vec2 p = impl.ScreenPoints[impl.Mesh.TetrahedronPoints[4 * cell + k]];
        if (!(p.x == p.x))
        {
          box = whole; // a vertex behind the eye
          return;
        }
        box = glm::dvec4(std::min<double>(box.x, p.x), std::min<double>(box.y, p.y), std::max<double>(box.z, p.x),
          std::max<double>(box.w, p.y));
      }
    };
    for (std::size_t i = 0; i < impl.VolumeCells.size(); ++i)
      for (int s = shellOf(impl.Low[i] - slack); s <= shellOf(impl.High[i] + slack); ++s)
      {
        impl.ShellCells[fill[s]++] = impl.VolumeCells[i];
        addScreen(impl.VolumeCells[i], s);
      }
    impl.ShellHasIsosurface.assign(shellCount, 0);
    for (std::size_t i = 0; i < impl.IsosurfaceCells.size(); ++i)
      for (int s = shellOf(isoLow[i] - slack); s <= shellOf(isoHigh[i] + slack); ++s)
      {
        impl.ShellHasIsosurface[s] = 1;
        addScreen(impl.IsosurfaceCells[i], s);
      }
  }
  else
  {
    // Back to front by centroid distance (as vtkPreIntegratedTetrahedraMapper), redone only when the
    // view, the points or the drawn cells changed.
    const glm::dmat4 eyeToModel = glm::inverse(modelToEye);
    const glm::dvec3 eye(eyeToModel * glm::dvec4(0, 0, 0, 1));
    const glm::dvec3 direction(glm::normalize(glm::dvec3(eyeToModel * glm::dvec4(0, 0, -1, 0))));
    if (impl.Order.Update(impl.Mesh, impl.DrawnCells, eye, direction, parallel))
      impl.OrderUploaded = false;
  }
  impl.LastSampleDistance = sampleDistance;

  // ---- GPU resources.
  if (impl.Context != window)
  {
    impl.ReleaseGraphics();
    impl.Context = window;
  }
  window->MakeCurrent();
  vtkOpenGLClearErrorMacro();
  vtkOpenGLState* state = window->GetState();
  if (!impl.MeshOnGpu)
  {
    uvgl::UploadBufferTexture(window, impl.TetrahedronBuffer, impl.TetrahedronTexture, impl.OrientedPoints, 4);
    impl.MeshOnGpu = true;
    impl.PointsOnGpu = false;
  }
  if (!impl.PointsOnGpu)
  {
    // A deforming mesh pays this upload and nothing else.
    uvgl::UploadBufferTexture(window, impl.PointBuffer, impl.PointTexture, impl.Mesh.PointData, 4);
    impl.PointsOnGpu = true;
  }
  if (needGradients && !impl.GradientsOnGpu)
  {
    uvgl::UploadBufferTexture(window, impl.GradientBuffer, impl.GradientTexture, impl.Gradients.Values, 4);
    impl.GradientsOnGpu = true;
  }
  if (!impl.TransferFunctionOnGpu)
  {
    uvgl::UploadTransferFunctionTexture(impl.TransferTexture, window, impl.Nodes);
    impl.TransferFunctionOnGpu = true;
  }
  if (impl.UploadedIsosurfaceTime != impl.IsosurfaceTime || !impl.IsosurfaceTexture->GetHandle())
  {
    uvgl::UploadIsosurfaces(impl.IsosurfaceTexture, window, drawnIsosurfaces);
    impl.UploadedIsosurfaceTime = impl.IsosurfaceTime;
  }
  uvgl::EnsurePsiTexture(impl.PsiTexture, window);
  if (textured)
  {
    const auto id = [](const void* p) { return std::to_string(reinterpret_cast<std::uintptr_t>(p)); };
    const std::string imageKey = id(image) + ":" + std::to_string(image->GetMTime()) + ":" + id(imageScalars) + ":" +
      std::to_string(imageScalars->GetMTime());
    if (imageKey != impl.TextureKey)
    {
      // Normalised to [0, 1] by the image's range, as the transfer function is; a float texture read
      // trilinearly.
      int dimensions[3];
      image->GetDimensions(dimensions);
      const vtkIdType count = image->GetNumberOfPoints();
      std::vector<float> values(count);
      vtkSMPTools::For(0, count, [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType p = begin; p < end; ++p)
        {
          const double value = (imageScalars->GetComponent(p, 0) - scalarOffset) * scalarScale;
          values[p] = std::isfinite(value) ? static_cast<float>(value) : 0.0f;
        }
      });
      impl.VolumeTexture->SetContext(window);
      impl.VolumeTexture->SetMinificationFilter(vtkTextureObject::Linear);
      impl.VolumeTexture->SetMagnificationFilter(vtkTextureObject::Linear);
      impl.VolumeTexture->SetWrapS(vtkTextureObject::ClampToEdge);
      impl.VolumeTexture->SetWrapT(vtkTextureObject::ClampToEdge);
      impl.VolumeTexture->SetWrapR(vtkTextureObject::ClampToEdge);
      impl.VolumeTexture->Create3DFromRaw(dimensions[0], dimensions[1], dimensions[2], 1, VTK_FLOAT, values.data());
      impl.TextureKey = imageKey;
    }
    vtkDataArray* meshCoordinates = impl.Mesh.Tetrahedra->GetPointData()->GetTCoords();
    if (!meshCoordinates)
      meshCoordinates = textureCoordinates; // the input itself when nothing was split
    const std::string coordinatesKey = impl.Mesh.Key() + "|" + id(meshCoordinates) + ":" +
      std::to_string(meshCoordinates->GetMTime());
    if (coordinatesKey != impl.TextureCoordinatesKey)
    {
      const vtkIdType count = meshCoordinates->GetNumberOfTuples();
      std::vector<float> coordinates(4 * count, 0.0f);
      vtkSMPTools::For(0, count, [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType p = begin; p < end; ++p)
          for (int d = 0; d < 3; ++d)
            coordinates[4 * p + d] = static_cast<float>(meshCoordinates->GetComponent(p, d));
      });
      uvgl::UploadBufferTexture(window, impl.TextureCoordinateBuffer, impl.TextureCoordinateTexture, coordinates, 4);
      impl.TextureCoordinatesKey = coordinatesKey;
    }
  }
  // Shells integrate segments of one length: a table lookup each, where the transfer function is
  // smooth enough for the table's bilinear reads (or as the user chose).
  const bool segmentTable = !cellProjection &&
    (this->SegmentIntegration == TABLE ||
      (this->SegmentIntegration == AUTOMATIC &&
        uv::NarrowestNodeGap(impl.Nodes) * (SegmentTableSize - 1) >= TableTexelsPerNodeGap));
  if (segmentTable)
  {
    // Exact comparisons: a key printed with six decimals read 0.000000 for every sample distance of a
    // mesh micrometres across, and the table was never rebuilt for a new distance.
    if (!impl.SegmentTableTexture->GetHandle() || sampleDistance != impl.SegmentTableLength ||
      impl.Nodes != impl.SegmentTableNodes)
    {
      const uv::TransferFunction tf(impl.Nodes);
      std::vector<float> texels = uv::SegmentTable(tf, sampleDistance, SegmentTableSize,
        [](int count, const auto& function) {
          vtkSMPTools::For(0, count, 1, [&](vtkIdType begin, vtkIdType end) {
            for (vtkIdType row = begin; row < end; ++row)
              function(static_cast<int>(row));
          });
        });
      impl.SegmentTableTexture->SetContext(window);
      impl.SegmentTableTexture->SetMinificationFilter(vtkTextureObject::Linear);
      impl.SegmentTableTexture->SetMagnificationFilter(vtkTextureObject::Linear);
      impl.SegmentTableTexture->SetWrapS(vtkTextureObject::ClampToEdge);
      impl.SegmentTableTexture->SetWrapT(vtkTextureObject::ClampToEdge);
      impl.SegmentTableTexture->Create2DFromRaw(SegmentTableSize, SegmentTableSize, 4, VTK_FLOAT, texels.data());
      impl.SegmentTableLength = sampleDistance;
      impl.SegmentTableNodes = impl.Nodes;
      ++impl.SegmentTableBuilds;
    }
  }
  // Cell lists as buffer textures: both routes read a list entry by vertex id.
  auto uploadList = [window](vtkOpenGLBufferObject* buffer, vtkTextureObject* texture,
                      const std::vector<std::uint32_t>& cells) {
    uvgl::UploadBufferTexture(window, buffer, texture, cells, 1);
  };
  if (cellProjection && !impl.OrderUploaded)
  {
    uploadList(impl.OrderBuffer, impl.OrderList, impl.Order.Order);
    impl.OrderUploaded = true;
  }
  else
  {
    if (!impl.ShellCells.empty())
      uploadList(impl.ShellBuffer, impl.ShellList, impl.ShellCells);
    if (!impl.IsosurfaceCellsOnGpu && !impl.IsosurfaceCells.empty())
    {
      uploadList(impl.IsosurfaceCellBuffer, impl.IsosurfaceList, impl.IsosurfaceCells);
      impl.IsosurfaceCellsOnGpu = true;
    }
  }
  const bool pulling = this->ProjectionRoute == VERTEX_PULLING;
  if (pulling && !impl.FaceIndicesOnGpu)
  {
    impl.FaceIndexBuffer->Upload(FaceIndexPattern(PullChunk), vtkOpenGLBufferObject::ElementArrayBuffer);
    impl.FaceIndicesOnGpu = true;
  }
  const int layers = this->IsosurfaceLayers;
  impl.EnsureImages(window, width, height, targets, layers);

  // ---- The depth of what VTK drew so far (opaque geometry), from the current framebuffer.
  if (!uvgl::CopySceneDepth(impl.SceneDepth, originX, originY, width, height) && !impl.WarnedMultisample)
  {
    vtkWarningMacro("multisampled render window: opaque geometry does not clip the volume (set MultiSamples to 0)");
    impl.WarnedMultisample = true;
  }

  vtkOpenGLShaderCache* cache = window->GetShaderCache();
  // ---- Opaque geometry's distance per pixel, once; none at all (the common case of a volume alone)
  // spares every fragment the read.
  bool opaqueGeometry = false;
  {
    vtkShaderProgram* opaque = cache->ReadyShaderProgram(uvFullScreenTriangleVS, uvBarycentricOpaqueDistanceFS, "");
    if (!opaque)
    {
      vtkErrorMacro("the opaque-distance shaders failed to compile or link");
      return;
    }
    vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglViewport viewport(state);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_SCISSOR_TEST);
    impl.OpaqueFramebuffer->SaveCurrentBindingsAndBuffers();
    impl.OpaqueFramebuffer->Bind();
    impl.OpaqueFramebuffer->ActivateDrawBuffers(1);
    state->vtkglViewport(0, 0, width, height);
    const float none[4] = { 3.0e38f, 0.0f, 0.0f, 0.0f };
    glClearBufferfv(GL_COLOR, 0, none);
    impl.SceneDepth->Activate();
    opaque->SetUniformi("opaqueDepth", impl.SceneDepth->GetTextureUnit());
    const glm::mat4 clipToEye(glm::inverse(eyeToClip));
    opaque->SetUniformMatrix4x4("clipToEye", const_cast<float*>(glm::value_ptr(clipToEye)));
    const float size[2] = { static_cast<float>(width), static_cast<float>(height) };
    opaque->SetUniform2f("viewportSize", size);
    opaque->SetUniformi("parallelProjection", parallel ? 1 : 0);
    GLuint query = 0;
    glGenQueries(1, &query);
    glBeginQuery(GL_SAMPLES_PASSED, query);
    impl.NoAttributes->Bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    impl.NoAttributes->Release();
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint samples = 0;
    glGetQueryObjectuiv(query, GL_QUERY_RESULT, &samples);
    glDeleteQueries(1, &query);
    opaqueGeometry = samples > 0;
    impl.SceneDepth->Deactivate();
    impl.OpaqueFramebuffer->RestorePreviousBindingsAndBuffers();
  }

  // ---- Programs.
  std::string defines = uvgl::TransferFunctionDefines(impl.Nodes) + "#define UV_SLICES " +
    std::to_string(slicesPerShell + 1) + "\n#define UV_TARGETS " + std::to_string(targets) +
    "\n#define UV_MAX_LAYERS " + std::to_string(layers) + "\n";
  if (needGradients)
    defines += "#define UV_GRADIENTS\n";
  else if (lit)
    defines += "#define UV_CELL_GRADIENTS\n";
  if (segmentTable)
    defines += "#define UV_SEGMENT_TABLE\n";
  if (opaqueGeometry)
    defines += "#define UV_OPAQUE_GEOMETRY\n";
  if (textured)
    defines += "#define UV_TEXTURE\n";
  const std::initializer_list<std::pair<const char*, const char*>> libraries = {
    { "//UV::BarycentricRay", uvBarycentricRayLib }, { "//UV::TransferFunction", uvTransferFunctionLib },
    { "//UV::Phong", uvPhongLib }, { "//UV::SegmentIntegration", uvSegmentIntegrationLib }
  };
  const std::initializer_list<std::pair<const char*, const char*>> tetrahedron = {
    { "//UV::BarycentricTetrahedron", uvBarycentricTetrahedronLib }
  };
  const std::string cellVertex =
    uvgl::ShaderSource(pulling ? uvBarycentricPullVS : uvBarycentricCellListVS, defines, tetrahedron);
  const std::string cellGeometry = pulling ? std::string() : uvgl::ShaderSource(uvBarycentricShellGS, defines, tetrahedron);
  const std::string screenVertex = uvgl::ShaderSource(uvFullScreenTriangleVS, defines);
  auto ready = [&](const std::string& vertex, const char* fragment, const std::string& geometry) {
    const std::string fragmentSource = uvgl::ShaderSource(fragment, defines, libraries);
    return cache->ReadyShaderProgram(vertex.c_str(), fragmentSource.c_str(), geometry.c_str());
  };
  const glm::mat3 normals(glm::transpose(glm::inverse(glm::dmat3(modelToEye))));
  // Uniforms every program over the tetrahedra takes (geometry stage and uvBarycentricRayLib).
  auto setCellUniforms = [&](vtkShaderProgram* program) {
    const glm::mat4 toEye(modelToEye), toClip(eyeToClip);
    program->SetUniformMatrix4x4("modelToEye", const_cast<float*>(glm::value_ptr(toEye)));
    program->SetUniformMatrix4x4("eyeToClip", const_cast<float*>(glm::value_ptr(toClip)));
    program->SetUniformi("parallelProjection", parallel ? 1 : 0);
    program->SetUniformi("tetrahedronPoints", impl.TetrahedronTexture->GetTextureUnit());
    program->SetUniformi("pointData", impl.PointTexture->GetTextureUnit());
    if (opaqueGeometry)
      program->SetUniformi("opaqueDistances", impl.OpaqueDistances->GetTextureUnit());
    program->SetUniformf("insideTolerance", InsideTolerance);
    if (textured)
    {
      int dimensions[3];
      image->GetDimensions(dimensions);
      const float size[3] = { static_cast<float>(dimensions[0]), static_cast<float>(dimensions[1]),
        static_cast<float>(dimensions[2]) };
      program->SetUniformi("pointTextureCoordinates", impl.TextureCoordinateTexture->GetTextureUnit());
      program->SetUniformi("volumeTexture", impl.VolumeTexture->GetTextureUnit());
      program->SetUniform3f("volumeTextureSize", size);
    }
    if (needGradients)
    {
      program->SetUniformi("pointGradients", impl.GradientTexture->GetTextureUnit());
      program->SetUniformMatrix3x3("modelToEyeNormals", const_cast<float*>(glm::value_ptr(normals)));
    }
  };
  auto setIntegrationUniforms = [&](vtkShaderProgram* program, int isosurfaceCount) {
    uvgl::SetTransferFunctionUniforms(program, impl.Nodes, impl.TransferTexture, impl.PsiTexture);
    program->SetUniformi("isosurfaces", impl.IsosurfaceTexture->GetTextureUnit());
    program->SetUniformi("isosurfaceCount", isosurfaceCount);
    program->SetUniformi("averageScalar", 0);
    program->SetUniformi("shadeVolume", shade ? 1 : 0);
    uvgl::SetPhongUniforms(program, renderer, property, worldToEye);
  };

  // Draws the tetrahedra at places [first, first + count) of a cell list, by the chosen route.
  auto drawCells = [&](vtkShaderProgram* program, vtkTextureObject* list, std::size_t first, std::size_t count) {
    program->SetUniformi("cellList", list->GetTextureUnit());
    // The list position of the draw's first tetrahedron rides in a uniform, so one index pattern
    // (PullChunk tetrahedra) serves every chunk.
    if (!pulling)
    {
      program->SetUniformi("listOffset", static_cast<int>(first));
      glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(count));
      return;
    }
    // Culling only here: the full-screen passes' triangle is a front face.
    state->vtkglEnable(GL_CULL_FACE);
    state->vtkglCullFace(GL_FRONT); // back faces: each ray leaves a tetrahedron through one
    for (std::size_t done = 0; done < count; done += PullChunk)
    {
      const std::size_t chunk = std::min<std::size_t>(PullChunk, count - done);
      program->SetUniformi("listOffset", static_cast<int>(first + done));
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(12 * chunk), GL_UNSIGNED_INT, nullptr);
    }
    state->vtkglCullFace(GL_BACK);
    state->vtkglDisable(GL_CULL_FACE);
  };

  // ---- Render into the float image.
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunctionSaver(state);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  vtkOpenGLState::ScopedglDepthFunc depthFunctionSaver(state);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(state);
  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  vtkOpenGLState::ScopedglScissor scissorBoxSaver(state);
  vtkOpenGLState::ScopedglClearColor clearColorSaver(state);

  std::vector<vtkTextureObject*> common = { impl.TetrahedronTexture, impl.PointTexture, impl.TransferTexture,
    impl.IsosurfaceTexture, impl.PsiTexture, impl.OpaqueDistances };
  for (vtkTextureObject* list : { impl.ShellList.Get(), impl.IsosurfaceList.Get(), impl.OrderList.Get() })
  {
    if (list->GetHandle())
      common.push_back(list);
  }
  if (needGradients)
    common.push_back(impl.GradientTexture);
  if (textured)
  {
    common.push_back(impl.VolumeTexture);
    common.push_back(impl.TextureCoordinateTexture);
  }
  for (vtkTextureObject* texture : common)
    texture->Activate();

  impl.AccumulationFramebuffer->SaveCurrentBindingsAndBuffers();
  impl.AccumulationFramebuffer->Bind();
  impl.AccumulationFramebuffer->ActivateDrawBuffers(1);
  state->vtkglViewport(0, 0, width, height);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT); // the image, and the mask: nothing opaque yet
  bool failed = false;
  impl.NoAttributes->Bind();
  state->vtkglDisable(GL_CULL_FACE);
  if (pulling)
  {
    impl.FaceIndexBuffer->Bind();
  }
  // The passes below touch only the pixels the volume's bounds can cover (the full-screen ones too).
  std::array<int, 4> volumeRectangle;
  {
    double bounds[6];
    volume->GetBounds(bounds);
    volumeRectangle = ScreenRectangle(bounds, eyeToClip * worldToEye, width, height);
    state->vtkglScissor(volumeRectangle[0], volumeRectangle[1], volumeRectangle[2], volumeRectangle[3]);
    state->vtkglEnable(GL_SCISSOR_TEST);
  }

  if (cellProjection)
  {
    vtkShaderProgram* program = ready(cellVertex, uvBarycentricCellProjectionFS, cellGeometry);
    if (program)
    {
      setCellUniforms(program);
      setIntegrationUniforms(program, static_cast<int>(isovalues.size()));
      state->vtkglDisable(GL_DEPTH_TEST);
      state->vtkglDepthMask(GL_FALSE);
      state->vtkglEnable(GL_BLEND);
      state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
      drawCells(program, impl.OrderList, 0, impl.Order.Order.size());
      impl.DrawnTetrahedra = static_cast<vtkIdType>(impl.Order.Order.size());
    }
    failed = !program;
  }
  else
  {
    // Isosurfaces first: each pixel's crossings, nearest first, one layer per pass (depth peeling),
    // until a pass finds none or IsosurfaceLayers are drawn.
    const bool isosurfaces = !impl.IsosurfaceCells.empty();
    int drawnLayers = 0;
    if (isosurfaces)
    {
      vtkShaderProgram* program = ready(cellVertex, uvBarycentricShellIsosurfaceFS, cellGeometry);
      failed = !program;
      if (program)
      {
        setCellUniforms(program);
        program->SetUniformi("isosurfaces", impl.IsosurfaceTexture->GetTextureUnit());
        program->SetUniformi("isosurfaceCount", static_cast<int>(isovalues.size()));
        uvgl::SetPhongUniforms(program, renderer, property, worldToEye);
        impl.PreviousLayer->Activate();
        program->SetUniformi("previousLayer", impl.PreviousLayer->GetTextureUnit());
        state->vtkglEnable(GL_DEPTH_TEST);
        state->vtkglDepthFunc(GL_LESS);
        state->vtkglDisable(GL_BLEND);
        GLuint query = 0;
        glGenQueries(1, &query);
        const float noColor[4] = { 0.0f, 0.0f, 0.0f, 0.0f }, noHit[4] = { 3.0e38f, 0.0f, 0.0f, 0.0f };
        for (int layer = 0; layer < layers; ++layer)
        {
          impl.IsosurfaceFramebuffer->Bind();
          // Removed first: re-adding the same texture with another layer would keep the old layer.
          impl.IsosurfaceFramebuffer->RemoveColorAttachments(2);
          impl.IsosurfaceFramebuffer->AddColorAttachment(0, impl.IsosurfaceColor, layer);
          impl.IsosurfaceFramebuffer->AddColorAttachment(1, impl.IsosurfaceDistance, layer);
          impl.IsosurfaceFramebuffer->AddDepthAttachment(impl.IsosurfaceDepth);
          impl.IsosurfaceFramebuffer->ActivateDrawBuffers(2);
          glClearBufferfv(GL_COLOR, 0, noColor);
          glClearBufferfv(GL_COLOR, 1, noHit);
          state->vtkglDepthMask(GL_TRUE);
          state->vtkglClear(GL_DEPTH_BUFFER_BIT);
          program->SetUniformi("layer", layer);
          glBeginQuery(GL_SAMPLES_PASSED, query);
          drawCells(program, impl.IsosurfaceList, 0, impl.IsosurfaceCells.size());
          glEndQuery(GL_SAMPLES_PASSED);
          impl.DrawnTetrahedra += static_cast<vtkIdType>(impl.IsosurfaceCells.size());
          GLuint samples = 0;
          glGetQueryObjectuiv(query, GL_QUERY_RESULT, &samples);
          if (samples == 0)
          {
            break; // no pixel has another crossing
          }
          ++drawnLayers;
          if (layer + 1 < layers)
          {
            // The next pass starts beyond this layer's hits.
            impl.IsosurfaceFramebuffer->ActivateReadBuffer(1);
            impl.PreviousLayer->CopyFromFrameBuffer(0, 0, 0, 0, width, height);
          }
        }
        glDeleteQueries(1, &query);
        impl.IsosurfaceLayers = drawnLayers;
        impl.PreviousLayer->Deactivate();
      }
    }
    vtkShaderProgram* slice = failed ? nullptr : ready(cellVertex, uvBarycentricShellSliceFS, cellGeometry);
    vtkShaderProgram* blend = slice ? ready(screenVertex, uvBarycentricShellBlendFS, "") : nullptr;
    vtkShaderProgram* mask = blend ? ready(screenVertex, uvBarycentricShellMaskFS, "") : nullptr;
    failed = !mask;
    if (!failed)
    {
      cache->ReadyShaderProgram(slice); // uniforms go to the bound program
      setCellUniforms(slice);
      slice->SetUniformf("sampleDistance", static_cast<float>(sampleDistance));
      cache->ReadyShaderProgram(blend);
      setIntegrationUniforms(blend, 0); // isosurfaces come from their own pass
      blend->SetUniformf("sampleDistance", static_cast<float>(sampleDistance));
      blend->SetUniformi("isosurfaceLayers", drawnLayers);
      if (segmentTable)
      {
        impl.SegmentTableTexture->Activate();
        blend->SetUniformi("segmentTable", impl.SegmentTableTexture->GetTextureUnit());
        blend->SetUniformf("segmentTableSize", static_cast<float>(SegmentTableSize));
      }
      impl.IsosurfaceColor->Activate();
      impl.IsosurfaceDistance->Activate();
      blend->SetUniformi("isosurfaceColor", impl.IsosurfaceColor->GetTextureUnit());
      blend->SetUniformi("isosurfaceDistance", impl.IsosurfaceDistance->GetTextureUnit());
      const bool terminateEarly = this->OpacityThreshold < 1.0;
      if (terminateEarly)
      {
        cache->ReadyShaderProgram(mask);
        mask->SetUniformf("opacityThreshold", static_cast<float>(this->OpacityThreshold));
      }
      state->vtkglEnable(GL_DEPTH_TEST);
      state->vtkglDepthFunc(GL_LESS);
      for (int s = 0; s < shellCount; ++s)
      {
        const std::uint32_t first = impl.ShellOffsets[s], count = impl.ShellOffsets[s + 1] - first;
        if (count == 0 && !(isosurfaces && impl.ShellHasIsosurface[s]))
        {
          ++impl.SkippedShells; // nothing overlaps it
          continue;
        }
        ++impl.Shells;
        // This shell's passes, clear included, only where its cells are (and the volume is).
        {
          const auto own = PixelRectangle(impl.ShellScreen[s], width, height);
          const int x0 = std::max(own[0], volumeRectangle[0]), y0 = std::max(own[1], volumeRectangle[1]);
          const int x1 = std::min(own[0] + own[2], volumeRectangle[0] + volumeRectangle[2]);
          const int y1 = std::min(own[1] + own[3], volumeRectangle[1] + volumeRectangle[3]);
          state->vtkglScissor(x0, y0, std::max(x1 - x0, 0), std::max(y1 - y0, 0));
        }
        state->vtkglDepthMask(GL_FALSE); // the mask is only read, except by the mask pass
        const float shellStart = static_cast<float>(firstDistance + s * slicesPerShell * sampleDistance);
        // Slices: cleared to "outside", then every overlapping cell's samples, MAX-blended.
        impl.SliceFramebuffer->Bind();
        impl.SliceFramebuffer->ActivateDrawBuffers(static_cast<unsigned int>(targets));
        state->vtkglClear(GL_COLOR_BUFFER_BIT);
        if (count > 0)
        {
          cache->ReadyShaderProgram(slice);
          slice->SetUniformf("shellStart", shellStart);
          state->vtkglEnable(GL_BLEND);
          state->vtkglBlendEquation(GL_MAX);
          drawCells(slice, impl.ShellList, first, count);
          state->vtkglBlendEquation(GL_FUNC_ADD);
          impl.DrawnTetrahedra += count;
        }
        // Blend: the shell's samples integrated, under what nearer shells left.
        impl.AccumulationFramebuffer->Bind();
        impl.AccumulationFramebuffer->ActivateDrawBuffers(1);
        cache->ReadyShaderProgram(blend);
        blend->SetUniformf("shellStart", shellStart);
        for (int t = 0; t < targets; ++t)
        {
          impl.Slices[t]->Activate();
          blend->SetUniformi(("slices" + std::to_string(t)).c_str(), impl.Slices[t]->GetTextureUnit());
        }
        state->vtkglEnable(GL_BLEND);
        state->vtkglBlendFuncSeparate(GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ONE_MINUS_DST_ALPHA, GL_ONE);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        for (int t = 0; t < targets; ++t)
          impl.Slices[t]->Deactivate();
        // Mask: pixels now opaque enough get depth 0, and later shells pass them by.
        if (terminateEarly && s + 1 < shellCount)
        {
          impl.SliceFramebuffer->Bind();
          impl.SliceFramebuffer->ActivateDrawBuffers(static_cast<unsigned int>(targets));
          cache->ReadyShaderProgram(mask);
          impl.Accumulation->Activate();
          mask->SetUniformi("accumulated", impl.Accumulation->GetTextureUnit());
          state->vtkglDisable(GL_BLEND);
          state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
          state->vtkglDepthMask(GL_TRUE);
          state->vtkglDepthFunc(GL_ALWAYS);
          glDrawArrays(GL_TRIANGLES, 0, 3);
          state->vtkglDepthFunc(GL_LESS);
          state->vtkglDepthMask(GL_FALSE);
          state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
          impl.Accumulation->Deactivate();
        }
      }
      impl.IsosurfaceColor->Deactivate();
      impl.IsosurfaceDistance->Deactivate();
      if (segmentTable)
        impl.SegmentTableTexture->Deactivate();
    }
  }
  if (pulling)
  {
    impl.FaceIndexBuffer->Release();
  }
  impl.NoAttributes->Release();
  for (vtkTextureObject* texture : common)
    texture->Deactivate();

  impl.AccumulationFramebuffer->Bind();
  if (this->KeepFloatImage && !failed)
  {
    uvgl::ReadFloatImage(impl.AccumulationFramebuffer, 0, width, height, impl.FloatImage);
  }
  impl.AccumulationFramebuffer->RestorePreviousBindingsAndBuffers();
  if (failed)
  {
    vtkErrorMacro("the barycentric shell shaders failed to compile or link");
    return;
  }

  // ---- Blend the float image into VTK's scene.
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST); // the rectangles above are the image's, not the window's
  if (!uvgl::CompositeIntoScene(window, impl.Accumulation, impl.NoAttributes, originX, originY, width, height))
  {
    vtkErrorMacro("the composite shaders failed to compile or link");
    return;
  }
  vtkOpenGLCheckErrorMacro("failed after rendering the tetrahedra");
}
