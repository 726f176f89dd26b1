/**
 * @class vtkUnstructuredVolumeOpacityMask
 * @brief Early ray termination for mappers that composite front to back in passes.
 *
 * Pixels whose accumulated opacity reached a threshold get depth 0 in the mask
 * (uvOpacityMaskFS.glsl, colour writes off); the passes after it draw with the depth test LESS at a
 * depth above 0, so the hardware's depth test discards their fragments on those pixels before they
 * are shaded. Owns the mask, a depth texture the mapper attaches to the framebuffers it draws into,
 * and (made on first use) a framebuffer holding only the mask, for mappers whose accumulated image
 * is the colour of the framebuffer they draw into (reading it there would be a feedback loop).
 * (OpenGL layer; not wrapped.)
 */
#ifndef vtkUnstructuredVolumeOpacityMask_h
#define vtkUnstructuredVolumeOpacityMask_h

#include "vtkUnstructuredVolumeFloatTarget.h"

#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

class vtkUnstructuredVolumeOpacityMask
{
public:
  void Resize(vtkOpenGLRenderWindow* window, int width, int height)
  {
    if (window == this->Context && width == this->Width && height == this->Height)
      return;
    this->Depth->SetContext(window);
    this->Depth->AllocateDepth(width, height, vtkTextureObject::Float32);
    this->Context = window;
    this->MaskOnlyReady = false; // made by the first RunAlone at this size
    this->Width = width;
    this->Height = height;
  }
  vtkTextureObject* GetDepth() { return this->Depth; }

  /// Attaches the mask to the bound float target and clears it: nothing is opaque yet.
  void AttachAndClear(vtkUnstructuredVolumeFloatTarget& target, vtkOpenGLState* state)
  {
    target.AttachDepth(this->Depth);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_DEPTH_BUFFER_BIT);
  }

  /// Masks the pixels of `accumulated` at or above the threshold the bound `program`
  /// (uvOpacityMaskFS.glsl) was given, into the bound framebuffer, which must not hold `accumulated`.
  void Run(vtkOpenGLState* state, vtkShaderProgram* program, vtkTextureObject* accumulated)
  {
    accumulated->Activate();
    program->SetUniformi("accumulated", accumulated->GetTextureUnit());
    state->vtkglDisable(GL_BLEND);
    state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglDepthFunc(GL_ALWAYS);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    state->vtkglDepthFunc(GL_LESS);
    state->vtkglDepthMask(GL_FALSE);
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    accumulated->Deactivate();
  }

  /// As Run, into the framebuffer that holds only the mask (the caller's bindings are restored and
  /// blending is left off).
  void RunAlone(vtkOpenGLState* state, vtkShaderProgram* program, vtkTextureObject* accumulated)
  {
    if (!this->MaskOnlyReady)
      this->MaskOnly->SetContext(this->Context);
    this->MaskOnly->SaveCurrentBindingsAndBuffers();
    this->MaskOnly->Bind();
    if (!this->MaskOnlyReady)
    {
      this->MaskOnly->AddDepthAttachment(this->Depth);
      this->MaskOnlyReady = true;
    }
    state->vtkglDrawBuffer(GL_NONE); // complete under OpenGL 3.2 without colour
    state->vtkglReadBuffer(GL_NONE);
    this->Run(state, program, accumulated);
    this->MaskOnly->RestorePreviousBindingsAndBuffers();
  }

  void Release()
  {
    if (this->Context)
    {
      this->Depth->ReleaseGraphicsResources(this->Context);
      this->MaskOnly->ReleaseGraphicsResources(this->Context);
    }
    this->Context = nullptr;
    this->MaskOnlyReady = false;
    this->Width = this->Height = 0;
  }

private:
  vtkNew<vtkTextureObject> Depth;
  vtkNew<vtkOpenGLFramebufferObject> MaskOnly;
  vtkOpenGLRenderWindow* Context = nullptr;
  bool MaskOnlyReady = false;
  int Width = 0, Height = 0;
};

#endif
