/**
 * @class vtkBarycentricShellIsosurfacePeelPass
 * @brief vtkBarycentricShellMapper's isosurfaces before the shells, by depth peeling.
 *
 * Each pass over the tetrahedra that hold an isovalue (uvBarycentricShellIsosurfaceFS.glsl) keeps
 * each pixel's nearest crossing beyond the previous layer's: one layer of lit colour and of distance
 * per pass, until a pass finds none or every layer is drawn. The blend pass composites each at its
 * distance. Owns the layers, their depth, the previous layer's distances, the framebuffer and the
 * list of isosurface cells. (OpenGL layer of the barycentric shell mapper; not wrapped.)
 */
#ifndef vtkBarycentricShellIsosurfacePeelPass_h
#define vtkBarycentricShellIsosurfacePeelPass_h

#include "vtkUnstructuredVolumeCellDrawer.h"
#include "vtkUnstructuredVolumeBufferTexture.h"
#include "vtkUnstructuredVolumeOpenGL.h"

#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkType.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

#include <cstdint>
#include <utility>
#include <vector>

class vtkBarycentricShellIsosurfacePeelPass
{
public:
  /// Up to `layers` layers of width x height.
  void Resize(vtkOpenGLRenderWindow* window, int width, int height, int layers)
  {
    if (window == this->Context && width == this->Width && height == this->Height && layers == this->Layers)
      return;
    for (auto [texture, components] : { std::make_pair(this->Color.Get(), 4), std::make_pair(this->Distance.Get(), 1) })
    {
      texture->SetContext(window);
      texture->SetMinificationFilter(vtkTextureObject::Nearest);
      texture->SetMagnificationFilter(vtkTextureObject::Nearest);
      texture->Allocate3D(width, height, layers, components, VTK_FLOAT);
    }
    this->Depth->SetContext(window);
    this->Depth->AllocateDepth(width, height, vtkTextureObject::Float32);
    uvgl::AllocateFloatImage(this->PreviousLayer, window, width, height, 1);
    this->Framebuffer->SetContext(window); // its layers are attached pass by pass
    this->Context = window;
    this->Width = width;
    this->Height = height;
    this->Layers = layers;
  }

  /// The cells holding an isovalue (uploaded when `version` is new; none is drawn from an empty list).
  void SyncCells(vtkOpenGLRenderWindow* window, const std::vector<std::uint32_t>& cells, std::uint64_t version)
  {
    if (!cells.empty())
      this->Cells.Sync(window, cells, 1, version);
  }

  /// Draws the layers with `program` (bound, its cell uniforms set) over the `cells` isosurface cells;
  /// returns the layers that found a crossing and adds the tetrahedra drawn to `drawn`. Calls
  /// `checkGLErrors(pass)` after each layer (the mapper's GL-error debug mode).
  template <typename CheckGLErrors>
  int Run(vtkOpenGLState* state, vtkShaderProgram* program, vtkUnstructuredVolumeCellDrawer& drawer, std::size_t cells,
    vtkIdType& drawn, const CheckGLErrors& checkGLErrors)
  {
    this->PreviousLayer->Activate();
    program->SetUniformi("previousLayer", this->PreviousLayer->GetTextureUnit());
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_LESS);
    state->vtkglDisable(GL_BLEND);
    int found = 0;
    for (int layer = 0; layer < this->Layers; ++layer)
    {
      this->BindLayer(state, layer);
      program->SetUniformi("layer", layer);
      const GLuint samples = uvgl::SamplesPassed([&] { drawer.Draw(state, program, this->Cells, 0, cells); });
      checkGLErrors("an isosurface layer of the shells");
      drawn += static_cast<vtkIdType>(cells);
      if (samples == 0)
        break; // no pixel has another crossing
      ++found;
      if (layer + 1 < this->Layers)
      {
        // The next pass starts beyond this layer's hits.
        this->Framebuffer->ActivateReadBuffer(1);
        this->PreviousLayer->CopyFromFrameBuffer(0, 0, 0, 0, this->Width, this->Height);
        checkGLErrors("the copy of an isosurface layer of the shells");
      }
    }
    this->PreviousLayer->Deactivate();
    return found;
  }

  /// The layers as the blend pass reads them (uniforms isosurfaceColor, isosurfaceDistance).
  void BindLayers(vtkShaderProgram* program)
  {
    this->Color->Activate();
    this->Distance->Activate();
    program->SetUniformi("isosurfaceColor", this->Color->GetTextureUnit());
    program->SetUniformi("isosurfaceDistance", this->Distance->GetTextureUnit());
  }
  void UnbindLayers()
  {
    this->Color->Deactivate();
    this->Distance->Deactivate();
  }

  std::size_t GetBytes() const { return this->Cells.GetBytes(); }

  void Release()
  {
    if (this->Context)
    {
      for (vtkTextureObject* texture :
        { this->Color.Get(), this->Distance.Get(), this->Depth.Get(), this->PreviousLayer.Get() })
        texture->ReleaseGraphicsResources(this->Context);
      this->Framebuffer->ReleaseGraphicsResources(this->Context);
    }
    this->Cells.Release();
    this->Context = nullptr;
    this->Width = this->Height = this->Layers = 0;
  }

private:
  static constexpr float NoHit = 3.0e38f; // the distance of a pixel without a crossing

  /// Layer `layer` of colour and distance as the draw buffers, cleared, with a cleared depth.
  void BindLayer(vtkOpenGLState* state, int layer)
  {
    this->Framebuffer->Bind();
    // Removed first: re-adding the same texture with another layer would keep the old layer.
    this->Framebuffer->RemoveColorAttachments(2);
    this->Framebuffer->AddColorAttachment(0, this->Color, layer);
    this->Framebuffer->AddColorAttachment(1, this->Distance, layer);
    this->Framebuffer->AddDepthAttachment(this->Depth);
    this->Framebuffer->ActivateDrawBuffers(2);
    const float noColor[4] = { 0.0f, 0.0f, 0.0f, 0.0f }, noHit[4] = { NoHit, 0.0f, 0.0f, 0.0f };
    glClearBufferfv(GL_COLOR, 0, noColor);
    glClearBufferfv(GL_COLOR, 1, noHit);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglClear(GL_DEPTH_BUFFER_BIT);
  }

  vtkNew<vtkTextureObject> Color, Distance, Depth, PreviousLayer;
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  vtkUnstructuredVolumeBufferTexture Cells;
  vtkOpenGLRenderWindow* Context = nullptr;
  int Width = 0, Height = 0, Layers = 0;
};

#endif
