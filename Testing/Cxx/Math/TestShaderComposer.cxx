// Programs composed from the table of libraries (uvShaderComposer.h): nesting, needs, each library
// once, markers in comments left alone, and a missing library made a compile error.
#include "uvShaderComposer.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace
{
const std::vector<uv::ShaderLibrary> Libraries = {
  { "Ray", "float Ray() { return 1.0; }\n", {} },
  { "Cell", "//UV::Ray\nfloat Cell() { return Ray(); }\n", {} },
  { "Light", "float Light() { return Ray() + Table(); }\n", { "Ray", "Table" } },
  { "Table", "float Table() { return 2.0; }", {} },
};

std::size_t Count(const std::string& text, const std::string& part)
{
  std::size_t count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1))
    ++count;
  return count;
}
} // namespace

TEST(ShaderComposer, DefinesGoRightAfterTheVersionMarker)
{
  const uv::ComposedShader shader =
    uv::ComposeShader("//VTK::System::Dec\nvoid main() {}\n", "#define UV_A\n", Libraries);
  EXPECT_EQ(shader.Text, "//VTK::System::Dec\n#define UV_A\nvoid main() {}\n");
  EXPECT_TRUE(shader.Missing.empty());
}

TEST(ShaderComposer, NestedMarkersAndNeedsComeFirstAndOnce)
{
  const uv::ComposedShader shader =
    uv::ComposeShader("//VTK::System::Dec\n//UV::Light\n  //UV::Cell\n//UV::Ray\nvoid main() {}\n", "", Libraries);
  EXPECT_TRUE(shader.Missing.empty());
  for (const char* function : { "float Ray()", "float Table()", "float Light()", "float Cell()" })
    EXPECT_EQ(Count(shader.Text, function), 1u) << function;
  // Light's needs before it; Ray already in when Cell asks for it.
  EXPECT_LT(shader.Text.find("float Ray()"), shader.Text.find("float Light()"));
  EXPECT_LT(shader.Text.find("float Table()"), shader.Text.find("float Light()"));
  EXPECT_LT(shader.Text.find("float Light()"), shader.Text.find("float Cell()"));
  EXPECT_LT(shader.Text.find("float Cell()"), shader.Text.find("void main()"));
  EXPECT_EQ(Count(shader.Text, "//UV::"), 0u);
}

TEST(ShaderComposer, MarkersMentionedInSentencesAreLeftAlone)
{
  const std::string source = "// inserted at //UV::Ray by the composer\nvoid main() {}\n";
  const uv::ComposedShader shader = uv::ComposeShader(source, "", Libraries);
  EXPECT_EQ(shader.Text, source);
}

TEST(ShaderComposer, AMarkerWithoutALibraryIsACompileError)
{
  const uv::ComposedShader shader = uv::ComposeShader("//UV::Lost\nvoid main() {}\n", "", Libraries);
  EXPECT_EQ(shader.Missing, std::vector<std::string>{ "Lost" });
  EXPECT_NE(shader.Text.find("#error no shader library for the marker //UV::Lost"), std::string::npos);
}
