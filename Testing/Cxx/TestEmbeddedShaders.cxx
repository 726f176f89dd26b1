// The GLSL embedded from Shaders/ compiles in VTK's OpenGL context and does what the mappers need of
// it: every program a mapper can use links, with every define combination its options allow, and
// the composite pass copies a premultiplied float image exactly and leaves no GL error.
#include "uvCompositePremultipliedFS.h"
#include "uvFullScreenTriangleVS.h"
#include "uvBarycentricCellProjectionFS.h"
#include "uvBarycentricShellBlendFS.h"
#include "uvBarycentricShellIsosurfaceFS.h"
#include "uvOpacityMaskFS.h"
#include "uvBarycentricShellSliceFS.h"
#include "vtkBarycentricShellPrograms.h"
#include "vtkHexahedralRayCastPrograms.h"
#include "vtkPreIntegratedTetrahedraPrograms.h"
#include "vtkPreIntegratedTetrahedraWalk.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace
{
/// An off-screen VTK window whose OpenGL context is current, with no GL error pending.
class EmbeddedShaders : public ::testing::Test
{
protected:
  void SetUp() override
  {
    if (!std::getenv("DISPLAY"))
    {
      GTEST_SKIP() << "no X display (the test suite runs under Xvfb)";
    }
    this->Window->AddRenderer(this->Renderer);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetSize(8, 8);
    this->Window->Render();
    this->Context = vtkOpenGLRenderWindow::SafeDownCast(this->Window);
    ASSERT_NE(this->Context, nullptr);
    this->Context->MakeCurrent();
    while (glGetError() != GL_NO_ERROR)
    {
    }
  }

  /// Compiles and links `sources`; the failure message names the variant.
  void ExpectLinks(const uvgl::ProgramSources& sources, const std::string& variant)
  {
    vtkShaderProgram* program = uvgl::ReadyProgram(this->Context, sources);
    EXPECT_NE(program, nullptr) << variant << " does not compile or link";
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << variant;
  }

  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkOpenGLRenderWindow* Context = nullptr;
};
}

namespace
{
const char* ClippingName(vtkPreIntegratedTetrahedraPrograms::Clipping clips)
{
  using Clipping = vtkPreIntegratedTetrahedraPrograms::Clipping;
  return clips == Clipping::NearPlane ? ", near-plane cuts" : clips == Clipping::Sides ? ", clipped sides" : "";
}
}

TEST_F(EmbeddedShaders, EveryPreIntegratedTetrahedraProgramLinks)
{
  const auto all = vtkPreIntegratedTetrahedraPrograms::AllOptions();
  // 35 option sets (18 of pulled faces, 12 of fans, 5 of ray casting), with and without the opaque depth
  EXPECT_EQ(all.size(), 70u);
  for (const auto& options : all)
  {
    const std::string variant = std::string("tetrahedra program, ") +
      (options.VertexPulling ? "vertex pulling" : "geometry shader") + (options.Gradients ? ", gradients" : "") +
      (options.NodeTexture ? ", node texture" : "") + (options.CellSurfaces ? ", cell surfaces" : "") +
      (options.SegmentTable ? ", segment table" : "") + ClippingName(options.Clips) +
      (options.OpaqueDepth ? ", opaque depth" : "") + (options.RayCasting ? ", ray casting" : "");
    this->ExpectLinks(vtkPreIntegratedTetrahedraPrograms::Sources(options), variant);
  }
  this->ExpectLinks(vtkPreIntegratedTetrahedraWalk::EntrySources(), "tetrahedra ray casting, entry pass");
}

TEST_F(EmbeddedShaders, EveryBarycentricShellProgramLinks)
{
  const auto all = vtkBarycentricShellPrograms::AllOptions();
  for (bool pulling : { true, false })
    for (std::size_t k = 0; k < all.size(); ++k)
    {
      const vtkBarycentricShellPrograms programs(
        this->Context, vtkBarycentricShellPrograms::DefinesFor(all[k]), pulling);
      const std::string variant = std::string("shell programs, ") +
        (pulling ? "vertex pulling" : "geometry shader") + ", options #" + std::to_string(k);
      for (const char* fragment : { uvBarycentricCellProjectionFS, uvBarycentricShellSliceFS })
        EXPECT_NE(programs.OverCells(fragment), nullptr) << variant;
      // Isosurfaces are always lit, by one of the two gradients.
      if (all[k].VertexGradients || all[k].CellGradients)
        EXPECT_NE(programs.OverCells(uvBarycentricShellIsosurfaceFS), nullptr) << variant;
      for (const char* fragment : { uvBarycentricShellBlendFS, uvOpacityMaskFS })
        EXPECT_NE(programs.FullScreen(fragment), nullptr) << variant;
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << variant;
    }
}

TEST_F(EmbeddedShaders, EveryHexahedralRayCastProgramLinks)
{
  this->ExpectLinks(vtkHexahedralRayCastPrograms::Entry(), "hexahedral entry program");
  const auto all = vtkHexahedralRayCastPrograms::AllTraversalOptions();
  EXPECT_EQ(all.size(), 12u); // vertex gradients only with point scalars
  for (const auto& options : all)
    this->ExpectLinks(vtkHexahedralRayCastPrograms::Traversal(options),
      std::string("hexahedral traversal program") + (options.NodeTexture ? ", node texture" : "") +
        (options.CellScalars ? ", cell scalars" : "") + (options.SkipInvisibleCells ? ", skipping" : "") +
        (options.VertexGradients ? ", vertex gradients" : ""));
}

TEST_F(EmbeddedShaders, CompositePassCopiesAFloatImage)
{
  EXPECT_NE(std::string(uvFullScreenTriangleVS).find("gl_VertexID"), std::string::npos);
  vtkOpenGLRenderWindow* context = this->Context;

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
