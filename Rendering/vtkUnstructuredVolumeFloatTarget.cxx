#include "vtkUnstructuredVolumeFloatTarget.h"

#include "vtkUnstructuredVolumeOpenGL.h"

#include "vtkImageData.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

vtkUnstructuredVolumeFloatTarget::vtkUnstructuredVolumeFloatTarget() = default;

vtkUnstructuredVolumeFloatTarget::~vtkUnstructuredVolumeFloatTarget() = default;

void vtkUnstructuredVolumeFloatTarget::Resize(vtkOpenGLRenderWindow* window, int width, int height)
{
  if (window == this->Context && width == this->Width && height == this->Height)
  {
    return;
  }
  this->SceneDepth->SetContext(window);
  this->SceneDepth->AllocateDepth(width, height, vtkTextureObject::Float32);
  this->Color->SetContext(window);
  this->Color->SetMinificationFilter(vtkTextureObject::Nearest);
  this->Color->SetMagnificationFilter(vtkTextureObject::Nearest);
  this->Color->Allocate2D(width, height, 4, VTK_FLOAT);
  this->Framebuffer->SetContext(window);
  this->Framebuffer->SaveCurrentBindingsAndBuffers();
  this->Framebuffer->Bind();
  this->Framebuffer->AddColorAttachment(0, this->Color);
  this->Framebuffer->ActivateDrawBuffers(1);
  this->Framebuffer->RestorePreviousBindingsAndBuffers();
  this->Context = window;
  this->Width = width;
  this->Height = height;
  this->AttachedDepth = nullptr; // reattached by the mapper against its resized depth
}

void vtkUnstructuredVolumeFloatTarget::AttachDepth(vtkTextureObject* depth)
{
  if (depth == this->AttachedDepth)
  {
    return;
  }
  // No Save/RestorePreviousBindingsAndBuffers here: the target is usually bound (Bind saved VTK's
  // bindings), and VTK's saved-bindings flag is per framebuffer, not a count, so a nested save on
  // the same framebuffer leaves the target bound after Unbind. Attaching binds and restores itself.
  if (depth)
    this->Framebuffer->AddDepthAttachment(depth);
  else
    this->Framebuffer->RemoveDepthAttachment();
  this->AttachedDepth = depth;
}

bool vtkUnstructuredVolumeFloatTarget::CopySceneDepth(int originX, int originY)
{
  return uvgl::CopySceneDepth(this->SceneDepth, originX, originY, this->Width, this->Height);
}

void vtkUnstructuredVolumeFloatTarget::Bind()
{
  this->Framebuffer->SaveCurrentBindingsAndBuffers();
  this->Framebuffer->Bind();
  this->Framebuffer->ActivateDrawBuffers(1);
  this->Context->GetState()->vtkglViewport(0, 0, this->Width, this->Height);
}

void vtkUnstructuredVolumeFloatTarget::Clear()
{
  vtkOpenGLState* state = this->Context->GetState();
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
}

void vtkUnstructuredVolumeFloatTarget::ReadBack(vtkSmartPointer<vtkImageData>& image)
{
  uvgl::ReadFloatImage(this->Framebuffer, 0, this->Width, this->Height, image);
}

void vtkUnstructuredVolumeFloatTarget::Unbind()
{
  this->Framebuffer->RestorePreviousBindingsAndBuffers();
}

bool vtkUnstructuredVolumeFloatTarget::Composite(int originX, int originY)
{
  return uvgl::CompositeIntoScene(
    this->Context, this->Color, this->NoAttributes, originX, originY, this->Width, this->Height);
}

vtkTextureObject* vtkUnstructuredVolumeFloatTarget::GetColor()
{
  return this->Color;
}

vtkTextureObject* vtkUnstructuredVolumeFloatTarget::GetSceneDepth()
{
  return this->SceneDepth;
}

vtkOpenGLFramebufferObject* vtkUnstructuredVolumeFloatTarget::GetFramebuffer()
{
  return this->Framebuffer;
}

vtkOpenGLVertexArrayObject* vtkUnstructuredVolumeFloatTarget::GetNoAttributes()
{
  return this->NoAttributes;
}

void vtkUnstructuredVolumeFloatTarget::Release()
{
  if (this->Context)
  {
    this->Color->ReleaseGraphicsResources(this->Context);
    this->SceneDepth->ReleaseGraphicsResources(this->Context);
    this->Framebuffer->ReleaseGraphicsResources(this->Context);
  }
  this->NoAttributes->ReleaseGraphicsResources();
  this->Context = nullptr;
  this->AttachedDepth = nullptr;
  this->Width = this->Height = 0;
}
