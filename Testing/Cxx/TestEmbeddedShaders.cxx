// The GLSL embedded from Shaders/ compiles in VTK's OpenGL context and does what the mappers need of
// it: the composite pass copies a premultiplied float image exactly and leaves no GL error.
#include "uvCompositePremultipliedFS.h"
#include "uvFullScreenTriangleVS.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

TEST(EmbeddedShaders, CompositePassCopiesAFloatImage)
{
  if (!std::getenv("DISPLAY"))
  {
    GTEST_SKIP() << "no X display (the test suite runs under Xvfb)";
  }
  EXPECT_NE(std::string(uvFullScreenTriangleVS).find("gl_VertexID"), std::string::npos);

  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->SetOffScreenRendering(1);
  window->SetSize(8, 8);
  window->Render();
  auto context = vtkOpenGLRenderWindow::SafeDownCast(window);
  ASSERT_NE(context, nullptr);
  context->MakeCurrent();
  while (glGetError() != GL_NO_ERROR)
  {
  }

  vtkShaderProgram* program =
    context->GetShaderCache()->ReadyShaderProgram(uvFullScreenTriangleVS, uvCompositePremultipliedFS, "");
  ASSERT_NE(program, nullptr) << "embedded shaders failed to compile or link";

  // A 2x2 premultiplied image; each quadrant of the viewport must show its texel.
  const std::vector<float> texels = { 0.25f, 0.5f, 0.125f, 0.5f, 1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 0, 0 };
  vtkNew<vtkTextureObject> image;
  image->SetContext(context);
  image->SetMinificationFilter(vtkTextureObject::Nearest);
  image->SetMagnificationFilter(vtkTextureObject::Nearest);
  ASSERT_TRUE(image->Create2DFromRaw(2, 2, 4, VTK_FLOAT, const_cast<float*>(texels.data())));
  image->Activate();
  program->SetUniformi("premultipliedImage", image->GetTextureUnit());

  vtkOpenGLState* state = context->GetState();
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglViewport(0, 0, 8, 8);
  vtkNew<vtkOpenGLVertexArrayObject> noVertices; // core profiles need a bound VAO to draw
  noVertices->Bind();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  noVertices->Release();
  image->Deactivate();

  std::vector<unsigned char> pixels(8 * 8 * 4);
  glReadPixels(0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  auto pixel = [&](int x, int y, int channel) { return static_cast<int>(pixels[4 * (8 * y + x) + channel]); };
  // Lower-left texel (0.25, 0.5, 0.125) -> (64, 128, 32) within one step of rounding.
  EXPECT_NEAR(pixel(1, 1, 0), 64, 1);
  EXPECT_NEAR(pixel(1, 1, 1), 128, 1);
  EXPECT_NEAR(pixel(1, 1, 2), 32, 1);
  EXPECT_EQ(pixel(6, 1, 0), 255); // lower-right texel: red
  EXPECT_EQ(pixel(1, 6, 1), 255); // upper-left texel: green
  EXPECT_EQ(pixel(6, 6, 0) + pixel(6, 6, 1) + pixel(6, 6, 2), 0);
  image->ReleaseGraphicsResources(context);
}
