// The OpenGL steps every mapper of this module takes the same way: VTK matrices to GLM, the copy of
// the scene's depth, the transfer function's uniforms, embedded GLSL with defines and shared
// libraries, and the final blend of a premultiplied float image into VTK's scene. (Uses VTK's
// OpenGL2 classes; the mappers' math lives in the VTK-free uv*.h headers.)
#ifndef vtkUnstructuredVolumeOpenGL_h
#define vtkUnstructuredVolumeOpenGL_h

#include "uvCompositePremultipliedFS.h"
#include "uvFullScreenTriangleVS.h"
#include "uvOpticalModel.h"
#include "uvBarycentricRayLib.h"
#include "uvBarycentricShellRecordLib.h"
#include "uvBarycentricTetrahedronLib.h"
#include "uvBilinearFaceLib.h"
#include "uvEyeRayLib.h"
#include "uvHexahedronLib.h"
#include "uvHexahedralCutsLib.h"
#include "uvHexahedralExitLib.h"
#include "uvHexahedralOverlapLib.h"
#include "uvHexahedralLoadedCellLib.h"
#include "uvHexahedralSegmentLib.h"
#include "uvPhongLib.h"
#include "uvProjectedTetrahedronLib.h"
#include "uvSegmentIntegrationLib.h"
#include "uvSegmentLengthTableLib.h"
#include "uvShaderComposer.h"
#include "uvTetrahedralWalkLib.h"
#include "uvTransferFunctionLib.h"
#include "uvPreIntegration.h"

#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkPointData.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkVolumeProperty.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

#include <glm/glm.hpp>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <initializer_list>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace uvgl
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

/// The buffer textures this process refused to make since it started, because they held more texels
/// than their context allows, and what the last refusal was: a mapper compares the count before and
/// after its upload, and fails the frame with that message.
struct BufferTextureRefusals
{
  int Count = 0;
  std::string Last;
};
inline BufferTextureRefusals& Refusals()
{
  static BufferTextureRefusals refusals;
  return refusals;
}

/// Uploads `values` (float, int or unsigned int; `components` per texel) as a buffer texture. False
/// (and nothing made, a refusal noted) when it holds more texels than GL_MAX_TEXTURE_BUFFER_SIZE:
/// OpenGL 3.3 promises 65536, and reads beyond a driver's limit are undefined.
template <typename T>
bool UploadBufferTexture(vtkOpenGLRenderWindow* window, vtkOpenGLBufferObject* buffer, vtkTextureObject* texture,
  const std::vector<T>& values, int components)
{
  GLint limit = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &limit);
  const std::size_t texels = values.size() / static_cast<std::size_t>(components);
  if (texels > static_cast<std::size_t>(limit))
  {
    std::ostringstream message;
    message << "the mesh needs a buffer texture of " << texels << " texels, and this OpenGL driver allows "
            << limit << " (GL_MAX_TEXTURE_BUFFER_SIZE)";
    Refusals().Last = message.str();
    ++Refusals().Count;
    return false;
  }
  static_assert(sizeof(T) == 4, "32-bit texels");
  constexpr int vtkType =
    std::is_same<T, float>::value ? VTK_FLOAT : (std::is_signed<T>::value ? VTK_INT : VTK_UNSIGNED_INT);
  static const unsigned int formats[3][4] = { { GL_R32F, GL_RG32F, GL_RGB32F, GL_RGBA32F },
    { GL_R32I, GL_RG32I, GL_RGB32I, GL_RGBA32I }, { GL_R32UI, GL_RG32UI, GL_RGB32UI, GL_RGBA32UI } };
  const int kind = vtkType == VTK_FLOAT ? 0 : (vtkType == VTK_INT ? 1 : 2);
  buffer->Upload(values, vtkOpenGLBufferObject::TextureBuffer);
  texture->SetContext(window);
  texture->SetInternalFormat(formats[kind][components - 1]);
  texture->CreateTextureBuffer(static_cast<unsigned int>(texels), components, vtkType, buffer);
  return true;
}

/// Sets the matrix uniform `name` of the bound `program` (in float, as GLSL reads it).
inline void SetUniformMatrix(vtkShaderProgram* program, const char* name, const glm::dmat4& m)
{
  const glm::mat4 single(m);
  program->SetUniformMatrix4x4(name, const_cast<float*>(&single[0][0]));
}
inline void SetUniformMatrix(vtkShaderProgram* program, const char* name, const glm::dmat3& m)
{
  const glm::mat3 single(m);
  program->SetUniformMatrix3x3(name, const_cast<float*>(&single[0][0]));
}

/// Allocates `texture` as a width x height float image of `components` channels, nearest filtering
/// (a screen-sized image a pass writes and a later one reads texel by texel).
inline void AllocateFloatImage(vtkTextureObject* texture, vtkOpenGLRenderWindow* window, int width, int height,
  int components)
{
  texture->SetContext(window);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->Allocate2D(width, height, components, VTK_FLOAT);
}

/// Uploads `texels` (width x height x depth texels of `components` floats) into `texture` as a 3D
/// float texture read with trilinear filtering, clamped at its edges (a table or a volume sampled
/// between its texels).
inline void UploadTrilinearVolume(vtkTextureObject* texture, vtkOpenGLRenderWindow* window, int width, int height,
  int depth, int components, const float* texels)
{
  texture->SetContext(window);
  texture->SetMinificationFilter(vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetWrapR(vtkTextureObject::ClampToEdge);
  texture->Create3DFromRaw(width, height, depth, components, VTK_FLOAT, const_cast<float*>(texels));
}

/// The samples that pass while `draw()` draws (an occlusion query; waits for the result).
template <typename Draw>
GLuint SamplesPassed(const Draw& draw)
{
  GLuint query = 0, samples = 0;
  glGenQueries(1, &query);
  glBeginQuery(GL_SAMPLES_PASSED, query);
  draw();
  glEndQuery(GL_SAMPLES_PASSED);
  glGetQueryObjectuiv(query, GL_QUERY_RESULT, &samples);
  glDeleteQueries(1, &query);
  return samples;
}

/// Whether the current context offers KHR_debug (core since OpenGL 4.3; an extension before).
inline bool HasDriverDebugOutput()
{
  if (!glGetDebugMessageLog)
    return false;
  GLint major = 0, minor = 0, extensions = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major > 4 || (major == 4 && minor >= 3))
    return true;
  glGetIntegerv(GL_NUM_EXTENSIONS, &extensions);
  for (GLint k = 0; k < extensions; ++k)
  {
    const char* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(k)));
    if (name && std::strcmp(name, "GL_KHR_debug") == 0)
      return true;
  }
  return false;
}

/// Whether the driver's debug messages go to a callback rather than to its log (VTK 9.6 installs
/// one and logs them itself): the log then stays empty.
inline bool DriverMessagesGoToACallback()
{
  GLvoid* callback = nullptr;
  glGetPointerv(GL_DEBUG_CALLBACK_FUNCTION, &callback);
  return callback != nullptr;
}

/// The driver's own messages (KHR_debug) since the last read that report a problem: errors,
/// undefined behaviour, deprecated behaviour and portability, one per line; "" when there are none or
/// the context lacks KHR_debug. Debug output is switched on in the context at the first read (a
/// driver may stay silent in a context not made for debugging; Mesa does not).
inline std::string TakeDriverMessages()
{
  if (!HasDriverDebugOutput() || DriverMessagesGoToACallback())
    return std::string();
  if (!glIsEnabled(GL_DEBUG_OUTPUT))
    glEnable(GL_DEBUG_OUTPUT);
  std::ostringstream problems;
  for (int batch = 0; batch < 64; ++batch)
  {
    constexpr GLsizei count = 16, size = 16 * 1024;
    GLenum sources[count], types[count], severities[count];
    GLuint ids[count];
    GLsizei lengths[count];
    std::vector<GLchar> text(size);
    const GLuint read = glGetDebugMessageLog(count, size, sources, types, ids, severities, lengths, text.data());
    const GLchar* message = text.data();
    for (GLuint k = 0; k < read; message += lengths[k], ++k)
    {
      const GLenum type = types[k];
      if (type == GL_DEBUG_TYPE_ERROR || type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR ||
        type == GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR || type == GL_DEBUG_TYPE_PORTABILITY)
        problems << "\n  driver: " << message;
    }
    if (read < static_cast<GLuint>(count))
      break;
  }
  return problems.str();
}

/// Draws `items` items of `verticesPerItem` vertices each without indices (glDrawArrays, no vertex
/// attributes: the shaders pull their data), in draws of a few thousand vertices each, setting the
/// uniform `offsetName` to each draw's first item (counted from `firstItem`): the vertex shader's item
/// is offset + gl_VertexID / verticesPerItem. Mesa's softpipe cuts longer non-indexed draws into
/// pieces of 4096 vertices and starts gl_VertexID again from `first` in each.
inline void DrawItemsInChunks(vtkShaderProgram* program, const char* offsetName, GLenum mode, std::size_t items,
  int verticesPerItem, std::size_t firstItem = 0)
{
  const std::size_t perDraw = std::max<std::size_t>(1, 3072 / static_cast<std::size_t>(verticesPerItem));
  for (std::size_t first = 0; first < items; first += perDraw)
  {
    const std::size_t count = std::min(perDraw, items - first);
    program->SetUniformi(offsetName, static_cast<int>(firstItem + first));
    glDrawArrays(mode, 0, static_cast<GLsizei>(count * verticesPerItem));
  }
}

/// Reads the float RGBA colour attachment `attachment` of the bound framebuffer into `image` (made when
/// null), width x height.
inline void ReadFloatImage(vtkOpenGLFramebufferObject* framebuffer, unsigned int attachment, int width, int height,
  vtkSmartPointer<vtkImageData>& image)
{
  if (!image)
    image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_FLOAT, 4);
  framebuffer->ActivateReadBuffer(attachment);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, image->GetScalarPointer());
  image->GetPointData()->GetScalars()->Modified();
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

/// Transfer-function nodes (normalised scalars) as uvTransferFunctionLib.glsl reads them: up to
/// MaximumUniformNodes as uniforms (cheaper to read than a texture on CPU rasterisers), more from a
/// texture (then TransferFunctionDefines adds UV_NODE_TEXTURE).
constexpr int MaximumUniformNodes = 64;

inline bool NodesNeedTexture(const std::vector<uv::TransferFunction::Node>& nodes)
{
  return nodes.size() > static_cast<std::size_t>(MaximumUniformNodes);
}

/// The defines uvTransferFunctionLib.glsl needs: its uniform capacity and, when the nodes do not
/// fit in it, UV_NODE_TEXTURE.
/// Whether the current context's texture units interpolate float textures with float weights, so
/// that the tables may be read with one filtered fetch. GL leaves the precision of the filter's
/// weights to the implementation: GPUs keep a few bits, and so does softpipe's 3D filter, enough to
/// cost the tables most of their accuracy. llvmpipe computes them in float (its filtered reads equal
/// the shaders' own interpolation: python.routes on both drivers); elsewhere the shaders interpolate
/// texelFetch reads with float weights (UV_TEXTURE_UNIT_FILTER undefined).
inline bool ExactTextureFilter()
{
  if (!glGetString) // no OpenGL loaded yet
    return false;
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return renderer && std::strstr(renderer, "llvmpipe");
}

inline std::string TransferFunctionDefines(bool nodeTexture)
{
  std::string defines = "#define UV_MAX_UNIFORM_NODES " + std::to_string(MaximumUniformNodes) + "\n";
  if (nodeTexture)
    defines += "#define UV_NODE_TEXTURE\n";
  if (ExactTextureFilter())
    defines += "#define UV_TEXTURE_UNIT_FILTER\n";
  return defines;
}

inline std::string TransferFunctionDefines(const std::vector<uv::TransferFunction::Node>& nodes)
{
  return TransferFunctionDefines(NodesNeedTexture(nodes));
}

/// The node texture's texels: row 0 (r, g, b, extinction), row 1 the scalar.
inline std::vector<float> TransferFunctionTexels(const std::vector<uv::TransferFunction::Node>& nodes)
{
  const std::size_t count = nodes.size();
  std::vector<float> texels(8 * count, 0.0f);
  for (std::size_t k = 0; k < count; ++k)
  {
    texels[4 * k + 0] = static_cast<float>(nodes[k].Color.r);
    texels[4 * k + 1] = static_cast<float>(nodes[k].Color.g);
    texels[4 * k + 2] = static_cast<float>(nodes[k].Color.b);
    texels[4 * k + 3] = static_cast<float>(nodes[k].Extinction);
    texels[4 * (count + k)] = static_cast<float>(nodes[k].Scalar);
  }
  return texels;
}

/// The uniforms of uvTransferFunctionLib.glsl other than its textures: the node count, the nodes
/// themselves when they fit in uniforms, and the Psi table's size.
inline void SetTransferFunctionUniforms(vtkShaderProgram* program, const std::vector<uv::TransferFunction::Node>& nodes)
{
  program->SetUniformi("nodeCount", static_cast<int>(nodes.size()));
  if (!NodesNeedTexture(nodes))
  {
    std::vector<float> values(4 * MaximumUniformNodes, 0.0f), scalars(MaximumUniformNodes, 0.0f);
    for (std::size_t k = 0; k < nodes.size(); ++k)
    {
      values[4 * k + 0] = static_cast<float>(nodes[k].Color.r);
      values[4 * k + 1] = static_cast<float>(nodes[k].Color.g);
      values[4 * k + 2] = static_cast<float>(nodes[k].Color.b);
      values[4 * k + 3] = static_cast<float>(nodes[k].Extinction);
      scalars[k] = static_cast<float>(nodes[k].Scalar);
    }
    program->SetUniform4fv("nodeValues", MaximumUniformNodes, values.data());
    program->SetUniform4fv("nodeScalars", MaximumUniformNodes / 4, scalars.data());
  }
  program->SetUniformf("psiTableSize", static_cast<float>(uv::PsiTableSize));
}

/// The uniforms of uvTransferFunctionLib.glsl with its textures, for mappers that keep their own
/// (`nodeTexture` and `psiTable` active; the node texture is read only when the nodes need it).
inline void SetTransferFunctionUniforms(vtkShaderProgram* program, const std::vector<uv::TransferFunction::Node>& nodes,
  vtkTextureObject* nodeTexture, vtkTextureObject* psiTable)
{
  SetTransferFunctionUniforms(program, nodes);
  if (NodesNeedTexture(nodes))
    program->SetUniformi("transferFunction", nodeTexture->GetTextureUnit());
  program->SetUniformi("psiTable", psiTable->GetTextureUnit());
}

/// Every GLSL library of Shaders/, by the name its marker line gives ("//UV::Name"), with the
/// libraries whose code it uses.
inline const std::vector<uv::ShaderLibrary>& ShaderLibraries()
{
  static const std::vector<uv::ShaderLibrary> libraries = {
    { "BarycentricRay", uvBarycentricRayLib, {} },
    { "BarycentricTetrahedron", uvBarycentricTetrahedronLib, {} },
    { "BilinearFace", uvBilinearFaceLib, {} },
    { "EyeRay", uvEyeRayLib, {} },
    { "Hexahedron", uvHexahedronLib, {} }, // holds the eye-ray library's marker where it needs it
    // The hexahedral traversal's sections, in the order uvHexahedralTraverseFS.glsl names them.
    { "HexahedralLoadedCell", uvHexahedralLoadedCellLib, { "Hexahedron", "BilinearFace" } },
    { "HexahedralSegment", uvHexahedralSegmentLib, { "HexahedralLoadedCell", "Phong" } },
    { "HexahedralCuts", uvHexahedralCutsLib, { "HexahedralSegment", "TransferFunction" } },
    { "HexahedralExit", uvHexahedralExitLib, { "HexahedralLoadedCell" } },
    { "HexahedralOverlap", uvHexahedralOverlapLib, { "HexahedralCuts" } },
    { "Phong", uvPhongLib, {} },
    { "ProjectedTetrahedron", uvProjectedTetrahedronLib, {} },
    { "SegmentIntegration", uvSegmentIntegrationLib, { "TransferFunction", "Phong" } },
    { "SegmentLengthTable", uvSegmentLengthTableLib, {} },
    { "ShellRecord", uvBarycentricShellRecordLib, {} },
    { "TetrahedralWalk", uvTetrahedralWalkLib, {} },
    { "TransferFunction", uvTransferFunctionLib, {} },
  };
  return libraries;
}

/// Embedded GLSL made ready to compile: `defines` inserted after VTK's version marker, and every
/// library marker replaced from ShaderLibraries() (uv::ComposeShader; one without a library turns
/// into an #error that names it).
inline std::string ShaderSource(const char* source, const std::string& defines)
{
  return uv::ComposeShader(source, defines, ShaderLibraries()).Text;
}

/// The eye rays of uvEyeRayLib.glsl: the near-plane point and the direction (far minus near point)
/// at ndc (0, 0) and their change per unit of ndc x and y, computed in double from `clipToModel`
/// and then rounded (a float matrix loses the direction when the far plane is far beyond the near).
/// Also sets viewportSize.
inline void SetEyeRayUniforms(vtkShaderProgram* program, const glm::dmat4& clipToModel, int width, int height)
{
  const auto unproject = [&clipToModel](double x, double y, double z) {
    const glm::dvec4 p = clipToModel * glm::dvec4(x, y, z, 1.0);
    return glm::dvec3(p) / p.w;
  };
  float nearPlane[3][3], rayDirection[3][3];
  const double ndc[3][2] = { { 0.0, 0.0 }, { 1.0, 0.0 }, { 0.0, 1.0 } };
  const glm::dvec3 near0 = unproject(0.0, 0.0, -1.0), far0 = unproject(0.0, 0.0, 1.0);
  for (int k = 0; k < 3; ++k)
  {
    glm::dvec3 nearPoint = unproject(ndc[k][0], ndc[k][1], -1.0);
    glm::dvec3 direction = unproject(ndc[k][0], ndc[k][1], 1.0) - nearPoint;
    if (k > 0)
    {
      nearPoint -= near0;
      direction -= far0 - near0;
    }
    for (int i = 0; i < 3; ++i)
    {
      nearPlane[k][i] = static_cast<float>(nearPoint[i]);
      rayDirection[k][i] = static_cast<float>(direction[i]);
    }
  }
  program->SetUniform3fv("nearPlane", 3, nearPlane);
  program->SetUniform3fv("rayDirection", 3, rayDirection);
  const float viewport[2] = { static_cast<float>(width), static_cast<float>(height) };
  program->SetUniform2f("viewportSize", viewport);
}

/// The sources of one shader program, ready to compile (no geometry stage when Geometry is empty).
struct ProgramSources
{
  std::string Vertex, Fragment, Geometry;
};

/// The program from VTK's shader cache (compiled once per distinct source), bound; null when it
/// does not compile or link.
inline vtkShaderProgram* ReadyProgram(vtkOpenGLRenderWindow* window, const ProgramSources& sources)
{
  return window->GetShaderCache()->ReadyShaderProgram(
    sources.Vertex.c_str(), sources.Fragment.c_str(), sources.Geometry.c_str());
}

/// The uniforms of uvPhongLib.glsl: the property's coefficients and the renderer's first switched-on
/// light as a direction towards it in eye space (a headlight when there is none).
inline void SetPhongUniforms(
  vtkShaderProgram* program, vtkRenderer* renderer, vtkVolumeProperty* property, const glm::dmat4& worldToEye)
{
  program->SetUniformf("ambient", static_cast<float>(property->GetAmbient()));
  program->SetUniformf("diffuse", static_cast<float>(property->GetDiffuse()));
  program->SetUniformf("specular", static_cast<float>(property->GetSpecular()));
  program->SetUniformf("specularPower", static_cast<float>(property->GetSpecularPower()));
  glm::dvec3 towardsLight(0.0, 0.0, 1.0), lightColor(1.0);
  vtkLightCollection* lights = renderer->GetLights();
  lights->InitTraversal();
  while (vtkLight* light = lights->GetNextItem())
  {
    if (!light->GetSwitch())
      continue;
    double position[3], focal[3];
    light->GetTransformedPosition(position);
    light->GetTransformedFocalPoint(focal);
    const glm::dvec3 world(position[0] - focal[0], position[1] - focal[1], position[2] - focal[2]);
    if (glm::length(world) > 0.0)
      towardsLight = glm::normalize(glm::dmat3(worldToEye) * world);
    const double* rgb = light->GetDiffuseColor();
    lightColor = glm::dvec3(rgb[0], rgb[1], rgb[2]) * light->GetIntensity();
    break;
  }
  const float direction[3] = { static_cast<float>(towardsLight.x), static_cast<float>(towardsLight.y),
    static_cast<float>(towardsLight.z) };
  const float color[3] = { static_cast<float>(lightColor.r), static_cast<float>(lightColor.g),
    static_cast<float>(lightColor.b) };
  program->SetUniform3f("lightDirection", direction);
  program->SetUniform3f("lightColor", color);
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

} // namespace uvgl

#endif
