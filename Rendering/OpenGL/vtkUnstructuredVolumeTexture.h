/**
 * @class vtkUnstructuredVolumeTexture
 * @brief A small 2D float texture (transfer-function nodes, isosurfaces, tables) that uploads only
 * when its texels change.
 *
 * Sync compares the texels with the copy it holds, so there is no key to get wrong: whatever the
 * texels were computed from (property, normalisation, isosurface list), equal texels are not
 * uploaded again and different ones always are. Meant for textures of at most a few hundred
 * thousand texels, where the comparison costs far less than a frame. (OpenGL layer; not wrapped.)
 */
#ifndef vtkUnstructuredVolumeTexture_h
#define vtkUnstructuredVolumeTexture_h

#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <vector>

class vtkUnstructuredVolumeTexture
{
public:
  enum class Filter
  {
    Nearest,
    Linear
  };

  /// Uploads width x height texels of `components` floats unless the same ones are on the GPU. True
  /// when it uploaded.
  bool Sync(vtkOpenGLRenderWindow* window, int width, int height, int components, const std::vector<float>& texels,
    Filter filter = Filter::Nearest)
  {
    if (window == this->Context && this->Texture->GetHandle() && width == this->Width && height == this->Height &&
      components == this->Components && filter == this->Filtering && texels == this->Texels)
    {
      return false;
    }
    const int mode = filter == Filter::Linear ? vtkTextureObject::Linear : vtkTextureObject::Nearest;
    this->Texture->SetContext(window);
    this->Texture->SetMinificationFilter(mode);
    this->Texture->SetMagnificationFilter(mode);
    this->Texture->SetWrapS(vtkTextureObject::ClampToEdge);
    this->Texture->SetWrapT(vtkTextureObject::ClampToEdge);
    this->Texture->Create2DFromRaw(width, height, components, VTK_FLOAT, const_cast<float*>(texels.data()));
    this->Context = window;
    this->Width = width;
    this->Height = height;
    this->Components = components;
    this->Filtering = filter;
    this->Texels = texels;
    return true;
  }

  /// True when a texture was made in `window` (whatever its texels).
  bool IsCreatedFor(vtkOpenGLRenderWindow* window) const
  {
    return window == this->Context && this->Texture->GetHandle();
  }

  void Bind(vtkShaderProgram* program, const char* name)
  {
    this->Texture->Activate();
    program->SetUniformi(name, this->Texture->GetTextureUnit());
  }
  void Unbind() { this->Texture->Deactivate(); }
  vtkTextureObject* GetTexture() { return this->Texture; }

  void Release()
  {
    if (this->Context)
    {
      this->Texture->ReleaseGraphicsResources(this->Context);
    }
    this->Context = nullptr;
    this->Texels.clear();
    this->Width = this->Height = this->Components = 0;
  }

private:
  vtkNew<vtkTextureObject> Texture;
  vtkOpenGLRenderWindow* Context = nullptr;
  int Width = 0, Height = 0, Components = 0;
  Filter Filtering = Filter::Nearest;
  std::vector<float> Texels;
};

#endif
