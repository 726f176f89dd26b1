/**
 * @class vtkUnstructuredVolumeTexture3D
 * @brief A linearly filtered 3D float texture (a pre-integration table) that uploads only when the
 * version of what it holds changes.
 *
 * The texels are large (megabytes) and built from a key the caller already compares, so the caller
 * passes that build's version rather than the texels being compared. (OpenGL layer; not wrapped.)
 */
#ifndef vtkUnstructuredVolumeTexture3D_h
#define vtkUnstructuredVolumeTexture3D_h

#include "vtkUnstructuredVolumeOpenGL.h"

#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <cstdint>
#include <vector>

class vtkUnstructuredVolumeTexture3D
{
public:
  /// Uploads width x height x depth texels of 4 floats unless this version is on the GPU of
  /// `window`. True when it uploaded.
  bool Sync(vtkOpenGLRenderWindow* window, int width, int height, int depth, const std::vector<float>& texels,
    std::uint64_t version)
  {
    if (window == this->Context && this->Texture->GetHandle() && version == this->Version)
      return false;
    uvgl::UploadTrilinearVolume(this->Texture, window, width, height, depth, 4, texels.data());
    this->Context = window;
    this->Version = version;
    this->Bytes = sizeof(float) * texels.size();
    return true;
  }

  void Bind(vtkShaderProgram* program, const char* name)
  {
    this->Texture->Activate();
    program->SetUniformi(name, this->Texture->GetTextureUnit());
  }
  void Unbind() { this->Texture->Deactivate(); }
  std::size_t GetBytes() const { return this->Context ? this->Bytes : 0; }

  void Release()
  {
    if (this->Context)
      this->Texture->ReleaseGraphicsResources(this->Context);
    this->Context = nullptr;
    this->Version = 0;
    this->Bytes = 0;
  }

private:
  vtkNew<vtkTextureObject> Texture;
  vtkOpenGLRenderWindow* Context = nullptr;
  std::uint64_t Version = 0;
  std::size_t Bytes = 0;
};

#endif
