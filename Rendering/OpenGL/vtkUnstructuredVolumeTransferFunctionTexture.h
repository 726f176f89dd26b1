/**
 * @class vtkUnstructuredVolumeTransferFunctionTexture
 * @brief The transfer function as uvTransferFunctionLib.glsl reads it: nodes and the Psi table.
 *
 * Up to uvgl::MaximumUniformNodes nodes go to the shader as uniforms (cheaper to read than a texture
 * on CPU rasterisers), more through a texture (the shader is then compiled with UV_NODE_TEXTURE,
 * see uvgl::TransferFunctionDefines). The Psi table (partial pre-integration) is made once per
 * process and uploaded once per context. Sync uploads the node texture only when the nodes change.
 * (OpenGL layer; not wrapped.)
 */
#ifndef vtkUnstructuredVolumeTransferFunctionTexture_h
#define vtkUnstructuredVolumeTransferFunctionTexture_h

#include "uvOpticalModel.h"
#include "uvPreIntegration.h"
#include "vtkUnstructuredVolumeOpenGL.h"
#include "vtkUnstructuredVolumeTexture.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"

#include <vector>

class vtkUnstructuredVolumeTransferFunctionTexture
{
public:
  /// True when the nodes changed since the last Sync (and were uploaded, if they need the texture).
  bool Sync(vtkOpenGLRenderWindow* window, const std::vector<uv::TransferFunction::Node>& nodes)
  {
    if (!this->Psi.IsCreatedFor(window))
    {
      const uv::PsiTable& table = uv::SharedPsiTable();
      const int size = table.GetSize();
      this->Psi.Sync(window, size, size, 1, table.GetValues(), vtkUnstructuredVolumeTexture::Filter::Linear);
    }
    const bool changed = nodes != this->Nodes;
    this->Nodes = nodes;
    if (uvgl::NodesNeedTexture(nodes))
    {
      this->NodeTexture.Sync(window, static_cast<int>(nodes.size()), 2, 4, uvgl::TransferFunctionTexels(nodes));
    }
    return changed;
  }

  /// Binds the textures and sets the library's uniforms for the nodes of the last Sync.
  void Bind(vtkShaderProgram* program)
  {
    uvgl::SetTransferFunctionUniforms(program, this->Nodes);
    if (uvgl::NodesNeedTexture(this->Nodes))
      this->NodeTexture.Bind(program, "transferFunction");
    this->Psi.Bind(program, "psiTable");
  }
  void Unbind()
  {
    if (uvgl::NodesNeedTexture(this->Nodes))
      this->NodeTexture.Unbind();
    this->Psi.Unbind();
  }

  const std::vector<uv::TransferFunction::Node>& GetNodes() const { return this->Nodes; }

  void Release()
  {
    this->NodeTexture.Release();
    this->Psi.Release();
    this->Nodes.clear();
  }

private:
  vtkUnstructuredVolumeTexture NodeTexture, Psi;
  std::vector<uv::TransferFunction::Node> Nodes;
};

#endif
