/**
 * @class vtkBarycentricShellSlicePass
 * @brief vtkBarycentricShellMapper's slicing of one shell.
 *
 * The shell's tetrahedra sample its slices (uvBarycentricShellSliceFS.glsl), MAX-blended into float
 * targets of four slices each, over the mask's depth. Owns the targets, their framebuffer and the
 * list of every shell's cells (the buckets' concatenation, uvShellBuckets.h). (OpenGL layer of the
 * barycentric shell mapper; not wrapped.)
 */
#ifndef vtkBarycentricShellSlicePass_h
#define vtkBarycentricShellSlicePass_h

#include "vtkUnstructuredVolumeCellDrawer.h"
#include "vtkBarycentricShellPrograms.h"
#include "vtkUnstructuredVolumeBufferTexture.h"
#include "vtkUnstructuredVolumeOpenGL.h"

#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

#include <array>
#include <cstdint>
#include <string>
#include <vector>

class vtkBarycentricShellSlicePass
{
public:
  static constexpr int MaximumTargets = 8; // four slices each (OpenGL 3.2 guarantees 8 draw buffers)

  /// `targets` float targets of width x height, with `mask` as their depth.
  void Resize(vtkOpenGLRenderWindow* window, int width, int height, int targets, vtkTextureObject* mask)
  {
    if (window == this->Context && width == this->Width && height == this->Height && targets == this->Targets)
      return;
    for (int t = 0; t < targets; ++t)
      uvgl::AllocateFloatImage(this->Slices[t], window, width, height, 4);
    this->Framebuffer->SetContext(window);
    this->Framebuffer->SaveCurrentBindingsAndBuffers();
    this->Framebuffer->Bind();
    this->Framebuffer->RemoveColorAttachments(MaximumTargets);
    for (int t = 0; t < targets; ++t)
      this->Framebuffer->AddColorAttachment(static_cast<unsigned int>(t), this->Slices[t]);
    this->Framebuffer->AddDepthAttachment(mask);
    this->Framebuffer->ActivateDrawBuffers(static_cast<unsigned int>(targets));
    this->Framebuffer->RestorePreviousBindingsAndBuffers();
    this->Context = window;
    this->Width = width;
    this->Height = height;
    this->Targets = targets;
  }

  /// Every shell's cells, one after the other (uploaded when `version` is new; none is drawn from
  /// an empty list).
  void SyncCells(vtkOpenGLRenderWindow* window, const std::vector<std::uint32_t>& cells, std::uint64_t version)
  {
    if (!cells.empty())
      this->Cells.Sync(window, cells, 1, version);
  }

  /// Binds the targets for drawing (the slices, and the mask pass's depth writes).
  void BindTargets()
  {
    this->Framebuffer->Bind();
    this->Framebuffer->ActivateDrawBuffers(static_cast<unsigned int>(this->Targets));
  }

  /// Clears the slices to "outside", then draws the `count` cells at list place `first` into them.
  void Run(vtkOpenGLState* state, const vtkBarycentricShellPrograms& programs, vtkShaderProgram* program,
    vtkUnstructuredVolumeCellDrawer& drawer, std::uint32_t first, std::uint32_t count, float shellStart)
  {
    this->BindTargets();
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
    if (count == 0)
      return;
    programs.Use(program);
    program->SetUniformf("shellStart", shellStart);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendEquation(GL_MAX);
    drawer.Draw(state, program, this->Cells, first, count);
    state->vtkglBlendEquation(GL_FUNC_ADD);
  }

  /// The slices as the blend pass reads them (uniforms slices0, slices1, ...).
  void BindSlices(vtkShaderProgram* program)
  {
    for (int t = 0; t < this->Targets; ++t)
    {
      this->Slices[t]->Activate();
      program->SetUniformi(("slices" + std::to_string(t)).c_str(), this->Slices[t]->GetTextureUnit());
    }
  }
  void UnbindSlices()
  {
    for (int t = 0; t < this->Targets; ++t)
      this->Slices[t]->Deactivate();
  }

  std::size_t GetBytes() const { return this->Cells.GetBytes(); }

  void Release()
  {
    if (this->Context)
    {
      for (auto& slice : this->Slices)
        slice->ReleaseGraphicsResources(this->Context);
      this->Framebuffer->ReleaseGraphicsResources(this->Context);
    }
    this->Cells.Release();
    this->Context = nullptr;
    this->Width = this->Height = this->Targets = 0;
  }

private:
  std::array<vtkNew<vtkTextureObject>, MaximumTargets> Slices;
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  vtkUnstructuredVolumeBufferTexture Cells;
  vtkOpenGLRenderWindow* Context = nullptr;
  int Width = 0, Height = 0, Targets = 0;
};

#endif
