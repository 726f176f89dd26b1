/**
 * @class vtkUnstructuredVolumePeelImages
 * @brief The screen-sized images of the ray walks' depth peels, besides the float target: the entry
 * (ray parameter, boundary face) with its depth, the exit (where each walk left the mesh) and,
 * where asked for, a second accumulation image that the walks alternate with the target's colour.
 *
 * Shared by the hexahedral ray caster and the tetrahedra mapper's ray walk, which peel the same way.
 * Reallocated only when the window or the frame's size changes. (OpenGL layer; not wrapped.)
 */
#ifndef vtkUnstructuredVolumePeelImages_h
#define vtkUnstructuredVolumePeelImages_h

#include "vtkUnstructuredVolumeFloatTarget.h"
#include "vtkUnstructuredVolumeOpenGL.h"

#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureObject.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

#include <vector>

class vtkUnstructuredVolumePeelImages
{
public:
  explicit vtkUnstructuredVolumePeelImages(bool withAccumulation)
    : WithAccumulation(withAccumulation)
  {
  }

  vtkNew<vtkTextureObject> Entry, EntryDepth, Exit, Accumulation;
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;

  void Resize(vtkOpenGLRenderWindow* window, int width, int height)
  {
    if (window == this->Context && width == this->Width && height == this->Height)
    {
      return;
    }
    for (vtkTextureObject* texture : this->ColourImages())
      uvgl::AllocateFloatImage(texture, window, width, height, 4);
    this->EntryDepth->SetContext(window);
    this->EntryDepth->AllocateDepth(width, height, vtkTextureObject::Float32);
    this->Framebuffer->SetContext(window);
    this->Context = window;
    this->Width = width;
    this->Height = height;
  }

  /// Starts an entry pass on the bound framebuffer: Entry and EntryDepth attached and cleared to "no
  /// entry" (green -1) and the far depth, the depth test keeping each pixel's nearest face.
  void BeginEntryPass(vtkOpenGLState* state)
  {
    this->Framebuffer->AddColorAttachment(0, this->Entry);
    this->Framebuffer->AddDepthAttachment(this->EntryDepth);
    this->Framebuffer->ActivateDrawBuffers(1);
    state->vtkglClearColor(0.0f, -1.0f, 0.0f, 0.0f);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_LESS);
  }

  /// Copies Accumulation into the target's colour; the framebuffer must be bound.
  void CopyAccumulationInto(vtkUnstructuredVolumeFloatTarget& target)
  {
    this->Framebuffer->AddColorAttachment(0, this->Accumulation);
    this->Framebuffer->ActivateReadBuffer(0);
    target.GetFramebuffer()->Bind(GL_DRAW_FRAMEBUFFER);
    const int w = this->Width, h = this->Height;
    glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST); // float to float: exact
  }

  void Release()
  {
    if (this->Context)
    {
      for (vtkTextureObject* texture : this->ColourImages())
        texture->ReleaseGraphicsResources(this->Context);
      this->EntryDepth->ReleaseGraphicsResources(this->Context);
      this->Framebuffer->ReleaseGraphicsResources(this->Context);
    }
    this->Context = nullptr;
    this->Width = this->Height = 0;
  }

private:
  std::vector<vtkTextureObject*> ColourImages()
  {
    std::vector<vtkTextureObject*> images{ this->Entry.Get(), this->Exit.Get() };
    if (this->WithAccumulation)
      images.push_back(this->Accumulation.Get());
    return images;
  }

  const bool WithAccumulation;
  vtkOpenGLRenderWindow* Context = nullptr;
  int Width = 0, Height = 0;
};

#endif
