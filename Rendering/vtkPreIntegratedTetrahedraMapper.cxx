#include "vtkPreIntegratedTetrahedraMapper.h"

#include "uvPreIntegratedTetrahedraFS.h"
#include "uvPreIntegratedTetrahedraGS.h"
#include "uvPreIntegratedTetrahedraPullVS.h"
#include "uvPreIntegratedTetrahedraVS.h"
#include "uvProjectedTetrahedronLib.h"
#include "uvSegmentIntegrationLib.h"
#include "uvTransferFunctionLib.h"
#include "uvMapperOpenGL.h"
#include "uvPreIntegration.h"
#include "uvTransferFunctionFromVolumeProperty.h"
#include "uvTetrahedralMesh.h"
#include "uvVisibilitySort.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkHexahedraToTetrahedra.h"
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
#include "vtkVertexGradientFilter.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtk_glew.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPreIntegratedTetrahedraMapper);

class vtkPreIntegratedTetrahedraMapper::Internals
{
public:
  // The mesh as the GPU takes it, rebuilt when the input or its scalar changes.
  uv::TetrahedralMesh Mesh;

  uv::VertexGradientCache Gradients;

  uv::NormalisedTransferFunction TransferFunction;
  const std::vector<uv::TransferFunction::Node>& Nodes = TransferFunction.Nodes; // normalised scalars
  uv::IsosurfaceList Isosurfaces;
  vtkMTimeType IsosurfaceTime = 0, UploadedIsosurfaceTime = 0;

  std::vector<std::pair<double, double>> VisibleListZeroSet;
  std::vector<double> VisibleListIsovalues;
  bool VisibleListValid = false;
  bool VisibleListSkipped = false;
  std::vector<std::uint32_t> Visible;

  uv::CentroidOrder Order;

  // GPU state, for one context.
  vtkOpenGLRenderWindow* Context = nullptr;
  vtkNew<vtkOpenGLBufferObject> TetrahedronBuffer, PointBuffer, GradientBuffer, OrderBuffer, OrderTexelBuffer,
    FanIndexBuffer;
  std::size_t FanIndexCount = 0; // tetrahedra the fan index buffer covers
  vtkNew<vtkTextureObject> TetrahedronTexture, PointTexture, GradientTexture, TransferTexture, IsosurfaceTexture,
    PsiTexture, DepthTexture, ColorTexture, OrderTexture;
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  vtkNew<vtkOpenGLVertexArrayObject> NoAttributes;
  bool MeshOnGpu = false, GradientsOnGpu = false, TransferFunctionOnGpu = false, OrderOnGpu = false;
  int OrderRoute = -1; // the route the uploaded order is for
  int ImageSize[2] = { 0, 0 };

  vtkSmartPointer<vtkImageData> FloatImage;
  vtkIdType DrawnTetrahedra = 0;
  int MeshUploads = 0, TransferFunctionUploads = 0, VisibleListBuilds = 0;
  uv::MeshWarnings Warned;
  bool WarnedMultisample = false;

  void ReleaseGraphics()
  {
    if (this->Context)
    {
      for (vtkTextureObject* texture : { this->TetrahedronTexture.Get(), this->PointTexture.Get(),
             this->GradientTexture.Get(), this->TransferTexture.Get(), this->IsosurfaceTexture.Get(),
             this->PsiTexture.Get(), this->DepthTexture.Get(), this->ColorTexture.Get(), this->OrderTexture.Get() })
      {
        texture->ReleaseGraphicsResources(this->Context);
      }
      for (vtkOpenGLBufferObject* buffer : { this->TetrahedronBuffer.Get(), this->PointBuffer.Get(),
             this->GradientBuffer.Get(), this->OrderBuffer.Get(), this->OrderTexelBuffer.Get(), this->FanIndexBuffer.Get() })
      {
        buffer->ReleaseGraphicsResources();
      }
      this->Framebuffer->ReleaseGraphicsResources(this->Context);
      this->NoAttributes->ReleaseGraphicsResources();
    }
    this->Context = nullptr;
    this->MeshOnGpu = this->GradientsOnGpu = this->TransferFunctionOnGpu = this->OrderOnGpu = false;
    this->UploadedIsosurfaceTime = 0;
    this->FanIndexCount = 0;
    this->ImageSize[0] = this->ImageSize[1] = 0;
  }
};

vtkPreIntegratedTetrahedraMapper::vtkPreIntegratedTetrahedraMapper()
  : Impl(new Internals)
{
  this->SetGradientArrayName("Gradients");
}

vtkPreIntegratedTetrahedraMapper::~vtkPreIntegratedTetrahedraMapper()
{
  this->SetGradientArrayName(nullptr);
}

void vtkPreIntegratedTetrahedraMapper::AddIsosurface(double value, double red, double green, double blue, double opacity)
{
  this->Impl->Isosurfaces.Add(value, red, green, blue, opacity);
  this->Modified();
  this->Impl->IsosurfaceTime = this->GetMTime();
}

void vtkPreIntegratedTetrahedraMapper::RemoveAllIsosurfaces()
{
  if (this->Impl->Isosurfaces.Clear())
  {
    this->Modified();
    this->Impl->IsosurfaceTime = this->GetMTime();
  }
}

int vtkPreIntegratedTetrahedraMapper::GetNumberOfIsosurfaces()
{
  return this->Impl->Isosurfaces.Size();
}

vtkImageData* vtkPreIntegratedTetrahedraMapper::GetFloatImage()
{
  return this->Impl->FloatImage;
}

vtkIdType vtkPreIntegratedTetrahedraMapper::GetNumberOfDrawnTetrahedra()
{
  return this->Impl->DrawnTetrahedra;
}
int vtkPreIntegratedTetrahedraMapper::GetNumberOfSorts()
{
  return this->Impl->Order.Sorts;
}
int vtkPreIntegratedTetrahedraMapper::GetNumberOfGradientComputations()
{
  return this->Impl->Gradients.Computations;
}
vtkIdType vtkPreIntegratedTetrahedraMapper::GetMeshMemoryInBytes()
{
  const Internals& impl = *this->Impl;
  std::size_t bytes = sizeof(std::uint32_t) * (impl.Mesh.TetrahedronPoints.size() + impl.Order.Order.size()) +
    sizeof(float) * impl.Mesh.PointData.size() + sizeof(std::uint32_t) * 12 * impl.FanIndexCount;
  if (impl.GradientsOnGpu)
    bytes += sizeof(float) * impl.Gradients.Values.size();
  return static_cast<vtkIdType>(bytes);
}

int vtkPreIntegratedTetrahedraMapper::GetNumberOfMeshUploads()
{
  return this->Impl->MeshUploads;
}
int vtkPreIntegratedTetrahedraMapper::GetNumberOfTransferFunctionUploads()
{
  return this->Impl->TransferFunctionUploads;
}
int vtkPreIntegratedTetrahedraMapper::GetNumberOfVisibleListBuilds()
{
  return this->Impl->VisibleListBuilds;
}

void vtkPreIntegratedTetrahedraMapper::ReleaseGraphicsResources(vtkWindow*)
{
  this->Impl->ReleaseGraphics();
}

void vtkPreIntegratedTetrahedraMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IntegrationMode: "
     << (this->IntegrationMode == AVERAGE_SCALAR ? "AverageScalar" : "PartialPreIntegration") << "\n";
  os << indent << "Isosurfaces: " << this->Impl->Isosurfaces.Size() << "\n";
  os << indent << "GradientArrayName: " << (this->GradientArrayName ? this->GradientArrayName : "(none)") << "\n";
  os << indent << "SkipInvisibleCells: " << this->SkipInvisibleCells << "\n";
  os << indent << "KeepFloatImage: " << this->KeepFloatImage << "\n";
}

void vtkPreIntegratedTetrahedraMapper::Render(vtkRenderer* renderer, vtkVolume* volume)
{
  Internals& impl = *this->Impl;
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

  // ---- The mesh, when the input or its scalar changed.
  int cellFlag = 0;
  vtkDataArray* inputScalars = uv::MapperScalars(this, input, cellFlag);
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
  uv::TetrahedralMesh::Change change;
  const std::string error = impl.Mesh.Update(
    input, inputScalars,
    [this](vtkDataSet* split) {
      int flag = 0;
      return uv::MapperScalars(this, split, flag);
    },
    [this](double progress) { this->UpdateProgress(progress); }, change);
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return;
  }
  if (change != uv::TetrahedralMesh::Change::Nothing)
  {
    impl.MeshOnGpu = impl.OrderOnGpu = false;
    impl.Order.Invalidate();
    impl.VisibleListValid = impl.VisibleListValid && change == uv::TetrahedralMesh::Change::Points;
    for (const std::string& warning : impl.Warned.New(impl.Mesh, input->GetNumberOfCells()))
      vtkWarningMacro(<< warning);
  }
  const std::size_t tetCount = impl.Mesh.Size();
  if (tetCount == 0)
  {
    return;
  }

  // ---- Transfer function and isosurfaces, normalised like the scalar.
  vtkVolumeProperty* property = volume->GetProperty();
  if (impl.TransferFunction.Update(property, impl.Mesh.ScalarOffset, impl.Mesh.ScalarScale))
  {
    impl.TransferFunctionOnGpu = false;
    impl.UploadedIsosurfaceTime = 0; // isovalues are normalised the same way
  }
  if (impl.Nodes.empty())
  {
    vtkErrorMacro("the volume property has no scalar opacity function");
    return;
  }
  const std::vector<uv::Isosurface> drawnIsosurfaces = impl.Isosurfaces.Drawn(impl.Mesh.ScalarOffset, impl.Mesh.ScalarScale);
  std::vector<double> isovalues;
  for (const uv::Isosurface& s : drawnIsosurfaces)
    isovalues.push_back(s.Value);

  // ---- Visible tetrahedra: rebuilt only when the zero-opacity set (or the isovalues) moved.
  const auto zeroSet = this->SkipInvisibleCells ? uv::ZeroExtinctionIntervals(impl.Nodes)
                                                : std::vector<std::pair<double, double>>();
  if (!impl.VisibleListValid || zeroSet != impl.VisibleListZeroSet || isovalues != impl.VisibleListIsovalues ||
    impl.VisibleListSkipped != this->SkipInvisibleCells)
  {
    std::vector<unsigned char> keep(tetCount, 1);
    if (this->SkipInvisibleCells)
    {
      vtkSMPTools::For(0, static_cast<vtkIdType>(tetCount), [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType t = begin; t < end; ++t)
        {
          const double lo = impl.Mesh.ScalarLow[t], hi = impl.Mesh.ScalarHigh[t];
          // Invisible when one zero interval holds the whole range, and no isovalue lies in it.
          const bool invisible =
            uv::RangeHasZeroExtinction(lo, hi, zeroSet) && !uv::RangeHoldsIsovalue(lo, hi, isovalues);
          keep[t] = invisible ? 0 : 1;
        }
      });
    }
    impl.Visible.clear();
    for (std::size_t t = 0; t < tetCount; ++t)
    {
      if (keep[t])
        impl.Visible.push_back(static_cast<std::uint32_t>(t));
    }
    impl.VisibleListZeroSet = zeroSet;
    impl.VisibleListIsovalues = isovalues;
    impl.VisibleListSkipped = this->SkipInvisibleCells;
    impl.VisibleListValid = true;
    impl.Order.Invalidate();
    ++impl.VisibleListBuilds;
  }
  if (impl.Visible.empty())
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
  const glm::dmat4 modelToWorld = uv::ToGlm(volume->GetMatrix()) * glm::translate(glm::dmat4(1.0), impl.Mesh.Center);
  const glm::dmat4 worldToEye = uv::ToGlm(camera->GetModelViewTransformMatrix());
  const glm::dmat4 eyeToClip = uv::ToGlm(camera->GetProjectionTransformMatrix(aspect, -1, 1));
  const glm::dmat4 modelToEye = worldToEye * modelToWorld;
  const glm::dmat4 eyeToModel = glm::inverse(modelToEye);
  const bool parallel = camera->GetParallelProjection() != 0;
  const glm::dvec3 eyeInModel = glm::dvec3(eyeToModel * glm::dvec4(0, 0, 0, 1));
  const glm::dvec3 viewInModel = glm::normalize(glm::dvec3(eyeToModel * glm::dvec4(0, 0, -1, 0)));

  // ---- Gradients, only when something is lit.
  const bool shade = property->GetShade() != 0;
  const bool needGradients = shade || !isovalues.empty();
  if (needGradients)
  {
    bool ignoredArray = false;
    if (impl.Gradients.Update(impl.Mesh, this->GradientArrayName, ignoredArray))
      impl.GradientsOnGpu = false;
    if (ignoredArray)
      vtkWarningMacro("the gradient array '" << this->GradientArrayName << "' does not have 3 components; computing gradients");
  }

  // ---- Visibility order: back to front by centroid distance, when the view or the list changed.
  if (impl.Order.Update(impl.Mesh, impl.Visible, eyeInModel, viewInModel, parallel))
  {
    impl.OrderOnGpu = false;
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
    uv::UploadBufferTexture(window, impl.TetrahedronBuffer, impl.TetrahedronTexture, impl.Mesh.TetrahedronPoints, 4);
    uv::UploadBufferTexture(window, impl.PointBuffer, impl.PointTexture, impl.Mesh.PointData, 4);
    impl.MeshOnGpu = true;
    ++impl.MeshUploads;
  }
  if (needGradients && !impl.GradientsOnGpu)
  {
    uv::UploadBufferTexture(window, impl.GradientBuffer, impl.GradientTexture, impl.Gradients.Values, 4);
    impl.GradientsOnGpu = true;
  }
  if (!impl.TransferFunctionOnGpu)
  {
    uv::UploadTransferFunctionTexture(impl.TransferTexture, window, impl.Nodes);
    impl.TransferFunctionOnGpu = true;
    ++impl.TransferFunctionUploads;
  }
  if (impl.UploadedIsosurfaceTime != impl.IsosurfaceTime || !impl.IsosurfaceTexture->GetHandle())
  {
    uv::UploadIsosurfaces(impl.IsosurfaceTexture, window, drawnIsosurfaces);
    impl.UploadedIsosurfaceTime = impl.IsosurfaceTime;
  }
  uv::EnsurePsiTexture(impl.PsiTexture, window);
  const bool pulling = this->ProjectionRoute == VERTEX_PULLING;
  if (!impl.OrderOnGpu || impl.OrderRoute != this->ProjectionRoute)
  {
    if (pulling)
    {
      uv::UploadBufferTexture(window, impl.OrderTexelBuffer, impl.OrderTexture, impl.Order.Order, 1);
    }
    else
    {
      impl.OrderBuffer->Upload(impl.Order.Order, vtkOpenGLBufferObject::ElementArrayBuffer);
    }
    impl.OrderOnGpu = true;
    impl.OrderRoute = this->ProjectionRoute;
  }
  if (pulling && impl.FanIndexCount < impl.Order.Order.size())
  {
    // Fixed for a given count: triangle t of the tetrahedron in place q is (5q+4, 5q+t, 5q+(t+1)%4).
    const std::size_t n = impl.Order.Order.size();
    std::vector<std::uint32_t> indices(12 * n);
    vtkSMPTools::For(0, static_cast<vtkIdType>(n), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType q = begin; q < end; ++q)
        for (int t = 0; t < 4; ++t)
        {
          indices[12 * q + 3 * t + 0] = static_cast<std::uint32_t>(5 * q + 4);
          indices[12 * q + 3 * t + 1] = static_cast<std::uint32_t>(5 * q + t);
          indices[12 * q + 3 * t + 2] = static_cast<std::uint32_t>(5 * q + (t + 1) % 4);
        }
    });
    impl.FanIndexBuffer->Upload(indices, vtkOpenGLBufferObject::ElementArrayBuffer);
    impl.FanIndexCount = n;
  }
  if (impl.ImageSize[0] != width || impl.ImageSize[1] != height)
  {
    impl.DepthTexture->SetContext(window);
    impl.DepthTexture->AllocateDepth(width, height, vtkTextureObject::Float32);
    impl.ColorTexture->SetContext(window);
    impl.ColorTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    impl.ColorTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    impl.ColorTexture->Allocate2D(width, height, 4, VTK_FLOAT);
    impl.Framebuffer->SetContext(window);
    impl.Framebuffer->SaveCurrentBindingsAndBuffers();
    impl.Framebuffer->Bind();
    impl.Framebuffer->AddColorAttachment(0, impl.ColorTexture);
    impl.Framebuffer->ActivateDrawBuffers(1);
    impl.Framebuffer->RestorePreviousBindingsAndBuffers();
    impl.ImageSize[0] = width;
    impl.ImageSize[1] = height;
  }

  // ---- The depth of what VTK drew so far (opaque geometry), from the current framebuffer.
  if (!uv::CopySceneDepth(impl.DepthTexture, originX, originY, width, height) && !impl.WarnedMultisample)
  {
    vtkWarningMacro("multisampled render window: opaque geometry does not clip the volume (set MultiSamples to 0)");
    impl.WarnedMultisample = true;
  }

  // ---- Project the tetrahedra into the float image, back to front.
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunctionSaver(state);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  vtkOpenGLState::ScopedglClearColor clearColorSaver(state);

  impl.Framebuffer->SaveCurrentBindingsAndBuffers();
  impl.Framebuffer->Bind();
  impl.Framebuffer->ActivateDrawBuffers(1);
  state->vtkglViewport(0, 0, width, height);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);

  std::string defines = uv::TransferFunctionDefines(impl.Nodes);
  if (needGradients)
    defines += "#define UV_GRADIENTS\n";
  const std::initializer_list<std::pair<const char*, const char*>> projection = {
    { "//UV::ProjectedTetrahedron", uvProjectedTetrahedronLib }
  };
  const std::string vertexSource = uv::ShaderSource(
    pulling ? uvPreIntegratedTetrahedraPullVS : uvPreIntegratedTetrahedraVS, defines, projection);
  const std::string geometrySource =
    pulling ? std::string() : uv::ShaderSource(uvPreIntegratedTetrahedraGS, defines, projection);
  const std::string fragmentSource = uv::ShaderSource(
    uvPreIntegratedTetrahedraFS, defines,
    { { "//UV::TransferFunction", uvTransferFunctionLib }, { "//UV::Phong", uvPhongLib },
      { "//UV::SegmentIntegration", uvSegmentIntegrationLib } });
  vtkShaderProgram* program = window->GetShaderCache()->ReadyShaderProgram(
    vertexSource.c_str(), fragmentSource.c_str(), geometrySource.c_str());
  if (!program)
  {
    impl.Framebuffer->RestorePreviousBindingsAndBuffers();
    vtkErrorMacro("the projected-tetrahedra shaders failed to compile or link");
    return;
  }
  auto setMatrix = [program](const char* name, const glm::dmat4& m) {
    glm::mat4 single(m);
    program->SetUniformMatrix4x4(name, glm::value_ptr(single));
  };
  setMatrix("modelToEye", modelToEye);
  setMatrix("eyeToClip", eyeToClip);
  setMatrix("clipToEye", glm::inverse(eyeToClip));
  if (needGradients)
  {
    glm::mat3 normals(glm::transpose(glm::inverse(glm::dmat3(modelToEye))));
    program->SetUniformMatrix3x3("modelToEyeNormals", glm::value_ptr(normals));
  }
  double clippingRange[2];
  camera->GetClippingRange(clippingRange);
  // Tetrahedra crossing the near plane (where rays begin) are ray-cast, in both projections.
  program->SetUniformf("nearDepth", static_cast<float>(clippingRange[0]));
  program->SetUniformf("zeroTolerance", 1e-6f);
  const float viewport[2] = { static_cast<float>(width), static_cast<float>(height) };
  program->SetUniform2f("viewportSize", viewport);
  program->SetUniformi("parallelProjection", parallel ? 1 : 0);
  program->SetUniformi("averageScalar", this->IntegrationMode == AVERAGE_SCALAR ? 1 : 0);
  program->SetUniformi("shadeVolume", shade ? 1 : 0);
  program->SetUniformi("isosurfaceCount", static_cast<int>(isovalues.size()));
  uv::SetPhongUniforms(program, renderer, property, worldToEye);

  std::vector<vtkTextureObject*> active = { impl.TetrahedronTexture, impl.PointTexture, impl.TransferTexture,
    impl.IsosurfaceTexture, impl.PsiTexture, impl.DepthTexture };
  if (needGradients)
    active.push_back(impl.GradientTexture);
  if (pulling)
    active.push_back(impl.OrderTexture);
  for (vtkTextureObject* texture : active)
    texture->Activate();
  program->SetUniformi("tetrahedronPoints", impl.TetrahedronTexture->GetTextureUnit());
  program->SetUniformi("pointData", impl.PointTexture->GetTextureUnit());
  uv::SetTransferFunctionUniforms(program, impl.Nodes, impl.TransferTexture, impl.PsiTexture);
  program->SetUniformi("isosurfaces", impl.IsosurfaceTexture->GetTextureUnit());
  program->SetUniformi("opaqueDepth", impl.DepthTexture->GetTextureUnit());
  if (needGradients)
    program->SetUniformi("pointGradients", impl.GradientTexture->GetTextureUnit());

  impl.NoAttributes->Bind();
  if (pulling)
  {
    program->SetUniformi("drawOrder", impl.OrderTexture->GetTextureUnit());
    impl.FanIndexBuffer->Bind();
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(12 * impl.Order.Order.size()), GL_UNSIGNED_INT, nullptr);
    impl.FanIndexBuffer->Release();
  }
  else
  {
    impl.OrderBuffer->Bind();
    glDrawElements(GL_POINTS, static_cast<GLsizei>(impl.Order.Order.size()), GL_UNSIGNED_INT, nullptr);
    impl.OrderBuffer->Release();
  }
  impl.NoAttributes->Release();
  for (vtkTextureObject* texture : active)
    texture->Deactivate();
  impl.DrawnTetrahedra = static_cast<vtkIdType>(impl.Order.Order.size());

  if (this->KeepFloatImage)
  {
    uv::ReadFloatImage(impl.Framebuffer, 0, width, height, impl.FloatImage);
  }
  impl.Framebuffer->RestorePreviousBindingsAndBuffers();

  // ---- Blend the float image into VTK's scene.
  if (!uv::CompositeIntoScene(window, impl.ColorTexture, impl.NoAttributes, originX, originY, width, height))
  {
    vtkErrorMacro("the composite shaders failed to compile or link");
    return;
  }
  vtkOpenGLCheckErrorMacro("failed after rendering the tetrahedra");
}
