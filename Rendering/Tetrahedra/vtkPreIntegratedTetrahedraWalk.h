/**
 * @class vtkPreIntegratedTetrahedraWalk
 * @brief vtkPreIntegratedTetrahedraMapper's ray-casting route: rays walk the tetrahedra by face
 * adjacency on the GPU, peel by peel.
 *
 * Each peel is two passes. The entry pass draws the mesh's boundary faces that face the eye,
 * widened by half a pixel and tested exactly per pixel (uvTetrahedralWalkEntryVS/FS.glsl), and
 * keeps, per pixel, the nearest one where the ray enters beyond where the previous walk left it.
 * The walk pass (uvTetrahedralWalkFS.glsl, full screen, the mapper's program) follows each ray from
 * that face through the tetrahedra, composites its segments front to back, and writes where the
 * ray left the mesh; it shades only the pixels the entry pass wrote (a depth test against the
 * entry's depth). Peels go on while some ray enters again (a non-convex mesh, holes, cells that
 * meet without sharing faces), at most MaximumPeels; the entry passes after the first draw only the
 * faces off the mesh's hull, the only ones a ray can enter by again, and a convex mesh has one peel.
 * Holds the adjacency (host and GPU, rebuilt only when the tetrahedra change) and the screen-sized
 * images. (OpenGL layer; not wrapped.)
 */
#ifndef vtkPreIntegratedTetrahedraWalk_h
#define vtkPreIntegratedTetrahedraWalk_h

#include "uvFaceAdjacencyOrder.h"
#include "uvTetrahedralWalk.h"
#include "uvTetrahedralWalkEntryFS.h"
#include "uvTetrahedralWalkEntryVS.h"
#include "vtkUnstructuredVolumeBufferTexture.h"
#include "vtkUnstructuredVolumeFloatTarget.h"
#include "vtkUnstructuredVolumeFrame.h"
#include "vtkUnstructuredVolumeOpenGL.h"
#include "vtkUnstructuredVolumePeelImages.h"
#include "vtkuvTetrahedralMesh.h"

#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

#include <glm/gtc/type_ptr.hpp>

#include <cstdint>
#include <vector>

class vtkPreIntegratedTetrahedraWalk
{
public:
  static constexpr int MaximumPeels = 32;

  /// The adjacency of the mesh's tetrahedra, when they changed (faces matched by their corners'
  /// positions as the tetrahedra were built: a deforming mesh keeps it).
  void Update(const vtkuv::TetrahedralMesh& mesh)
  {
    if (this->BuiltFor == mesh.TopologyVersion && !this->Neighbours.empty())
      return;
    // Matched by position: a cell scalar's copies of a point, and points repeated along a seam.
    const std::vector<std::uint32_t> same = uv::CoincidentPointIds(
      mesh.PointData, 4, [](auto begin, auto end, auto less) { vtkSMPTools::Sort(begin, end, less); });
    std::vector<std::uint32_t> corners(mesh.TetrahedronPoints.size());
    for (std::size_t i = 0; i < corners.size(); ++i)
      corners[i] = same[mesh.TetrahedronPoints[i]];
    const std::vector<std::int32_t> adjacency = uv::MakeTetrahedronFaceAdjacency(corners, vtkuv::ParallelFor);
    this->Neighbours = uv::PackedFaceNeighbours(adjacency, vtkuv::ParallelFor);
    this->Boundary = uv::BoundaryFaceRecords(this->Neighbours, corners);
    const auto position = [&mesh](std::size_t t, int k) { return glm::dvec3(mesh.Corner(t, k)); };
    this->Reentry = uv::MoveReentryFacesFirst(
      this->Boundary, corners, adjacency, position, vtkuv::ParallelFor, MaximumHullTestFaces);
    this->Folded = uv::FoldedFaces(corners, mesh.PointData, 4, this->Neighbours, vtkuv::ParallelFor);
    this->BuiltFor = mesh.TopologyVersion;
    ++this->Builds;
  }

  void Sync(vtkOpenGLRenderWindow* window)
  {
    this->NeighbourTexture.Sync(window, this->Neighbours, 4, this->BuiltFor);
    this->BoundaryTexture.Sync(window, this->Boundary, 1, this->BuiltFor);
  }

  /// Entry (boundary face, ray parameter), its depth and the walk's exit, at the frame's size.
  void Resize(vtkOpenGLRenderWindow* window, int width, int height) { this->Images.Resize(window, width, height); }

  /// The entry pass of one peel into Entry; returns the samples that passed (0: no ray enters
  /// again), or -1 when the program failed. Leaves the target bound.
  long DrawEntries(const vtkUnstructuredVolumeFrame& frame, const glm::dvec3& center,
    vtkUnstructuredVolumeFloatTarget& target,
    vtkUnstructuredVolumeBufferTexture& tetrahedronPoints, vtkUnstructuredVolumeBufferTexture& points,
    const glm::dvec3 bounds[2], bool firstPeel)
  {
    vtkOpenGLState* state = frame.Window->GetState();
    this->Images.Framebuffer->Bind();
    state->vtkglDisable(GL_BLEND);
    this->Images.BeginEntryPass(state);
    long samples = -1;
    vtkShaderProgram* program = uvgl::ReadyProgram(frame.Window, this->EntrySources());
    if (program)
    {
      this->BoundaryTexture.Bind(program, "boundaryFaces");
      tetrahedronPoints.Bind(program, "tetrahedronPoints");
      points.Bind(program, "pointData");
      this->Images.Exit->Activate();
      program->SetUniformi("previousExit", this->Images.Exit->GetTextureUnit());
      program->SetUniformi("firstPeel", firstPeel ? 1 : 0);
      const glm::dmat4 modelToClip = frame.ModelToClip(center);
      uvgl::SetUniformMatrix(program, "modelToClip", modelToClip);
      uvgl::SetEyeRayUniforms(program, glm::inverse(modelToClip), frame.Width, frame.Height);
      const glm::vec3 low(bounds[0]), high(bounds[1]);
      program->SetUniform3f("boundsLow", glm::value_ptr(low));
      program->SetUniform3f("boundsHigh", glm::value_ptr(high));
      const glm::vec4 eye = frame.Parallel ? glm::vec4(glm::vec3(frame.ViewInModel(center)), 0.0f)
                                           : glm::vec4(glm::vec3(frame.EyeInModel(center)), 1.0f);
      program->SetUniform4f("eyeInModel", glm::value_ptr(eye));
      target.GetNoAttributes()->Bind();
      const std::size_t faces = firstPeel ? this->Boundary.size() : this->Reentry;
      samples = uvgl::SamplesPassed([&] { uvgl::DrawItemsInChunks(program, "faceOffset", GL_TRIANGLES, faces, 3); });
      target.GetNoAttributes()->Release();
      this->Images.Exit->Deactivate();
      this->BoundaryTexture.Unbind();
      tetrahedronPoints.Unbind();
      points.Unbind();
    }
    this->Images.Framebuffer->RemoveDepthAttachment();
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_FALSE);
    target.GetFramebuffer()->Bind();
    return samples;
  }

  /// The walk pass of one peel with `program` (the mapper's, bound, its own uniforms set): blended
  /// under what earlier peels composited into the target, the exit written beside it.
  void DrawWalks(const vtkUnstructuredVolumeFrame& frame, const glm::dvec3& center,
    vtkUnstructuredVolumeFloatTarget& target,
    vtkShaderProgram* program, int maximumSteps)
  {
    vtkOpenGLState* state = frame.Window->GetState();
    vtkOpenGLFramebufferObject* framebuffer = target.GetFramebuffer();
    framebuffer->AddColorAttachment(1, this->Images.Exit);
    framebuffer->ActivateDrawBuffers(2);
    const float done[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    glClearBufferfv(GL_COLOR, 1, done);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ONE_MINUS_DST_ALPHA, GL_ONE);
    // Only pixels the entry pass wrote (depth below 1) are walked: the others fail the test before
    // their fragments are shaded.
    target.AttachDepth(this->Images.EntryDepth);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_GREATER);
    state->vtkglDepthMask(GL_FALSE);
    this->Images.Entry->Activate();
    program->SetUniformi("entry", this->Images.Entry->GetTextureUnit());
    this->BoundaryTexture.Bind(program, "boundaryFaces");
    this->NeighbourTexture.Bind(program, "faceNeighbours");
    program->SetUniformi("maximumSteps", maximumSteps);
    uvgl::SetEyeRayUniforms(program, glm::inverse(frame.ModelToClip(center)), frame.Width, frame.Height);
    target.GetNoAttributes()->Bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    target.GetNoAttributes()->Release();
    this->Images.Entry->Deactivate();
    this->BoundaryTexture.Unbind();
    this->NeighbourTexture.Unbind();
    state->vtkglDisable(GL_DEPTH_TEST);
    target.AttachDepth(nullptr);
    framebuffer->RemoveColorAttachment(1);
    framebuffer->ActivateDrawBuffers(1);
  }

  /// The entry pass's program (Testing/Cxx/TestEmbeddedShaders links it).
  static uvgl::ProgramSources EntrySources()
  {
    return { uvgl::ShaderSource(uvTetrahedralWalkEntryVS, ""),
      uvgl::ShaderSource(uvTetrahedralWalkEntryFS, ""),
      "" };
  }

  std::size_t BoundaryFaces() const { return this->Boundary.size(); }
  /// The boundary faces the peels after the first draw (uv::MoveReentryFacesFirst); 0: one peel.
  std::size_t ReentryFaces() const { return this->Reentry; }
  /// Interior faces with both tetrahedra on one side (uv::FoldedFaces), as of the last Update.
  std::size_t FoldedFaces() const { return this->Folded; }
  int GetBuilds() const { return this->Builds; }
  /// Host bytes (the adjacency and the boundary faces).
  std::size_t GetBytes() const
  {
    return sizeof(std::int32_t) * (this->Neighbours.capacity() + this->Boundary.capacity());
  }
  std::size_t GetGpuBytes() const { return this->NeighbourTexture.GetBytes() + this->BoundaryTexture.GetBytes(); }

  void Release()
  {
    this->NeighbourTexture.Release();
    this->BoundaryTexture.Release();
    this->Images.Release();
  }

private:
  /// The hull test's limit: beyond it every boundary face counts as one a ray may enter again by
  /// (the test is once per mesh, but takes each face against each boundary point).
  static constexpr std::size_t MaximumHullTestFaces = 20000;

  std::vector<std::int32_t> Neighbours, Boundary; // Boundary: the reentry faces first
  std::size_t Reentry = 0;
  std::uint64_t BuiltFor = 0; // the mesh's TopologyVersion
  std::size_t Folded = 0;
  int Builds = 0;
  vtkUnstructuredVolumeBufferTexture NeighbourTexture, BoundaryTexture;
  vtkUnstructuredVolumePeelImages Images{ false }; // no second accumulation: the walk blends into the target
};

#endif
