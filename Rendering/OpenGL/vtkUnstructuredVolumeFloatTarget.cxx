#include "vtkUnstructuredVolumeFloatTarget.h"

#include "vtkUnstructuredVolumeOpenGL.h"

#include "vtkImageData.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkTextureObject.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

vtkUnstructuredVolumeFloatTarget::vtkUnstructuredVolumeFloatTarget() = default;

vtkUnstructuredVolumeFloatTarget::~vtkUnstructuredVolumeFloatTarget() = default;

void vtkUnstructuredVolumeFloatTarget::Resize(
  vtkOpenGLRenderWindow* window, int width, int height, int tileWidth, int tileHeight)
{
  if (window == this->Context && width == this->Width && height == this->Height && tileWidth == this->TileWidth &&
    tileHeight == this->TileHeight)
  {
    return;
  }
  this->Width = width;
  this->Height = height;
  this->TileWidth = tileWidth;
  this->TileHeight = tileHeight;
  this->SceneDepth->SetContext(window);
  this->SceneDepth->AllocateDepth(width, height, vtkTextureObject::Float32);
  this->SceneDepthIsFar = false;
  this->Color->SetContext(window);
  // A reduced image is stretched over its tile: filtered, its edge texels not wrapped around. At
  // the tile's size nearest sampling copies the image exactly.
  const int filter = this->Reduced() ? vtkTextureObject::Linear : vtkTextureObject::Nearest;
  this->Color->SetMinificationFilter(filter);
  this->Color->SetMagnificationFilter(filter);
  this->Color->SetWrapS(vtkTextureObject::ClampToEdge);
  this->Color->SetWrapT(vtkTextureObject::ClampToEdge);
  this->Color->Allocate2D(width, height, 4, VTK_FLOAT);
  this->ColorIsNew = true;
  if (this->Reduced())
  {
    this->TileDepth->SetContext(window);
    this->TileDepth->AllocateDepth(tileWidth, tileHeight, vtkTextureObject::Float32);
    this->TileFramebuffer->SetContext(window);
    this->TileFramebuffer->SaveCurrentBindingsAndBuffers();
    this->TileFramebuffer->Bind();
    this->TileFramebuffer->AddDepthAttachment(this->TileDepth);
    this->TileFramebuffer->DeactivateDrawBuffers(); // depth only: complete without a colour image
    this->TileFramebuffer->DeactivateReadBuffer();
    this->TileFramebuffer->RestorePreviousBindingsAndBuffers();
  }
  else if (this->TileDepth->GetHandle())
  {
    this->TileDepth->ReleaseGraphicsResources(window);
    this->TileFramebuffer->ReleaseGraphicsResources(window);
  }
  this->Framebuffer->SetContext(window);
  this->Framebuffer->SaveCurrentBindingsAndBuffers();
  this->Framebuffer->Bind();
  this->Framebuffer->AddColorAttachment(0, this->Color);
  this->Framebuffer->ActivateDrawBuffers(1);
  this->Framebuffer->RestorePreviousBindingsAndBuffers();
  this->Context = window;
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
  this->SceneDepthIsFar = false;
  if (!this->Reduced())
  {
    return uvgl::CopySceneDepth(this->SceneDepth, originX, originY, this->Width, this->Height);
  }
  const bool copied = uvgl::CopySceneDepth(this->TileDepth, originX, originY, this->TileWidth, this->TileHeight);
  // Each image pixel takes the depth nearest its centre (a blit between two Float32 depth images).
  this->AttachDepth(this->SceneDepth);
  this->TileFramebuffer->SaveCurrentBindingsAndBuffers();
  this->TileFramebuffer->Bind(GL_READ_FRAMEBUFFER);
  this->Framebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  this->Context->GetState()->vtkglBlitFramebuffer(0, 0, this->TileWidth, this->TileHeight, 0, 0, this->Width,
    this->Height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  this->TileFramebuffer->RestorePreviousBindingsAndBuffers();
  this->AttachDepth(nullptr);
  return copied;
}

void vtkUnstructuredVolumeFloatTarget::ClearSceneDepth()
{
  if (this->SceneDepthIsFar)
  {
    return;
  }
  vtkTextureObject* attached = this->AttachedDepth;
  this->AttachDepth(this->SceneDepth);
  vtkOpenGLState* state = this->Context->GetState();
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  state->vtkglDepthMask(GL_TRUE); // a clear writes only where depth writes are on
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_DEPTH_BUFFER_BIT);
  this->AttachDepth(attached);
  this->SceneDepthIsFar = true;
}

void vtkUnstructuredVolumeFloatTarget::Bind()
{
  this->Framebuffer->SaveCurrentBindingsAndBuffers();
  this->Framebuffer->Bind();
  this->Framebuffer->ActivateDrawBuffers(1);
  this->Context->GetState()->vtkglViewport(0, 0, this->Width, this->Height);
}

void vtkUnstructuredVolumeFloatTarget::Clear(const uv::PixelRectangle& drawn)
{
  const uv::PixelRectangle cleared =
    this->ColorIsNew ? uv::PixelRectangle{ 0, 0, this->Width, this->Height } : uv::UnitePixels(drawn, this->LastDrawn);
  this->ColorIsNew = false;
  this->LastDrawn = drawn;
  vtkOpenGLState* state = this->Context->GetState();
  vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglScissor scissorBoxSaver(state);
  state->vtkglEnable(GL_SCISSOR_TEST);
  state->vtkglScissor(cleared[0], cleared[1], cleared[2], cleared[3]);
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

bool vtkUnstructuredVolumeFloatTarget::Composite(int originX, int originY, const uv::PixelRectangle& drawn)
{
  const uv::PixelRectangle tile = this->Reduced()
    ? uv::StretchedPixels(drawn, this->Width, this->Height, this->TileWidth, this->TileHeight)
    : drawn;
  vtkOpenGLState* state = this->Context->GetState();
  vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglScissor scissorBoxSaver(state);
  state->vtkglEnable(GL_SCISSOR_TEST);
  state->vtkglScissor(originX + tile[0], originY + tile[1], tile[2], tile[3]);
  return uvgl::CompositeIntoScene(
    this->Context, this->Color, this->NoAttributes, originX, originY, this->TileWidth, this->TileHeight);
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
    this->TileDepth->ReleaseGraphicsResources(this->Context);
    this->TileFramebuffer->ReleaseGraphicsResources(this->Context);
  }
  this->NoAttributes->ReleaseGraphicsResources();
  this->Context = nullptr;
  this->AttachedDepth = nullptr;
  this->SceneDepthIsFar = false;
  this->ColorIsNew = true;
  this->Width = this->Height = this->TileWidth = this->TileHeight = 0;
}
