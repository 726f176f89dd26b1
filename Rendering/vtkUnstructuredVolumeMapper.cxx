#include "vtkUnstructuredVolumeMapper.h"

#include "uvAdaptiveImageSampleDistance.h"
#include "uvIsosurfaceList.h"
#include "vtkUnstructuredVolumeFloatTarget.h"
#include "vtkUnstructuredVolumeFrame.h"
#include "vtkUnstructuredVolumeFrameStatistics.h"
#include "vtkUnstructuredVolumeOpenGL.h"
#include "vtkuvNormalisedTransferFunction.h"
#include "vtkuvRenderedScalar.h"
#include "vtkuvVertexGradientCache.h"

#include "vtkCallbackCommand.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLError.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <new>
#include <stdexcept>
#include <set>
#include <sstream>
#include <vector>

namespace
{
bool GLErrorChecksFromEnvironment()
{
  const char* value = std::getenv("UV_CHECK_GL_ERRORS");
  return value && std::strcmp(value, "1") == 0;
}

/// Drains the GL error flags (an implementation may hold several): their names, or "" when none.
/// `outOfMemory`, when given, tells whether GL_OUT_OF_MEMORY was among them.
std::string TakeGLErrors(bool* outOfMemory = nullptr)
{
  std::ostringstream names;
  for (int k = 0; k < 16; ++k)
  {
    const GLenum code = glGetError();
    if (code == GL_NO_ERROR)
      break;
    names << (k ? ", " : "") << vtkOpenGLStrError(code) << " (0x" << std::hex << code << std::dec << ")";
    if (outOfMemory && code == GL_OUT_OF_MEMORY)
      *outOfMemory = true;
  }
  return names.str();
}

/// Whether GL_OUT_OF_MEMORY is among the pending errors (taking them all).
bool GLOutOfMemory()
{
  bool outOfMemory = false;
  TakeGLErrors(&outOfMemory);
  return outOfMemory;
}
}

bool vtkUnstructuredVolumeMapper::GLErrorChecks = GLErrorChecksFromEnvironment();

void vtkUnstructuredVolumeMapper::SetGLErrorChecks(bool on)
{
  GLErrorChecks = on;
}

bool vtkUnstructuredVolumeMapper::GetGLErrorChecks()
{
  return GLErrorChecks;
}

bool vtkUnstructuredVolumeMapper::ReportGLErrors(const char* pass)
{
  const std::string errors = TakeGLErrors(), messages = uvgl::TakeDriverMessages();
  if (errors.empty() && messages.empty())
    return true;
  vtkErrorMacro("GL error after " << pass << ": " << (errors.empty() ? "none from glGetError" : errors) << messages);
  return false;
}

struct vtkUnstructuredVolumeMapper::Shared
{
  uv::IsosurfaceList Isosurfaces;
  vtkUnstructuredVolumeFloatTarget Target;
  vtkSmartPointer<vtkImageData> FloatImage;
  vtkOpenGLRenderWindow* Context = nullptr;
  std::set<std::string> WarningsGiven; // the keys of WarnOnce
  vtkNew<vtkUnstructuredVolumeFrameStatistics> Statistics;
  uv::AdaptiveImageSampleDistance Adaptive; // AutoAdjustSampleDistances
  struct
  {
    double Distance = 1.0, Seconds = 0.0;
    bool Interactive = false;
  } LastFrame;
};

vtkUnstructuredVolumeMapper::vtkUnstructuredVolumeMapper()
  : Base(new Shared)
{
  this->SetGradientArrayName("Gradients");
}

vtkUnstructuredVolumeMapper::~vtkUnstructuredVolumeMapper()
{
  this->SetGradientArrayName(nullptr);
}

void vtkUnstructuredVolumeMapper::AddIsosurface(double value, double red, double green, double blue, double opacity)
{
  this->Base->Isosurfaces.Add(value, red, green, blue, opacity);
  this->Modified();
}

bool vtkUnstructuredVolumeMapper::PrepareThrough(
  vtkUnstructuredVolumeMapper* delegate, const vtkUnstructuredVolumeFrame& frame)
{
  delegate->SetInputDataObject(this->GetInputDataObject(0, 0));
  delegate->SetScalarMode(this->ScalarMode);
  if (this->ArrayAccessMode == VTK_GET_ARRAY_BY_ID)
    delegate->SelectScalarArray(this->ArrayId);
  else
    delegate->SelectScalarArray(this->ArrayName);
  delegate->SetBlendMode(this->BlendMode);
  delegate->Base->Isosurfaces = this->Base->Isosurfaces;
  delegate->ProjectionRoute = this->ProjectionRoute;
  delegate->SkipInvisibleCells = this->SkipInvisibleCells;
  delegate->OpacityThreshold = this->OpacityThreshold;
  delegate->TransferFunctionTolerance = this->TransferFunctionTolerance;
  delegate->SegmentIntegration = this->SegmentIntegration;
  delegate->VisibilityOrder = this->VisibilityOrder;
  delegate->GradientMode = this->GradientMode;
  delegate->SetGradientArrayName(this->GradientArrayName);
  const bool prepared = delegate->Prepare(frame);
  this->MeshUpdates = { delegate->MeshUpdates.Builds, delegate->MeshUpdates.PointRefreshes,
    delegate->MeshUpdates.ValueRefreshes };
  this->NumberOfTransferFunctionNodes = delegate->NumberOfTransferFunctionNodes;
  this->NumberOfCyclesBroken = delegate->NumberOfCyclesBroken;
  this->NumberOfGapConstraints = delegate->NumberOfGapConstraints;
  return prepared;
}

namespace
{
/// A delegate's error or warning, given to its delegator's observers, or shown as VTK shows them
/// when the delegator has none.
void ForwardMessage(vtkObject*, unsigned long event, void* delegator, void* message)
{
  auto* to = static_cast<vtkObject*>(delegator);
  if (to->HasObserver(event))
    to->InvokeEvent(event, message);
  else if (event == vtkCommand::ErrorEvent)
    vtkOutputWindowDisplayErrorText(static_cast<const char*>(message));
  else
    vtkOutputWindowDisplayWarningText(static_cast<const char*>(message));
}
}

void vtkUnstructuredVolumeMapper::ForwardMessagesOf(vtkUnstructuredVolumeMapper* delegate)
{
  vtkNew<vtkCallbackCommand> forward;
  forward->SetCallback(ForwardMessage);
  forward->SetClientData(this);
  delegate->AddObserver(vtkCommand::ErrorEvent, forward);
  delegate->AddObserver(vtkCommand::WarningEvent, forward);
}

void vtkUnstructuredVolumeMapper::RemoveAllIsosurfaces()
{
  if (this->Base->Isosurfaces.Clear())
  {
    this->Modified();
  }
}

int vtkUnstructuredVolumeMapper::GetNumberOfIsosurfaces()
{
  return this->Base->Isosurfaces.Size();
}

const uv::IsosurfaceList& vtkUnstructuredVolumeMapper::GetIsosurfaces() const
{
  return this->Base->Isosurfaces;
}

vtkImageData* vtkUnstructuredVolumeMapper::GetFloatImage()
{
  return this->Base->FloatImage;
}

bool vtkUnstructuredVolumeMapper::FindScalar(
  vtkDataSet* data, vtkVolumeProperty* property, vtkuv::RenderedScalar& scalar)
{
  scalar = vtkuv::FindRenderedScalar(
    data, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, property);
  if (!scalar)
  {
    vtkErrorMacro("the input has no point or cell scalar to render (set one, or select an array with "
                  "SelectScalarArray)");
    return false;
  }
  return true;
}

bool vtkUnstructuredVolumeMapper::WarnCellScalarLimits(
  const vtkuv::RenderedScalar& scalar, bool shade, bool facesBetweenCells)
{
  if (!scalar.OnCells)
  {
    return false;
  }
  const bool isosurfaces = this->GetNumberOfIsosurfaces() > 0 && !facesBetweenCells;
  if (isosurfaces || shade)
  {
    std::ostringstream message;
    message << "rendering the " << scalar.Describe() << ", constant in each cell: "
            << (isosurfaces ? "isosurfaces are not drawn" : "") << (isosurfaces && shade ? " and " : "")
            << (shade ? "volume shading is off" : "") << " (" << (isosurfaces && shade ? "both need" : "it needs")
            << " a field that varies inside cells)";
    this->WarnOnce("cell scalar limits", message.str());
  }
  return true;
}

vtkUnstructuredVolumeFrameStatistics* vtkUnstructuredVolumeMapper::GetFrameStatistics()
{
  this->Base->Statistics->Clear();
  this->ReportStatistics(this->Base->Statistics);
  return this->Base->Statistics;
}

void vtkUnstructuredVolumeMapper::ReportStatistics(vtkUnstructuredVolumeFrameStatistics* statistics)
{
  statistics->SetValue("MeshBuilds", this->MeshUpdates.Builds);
  statistics->SetValue("PointRefreshes", this->MeshUpdates.PointRefreshes);
  statistics->SetValue("ValueRefreshes", this->MeshUpdates.ValueRefreshes);
  statistics->SetValue("TransferFunctionNodes", this->NumberOfTransferFunctionNodes);
  statistics->SetValue("CyclesBroken", static_cast<double>(this->NumberOfCyclesBroken));
  statistics->SetValue("GapConstraints", static_cast<double>(this->NumberOfGapConstraints));
  statistics->SetValue("UsedImageSampleDistance", this->Base->LastFrame.Distance);
  statistics->SetValue("InteractiveFrame", this->Base->LastFrame.Interactive ? 1.0 : 0.0);
  statistics->SetValue("FrameSeconds", this->Base->LastFrame.Seconds);
}

bool vtkUnstructuredVolumeMapper::CommitTransferFunction(vtkVolumeProperty* property, double offset,
  double scale, vtkuv::NormalisedTransferFunction& transferFunction, std::vector<uv::Isosurface>& drawnIsosurfaces,
  std::size_t maximumNodes)
{
  if (transferFunction.Update(property, offset, scale, this->TransferFunctionTolerance, maximumNodes) &&
    transferFunction.Resampled)
  {
    vtkWarningMacro("more than " << maximumNodes << " transfer-function nodes: resampled to that many");
  }
  this->NumberOfTransferFunctionNodes = static_cast<int>(transferFunction.Nodes.size());
  if (transferFunction.Nodes.empty())
  {
    vtkErrorMacro("the volume property has no scalar opacity function");
    return false;
  }
  drawnIsosurfaces = this->GetIsosurfaces().Drawn(offset, scale);
  return true;
}

bool vtkUnstructuredVolumeMapper::WarnOnce(const std::string& key, const std::string& message)
{
  if (!this->Base->WarningsGiven.insert(key).second)
  {
    return false;
  }
  vtkWarningMacro(<< message);
  return true;
}

bool vtkUnstructuredVolumeMapper::CheckArguments(vtkRenderer* renderer, vtkVolume* volume)
{
  if (!vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow()) || !volume || !volume->GetProperty())
  {
    vtkErrorMacro("needs an OpenGL render window and a volume with a property");
    return false;
  }
  vtkDataSet* input = this->GetDataSetInput();
  if (!input)
  {
    vtkErrorMacro("no input");
    return false;
  }
  return input->GetNumberOfCells() > 0 && input->GetNumberOfPoints() > 0; // an empty input draws nothing
}

void vtkUnstructuredVolumeMapper::UseContext(vtkOpenGLRenderWindow* window)
{
  if (this->Base->Context != window)
  {
    this->ReleaseGraphicsResources(this->Base->Context); // the old window's objects, in its context
    this->Base->Context = window;
  }
  window->MakeCurrent();
}

void vtkUnstructuredVolumeMapper::Render(vtkRenderer* renderer, vtkVolume* volume)
{
  if (!this->CheckArguments(renderer, volume))
  {
    return;
  }
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  const double start = vtkTimerLog::GetUniversalTime();
  const int buildsBefore = this->MeshUpdates.Builds;
  const double allowed = volume->GetAllocatedRenderTime();
  const bool interactive = this->AutoAdjustSampleDistances && uv::AdaptiveImageSampleDistance::IsInteractive(allowed);
  const double distance = this->ChooseImageSampleDistance(allowed);
  if (this->RenderFrame(renderer, volume, window, distance, interactive) && this->AutoAdjustSampleDistances)
  {
    glFinish(); // the frame's time is the GPU's too
  }
  this->TimeToDraw = vtkTimerLog::GetUniversalTime() - start;
  auto& last = this->Base->LastFrame;
  last.Distance = distance;
  last.Seconds = this->TimeToDraw;
  last.Interactive = interactive;
  if (this->MeshUpdates.Builds == buildsBefore) // a mesh build says nothing of the next frame
  {
    this->Base->Adaptive.Record(distance, this->TimeToDraw, allowed);
  }
}

double vtkUnstructuredVolumeMapper::ChooseImageSampleDistance(double allowedSeconds)
{
  if (!this->AutoAdjustSampleDistances)
  {
    return this->ImageSampleDistance;
  }
  uv::AdaptiveImageSampleDistance::Limits limits;
  limits.Still = this->ImageSampleDistance;
  limits.Minimum = this->MinimumImageSampleDistance;
  limits.Maximum = this->MaximumImageSampleDistance;
  return this->Base->Adaptive.Next(allowedSeconds, limits);
}

bool vtkUnstructuredVolumeMapper::RenderFrame(
  vtkRenderer* renderer, vtkVolume* volume, vtkOpenGLRenderWindow* window, double distance, bool interactive)
{
  vtkUnstructuredVolumeFrame frame = vtkUnstructuredVolumeFrame::Make(renderer, volume, window);
  frame.ReduceImage(distance);
  if (interactive)
  {
    frame.InteractiveReduction = distance / this->ImageSampleDistance;
  }
  if (frame.IsEmpty() || !this->WithinMemory("preparing the mesh", [&] { return this->Prepare(frame); }))
  {
    this->KeepTransparentImage(frame);
    return false;
  }
  this->UseContext(window);
  if (GLErrorChecks)
  {
    TakeGLErrors(); // what VTK left before the volume is not this mapper's
    uvgl::TakeDriverMessages();
  }
  const int refusedBefore = uvgl::Refusals().Count;
  bool uploaded = this->WithinMemory("uploading the mesh", [&] { return this->Upload(frame); });
  if (!GLErrorChecks && uploaded && GLOutOfMemory())
  {
    vtkErrorMacro("Cannot draw: the OpenGL driver ran out of memory uploading the mesh; nothing is drawn.");
    this->ReleaseMapperGraphics();
    uploaded = false;
  }
  this->CheckGLErrors("the upload");
  if (uvgl::Refusals().Count != refusedBefore)
  {
    vtkErrorMacro("Cannot draw: " << uvgl::Refusals().Last << "; nothing is drawn.");
    uploaded = false;
  }
  if (!uploaded)
  {
    this->KeepTransparentImage(frame);
    return true;
  }
  this->DrawAndComposite(frame);
  return true;
}

bool vtkUnstructuredVolumeMapper::WithinMemory(const char* step, const std::function<bool()>& run)
{
  try
  {
    return run();
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro("Cannot draw: host memory ran out " << step << " (" << this->GetDataSetInput()->GetNumberOfCells()
                                                      << " cells); nothing is drawn.");
  }
  catch (const std::length_error&)
  {
    vtkErrorMacro("Cannot draw: the mesh is too large for this mapper's arrays " << step << " ("
                                                      << this->GetDataSetInput()->GetNumberOfCells()
                                                      << " cells); nothing is drawn.");
  }
  this->ReleaseMapperGraphics();
  this->ForgetMesh();
  return false;
}

void vtkUnstructuredVolumeMapper::GetDrawnBounds(double bounds[6])
{
  this->GetBounds(bounds);
}

void vtkUnstructuredVolumeMapper::KeepTransparentImage(const vtkUnstructuredVolumeFrame& frame)
{
  if (!this->KeepFloatImage)
    return;
  vtkSmartPointer<vtkImageData>& image = this->Base->FloatImage;
  if (!image)
    image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(std::max(frame.Width, 0), std::max(frame.Height, 0), 1);
  image->AllocateScalars(VTK_FLOAT, 4);
  image->GetPointData()->GetScalars()->Fill(0.0);
}

bool vtkUnstructuredVolumeMapper::DrawAndComposite(const vtkUnstructuredVolumeFrame& frame)
{
  vtkUnstructuredVolumeFloatTarget& target = this->Base->Target;
  target.Resize(frame.Window, frame.Width, frame.Height, frame.TileWidth, frame.TileHeight);
  if (frame.OpaqueDepth && !target.CopySceneDepth(frame.OriginX, frame.OriginY))
  {
    this->WarnOnce("multisample",
      "multisampled render window: opaque geometry does not clip the volume (set MultiSamples to 0)");
  }
  // Every state a mapper's passes may change is restored when this scope ends.
  vtkOpenGLState* state = frame.Window->GetState();
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

  target.Bind();
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  // Only the pixels the drawn bounds can cover are cleared and composited: the image is transparent
  // everywhere else (the clear also takes back the last frame's pixels).
  double bounds[6];
  this->GetDrawnBounds(bounds);
  const uv::PixelRectangle volumePixels =
    uv::BoundsPixels(bounds, frame.EyeToClip * frame.WorldToEye * frame.VolumeToWorld, frame.Width, frame.Height);
  target.Clear(volumePixels);
  if (!frame.OpaqueDepth)
  {
    target.ClearSceneDepth(); // nothing drawn before the volumes: no copy to pay for
  }
  this->CheckGLErrors("binding and clearing the float target");
  const bool drawn = this->Draw(frame, target);
  if (drawn && this->KeepFloatImage)
  {
    target.ReadBack(this->Base->FloatImage);
    this->CheckGLErrors("reading the float image back");
  }
  target.Unbind();
  if (!drawn)
  {
    this->KeepTransparentImage(frame);
    return false;
  }
  // The composite blends over the volume's pixels (its own scissor): no depth test left from the passes.
  state->vtkglDisable(GL_DEPTH_TEST);
  if (!target.Composite(frame.OriginX, frame.OriginY, volumePixels))
  {
    vtkErrorMacro("the composite shaders failed to compile or link");
    return false;
  }
  return this->CheckGLErrors("the blend into the scene");
}

void vtkUnstructuredVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  vtkOpenGLRenderWindow* context = this->Base->Context;
  // The objects live in one window's context: another window (a renderer of it dropping a shared
  // volume, or closing) has none of them to release.
  if (!context || (window && window != context))
    return;
  // Buffers and vertex arrays are deleted by name in whichever context is current: make it theirs.
  context->PushContext();
  this->ReleaseMapperGraphics();
  this->Base->Target.Release();
  context->PopContext();
  this->Base->Context = nullptr;
}

void vtkUnstructuredVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Isosurfaces: " << this->Base->Isosurfaces.Size() << "\n";
  os << indent << "KeepFloatImage: " << this->KeepFloatImage << "\n";
  os << indent << "ImageSampleDistance: " << this->ImageSampleDistance << "\n";
  os << indent << "AutoAdjustSampleDistances: " << this->AutoAdjustSampleDistances << " (from "
     << this->MinimumImageSampleDistance << " to " << this->MaximumImageSampleDistance << ")\n";
  os << indent << "ProjectionRoute: " << (this->ProjectionRoute == VERTEX_PULLING ? "VertexPulling" : "GeometryShader")
     << "\n";
  os << indent << "SkipInvisibleCells: " << this->SkipInvisibleCells << "\n";
  os << indent << "OpacityThreshold: " << this->OpacityThreshold << "\n";
  os << indent << "TransferFunctionTolerance: " << this->TransferFunctionTolerance << "\n";
  os << indent << "VisibilityOrder: " << (this->VisibilityOrder == FACE_ORDER ? "FaceOrder" : "CentroidOrder") << "\n";
  os << indent << "SegmentIntegration: "
     << (this->SegmentIntegration == AUTOMATIC ? "Automatic" : this->SegmentIntegration == TABLE ? "Table" : "Exact")
     << "\n";
  os << indent << "GradientMode: " << (this->GradientMode == VERTEX_GRADIENTS ? "VertexGradients" : "CellGradients")
     << "\n";
  os << indent << "GradientArrayName: " << (this->GradientArrayName ? this->GradientArrayName : "(none)") << "\n";
  // What the mesh updates redid (readable where the mapper is not wrapped, as in ParaView's Python).
  os << indent << "MeshBuilds: " << this->MeshUpdates.Builds << "\n";
  os << indent << "PointRefreshes: " << this->MeshUpdates.PointRefreshes << "\n";
  os << indent << "ValueRefreshes: " << this->MeshUpdates.ValueRefreshes << "\n";
  // The last frame's reduction (AutoAdjustSampleDistances), readable there too.
  os << indent << "InteractiveFrame: " << this->Base->LastFrame.Interactive << "\n";
  os << indent << "UsedImageSampleDistance: " << this->Base->LastFrame.Distance << "\n";
  os << indent << "FrameSeconds: " << this->Base->LastFrame.Seconds << "\n";
}

void vtkUnstructuredVolumeMapper::UpdateVertexGradients(vtkuv::VertexGradientCache& gradients, vtkDataSet* cells,
  const vtkuv::RenderedScalar& scalar, std::uint64_t meshVersion)
{
  bool ignoredArray = false;
  gradients.Update(cells, scalar, meshVersion, this->GradientArrayName, ignoredArray);
  if (ignoredArray)
  {
    vtkWarningMacro(
      "the gradient array '" << this->GradientArrayName << "' does not have 3 components; computing gradients");
  }
}
