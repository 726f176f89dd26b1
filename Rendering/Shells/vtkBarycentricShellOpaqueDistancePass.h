/**
 * @class vtkBarycentricShellOpaqueDistancePass
 * @brief Once a frame, the distance of the scene's opaque geometry along each pixel's ray.
 *
 * From the float target's copy of the scene's depth (uvBarycentricOpaqueDistanceFS.glsl), so the
 * passes over the tetrahedra read one float instead of unprojecting a depth per fragment; an
 * occlusion query tells whether any pixel has opaque geometry at all (none, the common case of a
 * volume alone, spares every fragment the read). Owns the distance image and its framebuffer.
 * (OpenGL layer of vtkBarycentricShellMapper; not wrapped.)
 */
#ifndef vtkBarycentricShellOpaqueDistancePass_h
#define vtkBarycentricShellOpaqueDistancePass_h

#include "uvBarycentricOpaqueDistanceFS.h"
#include "uvFullScreenTriangleVS.h"
#include "vtkUnstructuredVolumeFloatTarget.h"
#include "vtkUnstructuredVolumeFrame.h"
#include "vtkUnstructuredVolumeOpenGL.h"

#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

class vtkBarycentricShellOpaqueDistancePass
{
public:
  void Resize(vtkOpenGLRenderWindow* window, int width, int height)
  {
    if (window == this->Context && width == this->Width && height == this->Height)
      return;
    uvgl::AllocateFloatImage(this->Distances, window, width, height, 1);
    this->Framebuffer->SetContext(window);
    this->Framebuffer->SaveCurrentBindingsAndBuffers();
    this->Framebuffer->Bind();
    this->Framebuffer->AddColorAttachment(0, this->Distances);
    this->Framebuffer->ActivateDrawBuffers(1);
    this->Framebuffer->RestorePreviousBindingsAndBuffers();
    this->Context = window;
    this->Width = width;
    this->Height = height;
  }

  /// Writes the distances (an empty vertex array bound); false when the shaders do not compile. `any`
  /// tells whether a pixel has opaque geometry. Leaves the framebuffer it found bound.
  bool Run(const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target, bool& any)
  {
    vtkShaderProgram* program =
      frame.Window->GetShaderCache()->ReadyShaderProgram(uvFullScreenTriangleVS, uvBarycentricOpaqueDistanceFS, "");
    if (!program)
      return false;
    vtkOpenGLState* state = frame.Window->GetState();
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_SCISSOR_TEST);
    this->Framebuffer->SaveCurrentBindingsAndBuffers();
    this->Framebuffer->Bind();
    this->Framebuffer->ActivateDrawBuffers(1);
    const float none[4] = { NoGeometry, 0.0f, 0.0f, 0.0f };
    glClearBufferfv(GL_COLOR, 0, none);
    vtkTextureObject* sceneDepth = target.GetSceneDepth();
    sceneDepth->Activate();
    program->SetUniformi("opaqueDepth", sceneDepth->GetTextureUnit());
    uvgl::SetUniformMatrix(program, "clipToEye", glm::inverse(frame.EyeToClip));
    const float size[2] = { static_cast<float>(frame.Width), static_cast<float>(frame.Height) };
    program->SetUniform2f("viewportSize", size);
    program->SetUniformi("parallelProjection", frame.Parallel ? 1 : 0);
    any = uvgl::SamplesPassed([] { glDrawArrays(GL_TRIANGLES, 0, 3); }) > 0;
    sceneDepth->Deactivate();
    this->Framebuffer->RestorePreviousBindingsAndBuffers();
    return true;
  }

  /// The distances as uvBarycentricRayLib.glsl reads them (uniform opaqueDistances).
  void Bind(vtkShaderProgram* program)
  {
    this->Distances->Activate();
    program->SetUniformi("opaqueDistances", this->Distances->GetTextureUnit());
  }
  void Unbind() { this->Distances->Deactivate(); }

  void Release()
  {
    if (this->Context)
    {
      this->Distances->ReleaseGraphicsResources(this->Context);
      this->Framebuffer->ReleaseGraphicsResources(this->Context);
    }
    this->Context = nullptr;
    this->Width = this->Height = 0;
  }

private:
  static constexpr float NoGeometry = 3.0e38f; // the distance of a pixel without opaque geometry

  vtkNew<vtkTextureObject> Distances;
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  vtkOpenGLRenderWindow* Context = nullptr;
  int Width = 0, Height = 0;
};

#endif
