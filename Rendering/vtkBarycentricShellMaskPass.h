/**
 * @class vtkBarycentricShellMaskPass
 * @brief Early ray termination between vtkBarycentricShellMapper's shells.
 *
 * Pixels whose accumulated opacity reached the threshold get depth 0 in the mask
 * (uvBarycentricShellMaskFS.glsl, colour writes off), and the depth test (LESS) keeps later shells'
 * slicing and blending off them. Owns the mask, a depth texture attached to the float target and to
 * the slices' framebuffer. (OpenGL layer of the barycentric shell mapper; not wrapped.)
 */
#ifndef vtkBarycentricShellMaskPass_h
#define vtkBarycentricShellMaskPass_h

#include "vtkBarycentricShellPrograms.h"
#include "vtkUnstructuredVolumeFloatTarget.h"

#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

class vtkBarycentricShellMaskPass
{
public:
  void Resize(vtkOpenGLRenderWindow* window, int width, int height)
  {
    if (window == this->Context && width == this->Width && height == this->Height)
      return;
    this->Depth->SetContext(window);
    this->Depth->AllocateDepth(width, height, vtkTextureObject::Float32);
    this->Context = window;
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

  /// Masks the pixels of `accumulated` at or above the threshold `program` was given, into the bound
  /// framebuffer (the slices', whose depth the mask is).
  void Run(vtkOpenGLState* state, const vtkBarycentricShellPrograms& programs, vtkShaderProgram* program,
    vtkTextureObject* accumulated)
  {
    programs.Use(program);
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

  void Release()
  {
    if (this->Context)
      this->Depth->ReleaseGraphicsResources(this->Context);
    this->Context = nullptr;
    this->Width = this->Height = 0;
  }

private:
  vtkNew<vtkTextureObject> Depth;
  vtkOpenGLRenderWindow* Context = nullptr;
  int Width = 0, Height = 0;
};

#endif
