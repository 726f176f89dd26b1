/**
 * @class vtkUnstructuredVolumeIndexBuffer
 * @brief An element (index) buffer that knows which version of its indices it holds.
 *
 * As vtkUnstructuredVolumeBufferTexture, for indices drawn with glDrawElements: Sync uploads only a
 * new version; Release forgets it. (OpenGL layer; not wrapped.)
 */
#ifndef vtkUnstructuredVolumeIndexBuffer_h
#define vtkUnstructuredVolumeIndexBuffer_h

#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

#include <cstdint>
#include <vector>

class vtkUnstructuredVolumeIndexBuffer
{
public:
  /// True when it uploaded.
  bool Sync(const std::vector<std::uint32_t>& indices, std::uint64_t version)
  {
    if (version == this->Version && this->Buffer->GetHandle())
    {
      return false;
    }
    this->Buffer->Upload(indices, vtkOpenGLBufferObject::ElementArrayBuffer);
    this->Version = version;
    this->Count = indices.size();
    return true;
  }

  /// Draws `count` indices from index `first` as `mode` (GL_POINTS, GL_TRIANGLES).
  void Draw(GLenum mode, std::size_t count, std::size_t first = 0)
  {
    this->Buffer->Bind();
    glDrawElements(mode, static_cast<GLsizei>(count), GL_UNSIGNED_INT,
      reinterpret_cast<const void*>(first * sizeof(std::uint32_t)));
    this->Buffer->Release();
  }

  /// Draws the first `count` indices as `mode`, each index offset by `baseVertex` (so a repeating
  /// pattern can stand for every batch of vertices).
  void DrawFromVertex(GLenum mode, std::size_t count, std::size_t baseVertex)
  {
    this->Buffer->Bind();
    glDrawElementsBaseVertex(mode, static_cast<GLsizei>(count), GL_UNSIGNED_INT, nullptr, static_cast<GLint>(baseVertex));
    this->Buffer->Release();
  }

  bool Holds(std::uint64_t version) const { return this->Version == version && this->Buffer->GetHandle(); }
  std::size_t GetCount() const { return this->Version ? this->Count : 0; }
  std::size_t GetBytes() const { return sizeof(std::uint32_t) * this->GetCount(); }

  void Release()
  {
    this->Buffer->ReleaseGraphicsResources();
    this->Version = 0;
    this->Count = 0;
  }

private:
  vtkNew<vtkOpenGLBufferObject> Buffer;
  std::uint64_t Version = 0;
  std::size_t Count = 0;
};

#endif
