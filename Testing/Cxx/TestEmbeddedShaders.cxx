// The GLSL embedded from Shaders/ compiles in VTK's OpenGL context and does what the mappers need of
// it: every program a mapper can use links, with every define combination its options allow, each of
// its stages as VTK composed it (version, defines, outputs) passes the Khronos reference compiler
// (glslangValidator) for the version and profile it declares, and the composite pass copies a
// premultiplied float image exactly and leaves no GL error.
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
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
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
    // Mesa falls back to another driver without a word where the one asked for is missing.
    const char* driver = std::getenv("GALLIUM_DRIVER");
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    ASSERT_TRUE(!driver || (renderer && std::strstr(renderer, driver))) << "asked for " << driver << ", got "
                                                                       << (renderer ? renderer : "none");
  }

  /// Compiles and links `sources`, and passes its stages to the reference compiler; the failure
  /// message names the variant.
  void ExpectLinks(const uvgl::ProgramSources& sources, const std::string& variant)
  {
    vtkShaderProgram* program = uvgl::ReadyProgram(this->Context, sources);
    EXPECT_NE(program, nullptr) << variant << " does not compile or link";
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << variant;
    this->ExpectReferenceCompilerAccepts(program, variant);
  }

  /// Each stage of `program`, as VTK composed it, is written out for glslangValidator, which TearDown
  /// runs once over all of a test's stages: the GLSL specification, not one driver's reading of it.
  /// Drivers accept what the specification does not allow, and reject some of what it does; only
  /// the first is caught here.
  void ExpectReferenceCompilerAccepts(vtkShaderProgram* program, const std::string& variant)
  {
    if (!program)
      return;
    const std::pair<vtkShader*, const char*> stages[] = { { program->GetVertexShader(), "vert" },
      { program->GetGeometryShader(), "geom" }, { program->GetFragmentShader(), "frag" } };
    for (const auto& [shader, stage] : stages)
    {
      const std::string source = shader ? shader->GetSource() : std::string();
      if (source.empty())
        continue;
      const std::filesystem::path file = this->Folder / (std::to_string(this->Stages.size()) + "." + stage);
      std::ofstream(file) << source;
      this->Stages.emplace_back(file.string(), variant + ", " + stage + " stage");
    }
  }

  void TearDown() override
  {
    if (this->Stages.empty())
      return;
    std::string command = std::string(UV_GLSLANG_VALIDATOR);
    for (const auto& stage : this->Stages)
      command += " '" + stage.first + "'";
    const std::filesystem::path log = this->Folder / "glslangValidator.log";
    const int status = std::system((command + " > '" + log.string() + "' 2>&1").c_str());
    std::stringstream output;
    output << std::ifstream(log).rdbuf();
    std::string failed;
    for (const auto& stage : this->Stages)
    {
      const std::size_t at = output.str().find(stage.first + "\nERROR");
      if (at != std::string::npos)
        failed += "\n  " + stage.second + " (" + stage.first + ")";
    }
    EXPECT_EQ(status, 0) << "glslangValidator rejects" << failed << "\n" << output.str();
    EXPECT_EQ(failed, "");
  }

  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkOpenGLRenderWindow* Context = nullptr;
  // Where each composed stage is written for the reference compiler (kept for reading after a run),
  // one folder per test: ctest runs them side by side.
  const std::filesystem::path Folder = [] {
    const char* driver = std::getenv("GALLIUM_DRIVER"); // the programs differ by driver
    const std::filesystem::path folder = std::filesystem::path(UV_TEST_OUTPUT) / "composed_glsl" /
      (driver ? driver : "default") / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::filesystem::create_directories(folder);
    return folder;
  }();
  std::vector<std::pair<std::string, std::string>> Stages; // (file, variant) for the reference compiler
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
      {
        vtkShaderProgram* program = programs.OverCells(fragment);
        EXPECT_NE(program, nullptr) << variant;
        this->ExpectReferenceCompilerAccepts(program, variant);
      }
      // Isosurfaces are always lit, by one of the two gradients.
      if (all[k].VertexGradients || all[k].CellGradients)
      {
        vtkShaderProgram* program = programs.OverCells(uvBarycentricShellIsosurfaceFS);
        EXPECT_NE(program, nullptr) << variant;
        this->ExpectReferenceCompilerAccepts(program, variant + ", isosurfaces");
      }
      for (const char* fragment : { uvBarycentricShellBlendFS, uvOpacityMaskFS })
      {
        vtkShaderProgram* program = programs.FullScreen(fragment);
        EXPECT_NE(program, nullptr) << variant;
        this->ExpectReferenceCompilerAccepts(program, variant);
      }
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << variant;
    }
}

TEST_F(EmbeddedShaders, EveryHexahedralRayCastProgramLinks)
{
  this->ExpectLinks(vtkHexahedralRayCastPrograms::Entry(), "hexahedral entry program");
  const auto all = vtkHexahedralRayCastPrograms::AllTraversalOptions();
  EXPECT_EQ(all.size(), 24u); // vertex gradients only with point scalars
  for (const auto& options : all)
    this->ExpectLinks(vtkHexahedralRayCastPrograms::Traversal(options),
      std::string("hexahedral traversal program") + (options.NodeTexture ? ", node texture" : "") +
        (options.CellScalars ? ", cell scalars" : "") + (options.SkipInvisibleCells ? ", skipping" : "") +
        (options.VertexGradients ? ", vertex gradients" : "") + (options.CellDensities ? ", densities" : ""));
}

TEST_F(EmbeddedShaders, CompositePassCopiesAFloatImage)
{
  EXPECT_NE(std::string(uvFullScreenTriangleVS).find("gl_VertexID"), std::string::npos);
  vtkOpenGLRenderWindow* context = this->Context;

  vtkShaderProgram* program =
    context->GetShaderCache()->ReadyShaderProgram(uvFullScreenTriangleVS, uvCompositePremultipliedFS, "");
  ASSERT_NE(program, nullptr) << "embedded shaders failed to compile or link";
  this->ExpectReferenceCompilerAccepts(program, "composite pass");

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

TEST_F(EmbeddedShaders, DriverMessagesReportProblemsOnly)
{
  // The GL-check mode's second source: the driver's debug output, where the context offers it.
  if (!uvgl::HasDriverDebugOutput())
    GTEST_SKIP() << "this context has no KHR_debug";
  if (uvgl::DriverMessagesGoToACallback())
    GTEST_SKIP() << "VTK reads the driver's messages itself here (a debug callback, VTK 9.6)";
  uvgl::TakeDriverMessages(); // switches debug output on, drains what came before
  glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_PERFORMANCE, 1, GL_DEBUG_SEVERITY_LOW, -1,
    "uv: a performance note");
  EXPECT_EQ(uvgl::TakeDriverMessages(), "");
  glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR, 2, GL_DEBUG_SEVERITY_HIGH, -1,
    "uv: undefined behaviour");
  EXPECT_NE(uvgl::TakeDriverMessages().find("uv: undefined behaviour"), std::string::npos);
  EXPECT_EQ(uvgl::TakeDriverMessages(), "") << "a message is reported once";
  // A real API error reaches the log as well as glGetError.
  glBindTexture(0x1234, 0);
  EXPECT_NE(uvgl::TakeDriverMessages(), "");
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
}
