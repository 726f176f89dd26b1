#include "vtkHexahedralRayCastMapper.h"

#include "uvBilinearFaceLib.h"
#include "uvFullScreenTriangleVS.h"
#include "uvHexahedralEntryFS.h"
#include "uvHexahedralEntryVS.h"
#include "uvHexahedralTraverseFS.h"
#include "uvHexahedronRay.h"
#include "uvIsosurfaceList.h"
#include "uvLinearCellSplit.h"
#include "vtkUnstructuredVolumeOpenGL.h"
#include "uvPhongLib.h"
#include "uvPreIntegration.h"
#include "uvRayCellGeometry.h"
#include "uvTransferFunctionLib.h"
#include "vtkUnstructuredVolumeTransferFunction.h"

#include "vtkCamera.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
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
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkHexahedralRayCastMapper);

namespace
{

/// A face by its sorted point ids, and which cell's local face it is.
struct FaceRecord
{
  std::array<std::uint32_t, 4> Key;
  std::uint32_t CellFace; // cell * 8 + local face
  bool operator<(const FaceRecord& other) const
  {
    return Key < other.Key || (Key == other.Key && CellFace < other.CellFace);
  }
};
} // namespace

class vtkHexahedralRayCastMapper::Internals
{
public:
  std::string MeshKey;
  std::vector<std::uint32_t> CellPoints;   // 8 per cell, VTK hexahedron order
  std::vector<float> PointData;            // recentred position, normalised scalar
  std::vector<std::int32_t> Neighbours;    // 8 per cell (6 used): neighbour * 8 + face, or -1
  std::vector<std::int32_t> BoundaryFaces; // 4 per boundary face: cell, local face, 0, 0
  glm::dvec3 Center{ 0.0 };
  double ScalarOffset = 0.0, ScalarScale = 1.0;
  int MeshBuilds = 0, Peels = 0;
  vtkIdType TangledCells = 0;
  std::string EyeCellKey;
  glm::dvec3 EyeCellPosition{ 0.0 };
  int EyeCell = -1;
  bool WarnedNaN = false;
  uv::IsosurfaceList Isosurfaces;
  std::string UploadedIsosurfacesKey;

  vtkOpenGLRenderWindow* Context = nullptr;
  vtkNew<vtkOpenGLBufferObject> CellPointBuffer, PointBuffer, NeighbourBuffer, BoundaryBuffer;
  vtkNew<vtkTextureObject> CellPointTexture, PointTexture, NeighbourTexture, BoundaryTexture, PsiTexture,
    IsosurfaceTexture, OpaqueDepthTexture, EntryTexture, EntryDepthTexture, ExitTexture, AccumulationTexture[2];
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  vtkNew<vtkOpenGLVertexArrayObject> NoAttributes;
  bool MeshOnGpu = false;
  int ImageSize[2] = { 0, 0 };
  vtkSmartPointer<vtkImageData> FloatImage;

  void ReleaseGraphics()
  {
    if (this->Context)
    {
      for (vtkTextureObject* texture : { this->CellPointTexture.Get(), this->PointTexture.Get(),
             this->NeighbourTexture.Get(), this->BoundaryTexture.Get(), this->PsiTexture.Get(),
             this->IsosurfaceTexture.Get(),
             this->OpaqueDepthTexture.Get(), this->EntryTexture.Get(), this->EntryDepthTexture.Get(),
             this->ExitTexture.Get(), this->AccumulationTexture[0].Get(), this->AccumulationTexture[1].Get() })
      {
        texture->ReleaseGraphicsResources(this->Context);
      }
      for (vtkOpenGLBufferObject* buffer : { this->CellPointBuffer.Get(), this->PointBuffer.Get(),
             this->NeighbourBuffer.Get(), this->BoundaryBuffer.Get() })
      {
        buffer->ReleaseGraphicsResources();
      }
      this->Framebuffer->ReleaseGraphicsResources(this->Context);
      this->NoAttributes->ReleaseGraphicsResources();
    }
    this->Context = nullptr;
    this->MeshOnGpu = false;
    this->UploadedIsosurfacesKey.clear();
    this->ImageSize[0] = this->ImageSize[1] = 0;
  }
};

vtkHexahedralRayCastMapper::vtkHexahedralRayCastMapper()
  : Impl(new Internals)
{
}

vtkHexahedralRayCastMapper::~vtkHexahedralRayCastMapper() = default;

void vtkHexahedralRayCastMapper::AddIsosurface(double value, double red, double green, double blue, double opacity)
{
  this->Impl->Isosurfaces.Add(value, red, green, blue, opacity);
  this->Modified();
}

void vtkHexahedralRayCastMapper::RemoveAllIsosurfaces()
{
  if (this->Impl->Isosurfaces.Clear())
    this->Modified();
}

int vtkHexahedralRayCastMapper::GetNumberOfIsosurfaces()
{
  return this->Impl->Isosurfaces.Size();
}

vtkImageData* vtkHexahedralRayCastMapper::GetFloatImage()
{
  return this->Impl->FloatImage;
}
vtkIdType vtkHexahedralRayCastMapper::GetNumberOfCells()
{
  return static_cast<vtkIdType>(this->Impl->CellPoints.size() / 8);
}
vtkIdType vtkHexahedralRayCastMapper::GetNumberOfBoundaryFaces()
{
  return static_cast<vtkIdType>(this->Impl->BoundaryFaces.size() / 4);
}
int vtkHexahedralRayCastMapper::GetNumberOfPeels()
{
  return this->Impl->Peels;
}
vtkIdType vtkHexahedralRayCastMapper::GetNumberOfTangledCells()
{
  return this->Impl->TangledCells;
}
vtkIdType vtkHexahedralRayCastMapper::GetMeshMemoryInBytes()
{
  const Internals& impl = *this->Impl;
  return static_cast<vtkIdType>(sizeof(std::uint32_t) * impl.CellPoints.size() + sizeof(float) * impl.PointData.size() +
    sizeof(std::int32_t) * (impl.Neighbours.size() + impl.BoundaryFaces.size()));
}
int vtkHexahedralRayCastMapper::GetNumberOfMeshBuilds()
{
  return this->Impl->MeshBuilds;
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

void vtkHexahedralRayCastMapper::ReleaseGraphicsResources(vtkWindow*)
{
  this->Impl->ReleaseGraphics();
}

void vtkHexahedralRayCastMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const char* modes[] = { "Accurate", "Fast", "FixedSteps" };
  os << indent << "IntegrationMode: " << modes[this->IntegrationMode] << "\n";
  os << indent << "FixedSteps: " << this->FixedSteps << "\n";
  os << indent << "OpacityThreshold: " << this->OpacityThreshold << "\n";
  os << indent << "MaximumPeels: " << this->MaximumPeels << "\n";
  os << indent << "Isosurfaces: " << this->Impl->Isosurfaces.Size() << "\n";
}

void vtkHexahedralRayCastMapper::Render(vtkRenderer* renderer, vtkVolume* volume)
{
  Internals& impl = *this->Impl;
  impl.Peels = 0;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  vtkDataSet* input = vtkDataSet::SafeDownCast(this->GetInputDataObject(0, 0));
  if (!window || !volume || !volume->GetProperty() || !input)
  {
    vtkErrorMacro("needs an input, an OpenGL render window and a volume with a property");
    return;
  }
  if (input->GetNumberOfCells() == 0 || input->GetNumberOfPoints() == 0)
  {
    return; // an empty grid draws nothing
  }
  int cellFlag = 0;
  vtkDataArray* scalars = vtkAbstractMapper::GetScalars(
    input, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
  if (!scalars)
  {
    vtkErrorMacro("the input has no point scalar to render (set one, or select an array with SelectScalarArray)");
    return;
  }
  if (cellFlag != 0)
  {
    vtkErrorMacro("cell scalars are not supported: convert them to point data (vtkCellDataToPointData)");
    return;
  }

  // ---- The mesh: cells, recentred points, face adjacency, boundary faces.
  const std::string meshKey = std::to_string(reinterpret_cast<std::uintptr_t>(input)) + ":" +
    std::to_string(input->GetMTime()) + ":" + std::to_string(reinterpret_cast<std::uintptr_t>(scalars)) + ":" +
    std::to_string(scalars->GetMTime());
  if (meshKey != impl.MeshKey)
  {
    this->UpdateProgress(0.0); // preparation (adjacency) can take seconds on large meshes
    impl.MeshKey.clear();
    impl.MeshOnGpu = false;
    // Any vtkDataSet through its generic cell API: unstructured grids, and structured grids
    // (hexahedra; blanked cells are empty and skipped), image data and rectilinear grids (voxels)
    // with no conversion.
    vtkDataSet* grid = input;
    const vtkIdType pointCount = grid->GetNumberOfPoints();
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (vtkIdType p = 0; p < pointCount; ++p)
    {
      const double s = scalars->GetComponent(p, 0);
      if (std::isfinite(s))
      {
        low = std::min(low, s);
        high = std::max(high, s);
      }
    }
    if (!(low <= high))
      low = high = 0.0;
    impl.ScalarOffset = low;
    impl.ScalarScale = high > low ? 1.0 / (high - low) : 1.0;
    double bounds[6];
    grid->GetBounds(bounds);
    impl.Center = glm::dvec3(bounds[0] + bounds[1], bounds[2] + bounds[3], bounds[4] + bounds[5]) * 0.5;
    impl.PointData.assign(4 * pointCount, 0.0f);
    double firstPoint[3];
    grid->GetPoint(0, firstPoint); // vtkDataSet::GetPoint(id, x) is thread-safe after one serial call
    vtkSMPTools::For(0, pointCount, [&](vtkIdType begin, vtkIdType end) {
      double x[3];
      for (vtkIdType p = begin; p < end; ++p)
      {
        grid->GetPoint(p, x);
        for (int d = 0; d < 3; ++d)
          impl.PointData[4 * p + d] = static_cast<float>(x[d] - impl.Center[d]);
        impl.PointData[4 * p + 3] =
          static_cast<float>((scalars->GetComponent(p, 0) - impl.ScalarOffset) * impl.ScalarScale);
      }
    });

    impl.CellPoints.clear();
    vtkIdType others = 0, withNaN = 0;
    vtkNew<vtkIdList> cellIds;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    {
      const int type = grid->GetCellType(c);
      if (type == VTK_EMPTY_CELL)
        continue; // blanked
      if (type != VTK_HEXAHEDRON && type != VTK_VOXEL)
      {
        ++others;
        continue;
      }
      grid->GetCellPoints(c, cellIds);
      const vtkIdType* ids = cellIds->GetPointer(0);
      std::array<std::uint32_t, 8> corners;
      for (int k = 0; k < 8; ++k)
        corners[k] = static_cast<std::uint32_t>(ids[type == VTK_VOXEL ? uv::VoxelToHexahedronOrder[k] : k]);
      bool finite = true;
      for (std::uint32_t id : corners)
        finite = finite && std::isfinite(impl.PointData[4 * id + 3]);
      if (!finite)
      {
        ++withNaN;
        continue;
      }
      impl.CellPoints.insert(impl.CellPoints.end(), corners.begin(), corners.end());
    }
    if (others > 0)
    {
      vtkErrorMacro(<< others << " cells are not hexahedra or voxels: split the mesh with "
                    << "vtkHexahedraToTetrahedra and render it with vtkPreIntegratedTetrahedraMapper");
      impl.CellPoints.clear();
      return;
    }
    // Folded cells (a crushed mesh): told, not refused.
    std::atomic<vtkIdType> tangled(0);
    vtkSMPTools::For(0, static_cast<vtkIdType>(impl.CellPoints.size() / 8), [&](vtkIdType begin, vtkIdType end) {
      vtkIdType found = 0;
      for (vtkIdType c = begin; c < end; ++c)
      {
        glm::dvec3 p[8];
        for (int k = 0; k < 8; ++k)
        {
          const float* x = &impl.PointData[4 * impl.CellPoints[8 * c + k]];
          p[k] = glm::dvec3(x[0], x[1], x[2]);
        }
        found += uv::IsTangledHexahedron(p) ? 1 : 0;
      }
      tangled += found;
    });
    impl.TangledCells = tangled;
    if (impl.TangledCells > 0)
    {
      vtkWarningMacro(<< impl.TangledCells << " hexahedra are tangled (their Jacobian changes sign, as in a "
                      << "crushed mesh): what a ray integrates through them is not well defined");
    }
    if (withNaN > 0 && !impl.WarnedNaN)
    {
      vtkWarningMacro(<< withNaN << " cells touch a NaN scalar and are left out (holes in the mesh)");
      impl.WarnedNaN = true;
    }
    // Face adjacency by sorting the faces' sorted point ids.
    const std::size_t cellCount = impl.CellPoints.size() / 8;
    std::vector<FaceRecord> faces(6 * cellCount);
    vtkSMPTools::For(0, static_cast<vtkIdType>(cellCount), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType c = begin; c < end; ++c)
        for (int f = 0; f < 6; ++f)
        {
          FaceRecord& record = faces[6 * c + f];
          for (int k = 0; k < 4; ++k)
            record.Key[k] = impl.CellPoints[8 * c + uv::HexahedronFaces[f].Vertices[k]];
          std::sort(record.Key.begin(), record.Key.end());
          record.CellFace = static_cast<std::uint32_t>(8 * c + f);
        }
    });
    this->UpdateProgress(0.4);
    vtkSMPTools::Sort(faces.begin(), faces.end());
    this->UpdateProgress(0.8);
    impl.Neighbours.assign(8 * cellCount, -1);
    impl.BoundaryFaces.clear();
    for (std::size_t i = 0; i < faces.size();)
    {
      std::size_t j = i + 1;
      while (j < faces.size() && faces[j].Key == faces[i].Key)
        ++j;
      if (j - i == 2)
      {
        const std::uint32_t a = faces[i].CellFace, b = faces[i + 1].CellFace;
        impl.Neighbours[8 * (a / 8) + a % 8] = static_cast<std::int32_t>(b);
        impl.Neighbours[8 * (b / 8) + b % 8] = static_cast<std::int32_t>(a);
      }
      else
      {
        // A boundary face (or a non-manifold one: every copy is treated as boundary).
        for (std::size_t k = i; k < j; ++k)
        {
          const std::uint32_t cf = faces[k].CellFace;
          impl.BoundaryFaces.insert(impl.BoundaryFaces.end(),
            { static_cast<std::int32_t>(cf / 8), static_cast<std::int32_t>(cf % 8), 0, 0 });
        }
      }
      i = j;
    }
    impl.MeshKey = meshKey;
    ++impl.MeshBuilds;
    this->UpdateProgress(1.0);
  }
  const std::size_t cellCount = impl.CellPoints.size() / 8;
  const std::size_t boundaryCount = impl.BoundaryFaces.size() / 4;
  if (cellCount == 0 || boundaryCount == 0)
  {
    return;
  }

  // ---- Transfer function as at most 64 uniform nodes, normalised like the scalar.
  vtkVolumeProperty* property = volume->GetProperty();
  std::vector<uv::TransferFunction::Node> nodes = uvvtk::TransferFunctionNodes(property);
  if (nodes.empty())
  {
    vtkErrorMacro("the volume property has no scalar opacity function");
    return;
  }
  if (nodes.size() > static_cast<std::size_t>(uvgl::MaximumUniformNodes))
  {
    // Fewer subdivisions of curved functions first; resample evenly as a last resort.
    nodes = uvvtk::TransferFunctionNodes(property, 1);
    if (nodes.size() > static_cast<std::size_t>(uvgl::MaximumUniformNodes))
    {
      const uv::TransferFunction tf(nodes);
      const double first = nodes.front().Scalar, last = nodes.back().Scalar;
      nodes.clear();
      for (int k = 0; k < uvgl::MaximumUniformNodes; ++k)
      {
        const double s = first + (last - first) * k / (uvgl::MaximumUniformNodes - 1);
        const auto n = tf.Evaluate(s);
        nodes.push_back({ s, n.Color, n.Extinction });
      }
      vtkWarningMacro("more than " << uvgl::MaximumUniformNodes << " transfer-function nodes: resampled to that many");
    }
  }
  for (auto& node : nodes)
  {
    node.Scalar = (node.Scalar - impl.ScalarOffset) * impl.ScalarScale;
  }

  // ---- Camera.
  int width, height, originX, originY;
  renderer->GetTiledSizeAndOrigin(&width, &height, &originX, &originY);
  if (width < 1 || height < 1)
  {
    return;
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  const double aspect = static_cast<double>(width) / height;
  const glm::dmat4 modelToWorld = uvgl::ToGlm(volume->GetMatrix()) * glm::translate(glm::dmat4(1.0), impl.Center);
  const glm::dmat4 worldToEye = uvgl::ToGlm(camera->GetModelViewTransformMatrix());
  const glm::dmat4 modelToEye = worldToEye * modelToWorld;
  const glm::dmat4 modelToClip = uvgl::ToGlm(camera->GetProjectionTransformMatrix(aspect, -1, 1)) * modelToEye;
  const glm::mat4 modelToEyeF(modelToEye);
  const glm::mat3 normalToEyeF(glm::transpose(glm::inverse(glm::dmat3(modelToEye))));
  const glm::mat4 modelToClipF(modelToClip), clipToModelF(glm::inverse(modelToClip));
  // A perspective eye inside the mesh: rays start there, in the cell that holds it.
  const glm::dvec3 eyeModel =
    glm::dvec3(glm::inverse(uvgl::ToGlm(camera->GetModelViewTransformMatrix()) * modelToWorld) * glm::dvec4(0, 0, 0, 1));
  int eyeCell = -1;
  if (!camera->GetParallelProjection())
  {
    if (impl.EyeCellKey != impl.MeshKey || impl.EyeCellPosition != eyeModel)
    {
      impl.EyeCell = -1;
      for (std::size_t c = 0; c < cellCount && impl.EyeCell < 0; ++c)
      {
        glm::dvec3 p[8], low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
        for (int k = 0; k < 8; ++k)
        {
          const float* x = &impl.PointData[4 * impl.CellPoints[8 * c + k]];
          p[k] = glm::dvec3(x[0], x[1], x[2]);
          low = glm::min(low, p[k]);
          high = glm::max(high, p[k]);
        }
        if (glm::any(glm::lessThan(eyeModel, low)) || glm::any(glm::greaterThan(eyeModel, high)))
          continue;
        glm::dvec3 xi(0.5);
        if (uv::InverseTrilinear(p, eyeModel, xi) && uv::InUnitCube(xi, 1e-9))
          impl.EyeCell = static_cast<int>(c);
      }
      impl.EyeCellKey = impl.MeshKey;
      impl.EyeCellPosition = eyeModel;
    }
    eyeCell = impl.EyeCell;
  }

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
    uvgl::UploadBufferTexture(window, impl.CellPointBuffer, impl.CellPointTexture, impl.CellPoints, 4);
    uvgl::UploadBufferTexture(window, impl.PointBuffer, impl.PointTexture, impl.PointData, 4);
    uvgl::UploadBufferTexture(window, impl.NeighbourBuffer, impl.NeighbourTexture, impl.Neighbours, 4);
    uvgl::UploadBufferTexture(window, impl.BoundaryBuffer, impl.BoundaryTexture, impl.BoundaryFaces, 4);
    impl.MeshOnGpu = true;
  }
  uvgl::EnsurePsiTexture(impl.PsiTexture, window);
  // Isosurfaces, normalised like the scalar: uploaded when they or the normalisation change.
  const std::vector<uv::Isosurface> isosurfaces = impl.Isosurfaces.Drawn(impl.ScalarOffset, impl.ScalarScale);
  std::string isosurfacesKey = "n" + std::to_string(isosurfaces.size());
  for (const uv::Isosurface& s : isosurfaces)
    isosurfacesKey += ":" + std::to_string(s.Value) + "," + std::to_string(s.Color[0]) + "," +
      std::to_string(s.Color[1]) + "," + std::to_string(s.Color[2]) + "," + std::to_string(s.Opacity);
  if (isosurfacesKey != impl.UploadedIsosurfacesKey || !impl.IsosurfaceTexture->GetHandle())
  {
    uvgl::UploadIsosurfaces(impl.IsosurfaceTexture, window, isosurfaces);
    impl.UploadedIsosurfacesKey = isosurfacesKey;
  }
  if (impl.ImageSize[0] != width || impl.ImageSize[1] != height)
  {
    for (vtkTextureObject* texture : { impl.EntryTexture.Get(), impl.ExitTexture.Get(),
           impl.AccumulationTexture[0].Get(), impl.AccumulationTexture[1].Get() })
    {
      texture->SetContext(window);
      texture->SetMinificationFilter(vtkTextureObject::Nearest);
      texture->SetMagnificationFilter(vtkTextureObject::Nearest);
      texture->Allocate2D(width, height, 4, VTK_FLOAT);
    }
    impl.EntryDepthTexture->SetContext(window);
    impl.EntryDepthTexture->AllocateDepth(width, height, vtkTextureObject::Float32);
    impl.OpaqueDepthTexture->SetContext(window);
    impl.OpaqueDepthTexture->AllocateDepth(width, height, vtkTextureObject::Float32);
    impl.Framebuffer->SetContext(window);
    impl.ImageSize[0] = width;
    impl.ImageSize[1] = height;
  }
  uvgl::CopySceneDepth(impl.OpaqueDepthTexture, originX, originY, width, height); // far if multisampled

  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunctionSaver(state);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  vtkOpenGLState::ScopedglDepthFunc depthFunctionSaver(state);
  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  vtkOpenGLState::ScopedglClearColor clearColorSaver(state);

  const std::string defines = uvgl::TransferFunctionDefines(nodes); // at most 64 nodes: uniforms
  const std::initializer_list<std::pair<const char*, const char*>> faces = { { "//UV::BilinearFace", uvBilinearFaceLib } };
  const std::string entryVertexSource = uvgl::ShaderSource(uvHexahedralEntryVS, defines);
  const std::string entryFragmentSource = uvgl::ShaderSource(uvHexahedralEntryFS, defines, faces);
  const std::string traverseSource = uvgl::ShaderSource(uvHexahedralTraverseFS, defines,
    { { "//UV::BilinearFace", uvBilinearFaceLib }, { "//UV::TransferFunction", uvTransferFunctionLib },
      { "//UV::Phong", uvPhongLib } });
  const float viewport[2] = { static_cast<float>(width), static_cast<float>(height) };

  impl.Framebuffer->SaveCurrentBindingsAndBuffers();
  impl.Framebuffer->Bind();
  state->vtkglViewport(0, 0, width, height);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglDisable(GL_BLEND);
  // Start: nothing accumulated.
  impl.Framebuffer->AddColorAttachment(0, impl.AccumulationTexture[0]);
  impl.Framebuffer->ActivateDrawBuffers(1);
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  int source = 0;
  GLuint query = 0;
  glGenQueries(1, &query);
  bool failed = false;
  for (int peel = 0; peel < this->MaximumPeels; ++peel)
  {
    // Entry pass: the nearest entering boundary face beyond the previous exit.
    impl.Framebuffer->AddColorAttachment(0, impl.EntryTexture);
    impl.Framebuffer->AddDepthAttachment(impl.EntryDepthTexture);
    impl.Framebuffer->ActivateDrawBuffers(1);
    state->vtkglClearColor(0.0f, -1.0f, 0.0f, 0.0f);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_LESS);
    vtkShaderProgram* entry = window->GetShaderCache()->ReadyShaderProgram(
      entryVertexSource.c_str(), entryFragmentSource.c_str(), "");
    if (!entry)
    {
      failed = true;
      break;
    }
    impl.BoundaryTexture->Activate();
    impl.CellPointTexture->Activate();
    impl.PointTexture->Activate();
    impl.ExitTexture->Activate();
    entry->SetUniformi("boundaryFaces", impl.BoundaryTexture->GetTextureUnit());
    entry->SetUniformi("cellPoints", impl.CellPointTexture->GetTextureUnit());
    entry->SetUniformi("pointData", impl.PointTexture->GetTextureUnit());
    entry->SetUniformi("previousExit", impl.ExitTexture->GetTextureUnit());
    entry->SetUniformi("firstPeel", peel == 0 ? 1 : 0);
    entry->SetUniformMatrix4x4("modelToClip", const_cast<float*>(glm::value_ptr(modelToClipF)));
    entry->SetUniformMatrix4x4("clipToModel", const_cast<float*>(glm::value_ptr(clipToModelF)));
    entry->SetUniform2f("viewportSize", viewport);
    impl.NoAttributes->Bind();
    glBeginQuery(GL_SAMPLES_PASSED, query);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(6 * boundaryCount));
    glEndQuery(GL_SAMPLES_PASSED);
    impl.NoAttributes->Release();
    impl.ExitTexture->Deactivate();
    GLuint samples = 0;
    glGetQueryObjectuiv(query, GL_QUERY_RESULT, &samples);
    impl.Framebuffer->RemoveDepthAttachment();
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_FALSE);
    if (samples == 0 && !(peel == 0 && eyeCell >= 0))
    {
      impl.BoundaryTexture->Deactivate();
      impl.CellPointTexture->Deactivate();
      impl.PointTexture->Deactivate();
      break; // no ray enters the mesh again
    }
    ++impl.Peels;

    // Traversal pass: walk and integrate, compositing into the other accumulation texture.
    const int target = 1 - source;
    impl.Framebuffer->AddColorAttachment(0, impl.AccumulationTexture[target]);
    impl.Framebuffer->AddColorAttachment(1, impl.ExitTexture);
    impl.Framebuffer->ActivateDrawBuffers(2);
    vtkShaderProgram* traverse =
      window->GetShaderCache()->ReadyShaderProgram(uvFullScreenTriangleVS, traverseSource.c_str(), "");
    if (!traverse)
    {
      failed = true;
      break;
    }
    impl.EntryTexture->Activate();
    impl.AccumulationTexture[source]->Activate();
    impl.OpaqueDepthTexture->Activate();
    impl.NeighbourTexture->Activate();
    impl.PsiTexture->Activate();
    impl.IsosurfaceTexture->Activate();
    traverse->SetUniformi("entry", impl.EntryTexture->GetTextureUnit());
    traverse->SetUniformi("accumulated", impl.AccumulationTexture[source]->GetTextureUnit());
    traverse->SetUniformi("opaqueDepth", impl.OpaqueDepthTexture->GetTextureUnit());
    traverse->SetUniformi("boundaryFaces", impl.BoundaryTexture->GetTextureUnit());
    traverse->SetUniformi("cellPoints", impl.CellPointTexture->GetTextureUnit());
    traverse->SetUniformi("cellNeighbours", impl.NeighbourTexture->GetTextureUnit());
    traverse->SetUniformi("pointData", impl.PointTexture->GetTextureUnit());
    uvgl::SetTransferFunctionUniforms(traverse, nodes, nullptr, impl.PsiTexture); // at most 64: uniforms
    traverse->SetUniformi("isosurfaces", impl.IsosurfaceTexture->GetTextureUnit());
    traverse->SetUniformi("isosurfaceCount", static_cast<int>(isosurfaces.size()));
    traverse->SetUniformMatrix4x4("modelToEye", const_cast<float*>(glm::value_ptr(modelToEyeF)));
    traverse->SetUniformMatrix3x3("normalToEye", const_cast<float*>(glm::value_ptr(normalToEyeF)));
    traverse->SetUniformi("parallelProjection", camera->GetParallelProjection() ? 1 : 0);
    uvgl::SetPhongUniforms(traverse, renderer, property, worldToEye);
    traverse->SetUniformMatrix4x4("clipToModel", const_cast<float*>(glm::value_ptr(clipToModelF)));
    traverse->SetUniform2f("viewportSize", viewport);
    traverse->SetUniformi("integrationMode", this->IntegrationMode);
    traverse->SetUniformi("fixedSteps", this->FixedSteps);
    traverse->SetUniformi("exactEnds", this->ExactSegmentEnds ? 1 : 0);
    traverse->SetUniformf("opacityThreshold", static_cast<float>(this->OpacityThreshold));
    traverse->SetUniformi("maximumCells", static_cast<int>(std::min<std::size_t>(cellCount + 8, 1 << 20)));
    traverse->SetUniformi("eyeCell", peel == 0 ? eyeCell : -1);
    const float eye[3] = { static_cast<float>(eyeModel.x), static_cast<float>(eyeModel.y), static_cast<float>(eyeModel.z) };
    traverse->SetUniform3f("eyeModel", eye);
    impl.NoAttributes->Bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    impl.NoAttributes->Release();
    for (vtkTextureObject* texture : { impl.EntryTexture.Get(), impl.AccumulationTexture[source].Get(),
           impl.OpaqueDepthTexture.Get(), impl.NeighbourTexture.Get(), impl.PsiTexture.Get(), impl.IsosurfaceTexture.Get(),
           impl.BoundaryTexture.Get(), impl.CellPointTexture.Get(), impl.PointTexture.Get() })
    {
      texture->Deactivate();
    }
    impl.Framebuffer->RemoveColorAttachment(1);
    impl.Framebuffer->ActivateDrawBuffers(1);
    source = target;
  }
  glDeleteQueries(1, &query);
  if (this->KeepFloatImage && !failed)
  {
    impl.Framebuffer->AddColorAttachment(0, impl.AccumulationTexture[source]);
    uvgl::ReadFloatImage(impl.Framebuffer, 0, width, height, impl.FloatImage);
  }
  impl.Framebuffer->RestorePreviousBindingsAndBuffers();
  if (failed)
  {
    vtkErrorMacro("the hexahedral ray-casting shaders failed to compile or link");
    return;
  }

  // ---- Blend the result into VTK's scene.
  if (!uvgl::CompositeIntoScene(
        window, impl.AccumulationTexture[source], impl.NoAttributes, originX, originY, width, height))
  {
    vtkErrorMacro("the composite shaders failed to compile or link");
    return;
  }
  vtkOpenGLCheckErrorMacro("failed after ray casting the hexahedra");
}
