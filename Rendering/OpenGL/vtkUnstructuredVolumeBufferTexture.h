/**
 * @class vtkUnstructuredVolumeBufferTexture
 * @brief A GPU buffer texture that knows which version of its data it holds.
 *
 * Sync(window, values, components, version) uploads only when `version` differs from the one it
 * holds (or the context changed); Release forgets both. Callers number their data's versions from
 * 1 (a counter bumped on every change, or a vtkMTimeType), so a released or new texture (version 0)
 * always uploads. This replaces per-mapper "on GPU" flags, which had to be reset by hand.
 * (OpenGL layer; not wrapped.)
 */
#ifndef vtkUnstructuredVolumeBufferTexture_h
#define vtkUnstructuredVolumeBufferTexture_h

#include "vtkUnstructuredVolumeOpenGL.h"

#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <cstdint>
#include <vector>

class vtkUnstructuredVolumeBufferTexture
{
public:
  /// Uploads `values` (32-bit; `components` per texel) unless this version is already held. True
  /// when it uploaded, or tried to: over the driver's limit it holds nothing (uvgl::Refusals()).
  template <typename T>
  bool Sync(vtkOpenGLRenderWindow* window, const std::vector<T>& values, int components, std::uint64_t version)
  {
    if (version == this->Version && window == this->Context && this->Texture->GetHandle())
    {
      return false;
    }
    if (!uvgl::UploadBufferTexture(window, this->Buffer, this->Texture, values, components))
    {
      this->Release(); // over the driver's limit: noted in uvgl::Refusals(), held as nothing
      return true;
    }
    this->Context = window;
    this->Version = version;
    this->Bytes = sizeof(T) * values.size();
    return true;
  }

  /// Binds the texture to a unit and points the sampler uniform `name` of `program` at it.
  void Bind(vtkShaderProgram* program, const char* name)
  {
    this->Texture->Activate();
    program->SetUniformi(name, this->Texture->GetTextureUnit());
  }
  void Unbind() { this->Texture->Deactivate(); }

  bool Holds(std::uint64_t version) const { return this->Version == version && this->Texture->GetHandle(); }
  std::size_t GetBytes() const { return this->Version ? this->Bytes : 0; }
  vtkTextureObject* GetTexture() { return this->Texture; }

  void Release()
  {
    if (this->Context)
    {
      this->Texture->ReleaseGraphicsResources(this->Context);
    }
    this->Buffer->ReleaseGraphicsResources();
    this->Context = nullptr;
    this->Version = 0;
    this->Bytes = 0;
  }

private:
  vtkNew<vtkOpenGLBufferObject> Buffer;
  vtkNew<vtkTextureObject> Texture;
  vtkOpenGLRenderWindow* Context = nullptr;
  std::uint64_t Version = 0;
  std::size_t Bytes = 0;
};

#endif
