// The OpenGL steps every mapper of this module takes the same way: VTK matrices to GLM, the Psi table
// texture, the copy of the scene's depth, embedded GLSL with defines and shared libraries, and the
// final blend of a premultiplied float image into VTK's scene. (Uses VTK's OpenGL2 classes; the
// mappers' math lives in the VTK-free uv*.h headers.)
#ifndef uvMapperOpenGL_h
#define uvMapperOpenGL_h

#include "uvCompositePremultipliedFS.h"
#include "uvFullScreenTriangleVS.h"
#include "uvPreIntegration.h"

#include "vtkMatrix4x4.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <glm/glm.hpp>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace uv
{

/// A VTK (row-major) matrix as a GLM (column-major) one.
inline glm::dmat4 ToGlm(vtkMatrix4x4* m)
{
  glm::dmat4 result;
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column)
      result[column][row] = m->GetElement(row, column);
  return result;
}

/// Creates the Psi table texture (bilinear, clamped) unless it exists; the table is computed once
/// per process.
inline void EnsurePsiTexture(vtkTextureObject* texture, vtkOpenGLRenderWindow* window)
{
  if (texture->GetHandle())
  {
    return;
  }
  static const PsiTable table;
  texture->SetContext(window);
  texture->SetMinificationFilter(vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->Create2DFromRaw(
    table.GetSize(), table.GetSize(), 1, VTK_FLOAT, const_cast<float*>(table.GetValues().data()));
}

/// Copies the depth of what VTK drew so far (opaque geometry) from the current framebuffer's
/// viewport into `depth`. A multisampled framebuffer cannot be copied from directly: `depth` is then
/// filled with the far plane and false returned.
inline bool CopySceneDepth(vtkTextureObject* depth, int originX, int originY, int width, int height)
{
  GLint sampleBuffers = 0;
  glGetIntegerv(GL_SAMPLE_BUFFERS, &sampleBuffers);
  if (sampleBuffers == 0)
  {
    depth->CopyFromFrameBuffer(originX, originY, 0, 0, width, height);
    return true;
  }
  std::vector<float> far(static_cast<std::size_t>(width) * height, 1.0f);
  depth->CreateDepthFromRaw(width, height, vtkTextureObject::Float32, VTK_FLOAT, far.data());
  return false;
}

/// Embedded GLSL made ready to compile: `defines` inserted after VTK's version marker, and each
/// (marker, library) pair's marker replaced by the library's text.
inline std::string ShaderSource(const char* source, const std::string& defines,
  std::initializer_list<std::pair<const char*, const char*>> libraries = {})
{
  std::string text(source);
  const std::string version = "//VTK::System::Dec\n";
  const auto at = text.find(version);
  if (at != std::string::npos)
    text.insert(at + version.size(), defines);
  for (const auto& [marker, library] : libraries)
  {
    const auto where = text.find(marker);
    if (where != std::string::npos)
      text.replace(where, std::string(marker).size(), library);
  }
  return text;
}

/// Blends a premultiplied RGBA image over the viewport of VTK's scene (ONE, ONE_MINUS_SRC_ALPHA).
/// False when the composite shaders do not compile.
inline bool CompositeIntoScene(vtkOpenGLRenderWindow* window, vtkTextureObject* image,
  vtkOpenGLVertexArrayObject* noAttributes, int originX, int originY, int width, int height)
{
  vtkOpenGLState* state = window->GetState();
  state->vtkglViewport(originX, originY, width, height);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  vtkShaderProgram* composite =
    window->GetShaderCache()->ReadyShaderProgram(uvFullScreenTriangleVS, uvCompositePremultipliedFS, "");
  if (!composite)
  {
    return false;
  }
  image->Activate();
  composite->SetUniformi("premultipliedImage", image->GetTextureUnit());
  noAttributes->Bind();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  noAttributes->Release();
  image->Deactivate();
  return true;
}

} // namespace uv

#endif
