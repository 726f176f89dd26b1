/**
 * @class vtkUnstructuredVolumeCellDrawer
 * @brief Draws the tetrahedra at a range of places of a cell list, by vtkBarycentricShellMapper's
 * chosen route (and vtkPreIntegratedTetrahedraMapper's vertex-pulling route).
 *
 * Geometry-shader route: one point per tetrahedron (uvBarycentricCellListVS.glsl). Vertex pulling:
 * four vertices per tetrahedron under a fixed index pattern of its four faces, wound outwards for
 * positively oriented tetrahedra (the vertex stage swaps two vertices of the others), front faces
 * culled (uvBarycentricPullVS.glsl). The list's first
 * place rides in a uniform, so one pattern of ChunkSize tetrahedra serves every chunk of every list.
 * Owns that pattern. (OpenGL layer of the tetrahedral mappers; not wrapped.)
 */
#ifndef vtkUnstructuredVolumeCellDrawer_h
#define vtkUnstructuredVolumeCellDrawer_h

#include "vtkUnstructuredVolumeBufferTexture.h"
#include "vtkUnstructuredVolumeIndexBuffer.h"
#include "vtkUnstructuredVolumeOpenGL.h"

#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

#include <algorithm>
#include <cstdint>
#include <vector>

class vtkUnstructuredVolumeCellDrawer
{
public:
  static constexpr int ChunkSize = 16384; // tetrahedra per draw of the vertex-pulling route

  /// Chooses the route; the pattern is uploaded once (it never changes).
  void Sync(bool pulling)
  {
    this->Pulling = pulling;
    if (pulling && !this->FaceIndices.Holds(1))
      this->FaceIndices.Sync(FacePattern(ChunkSize), 1);
  }

  /// Draws places [first, first + count) of `list` with `program` (bound).
  void Draw(vtkOpenGLState* state, vtkShaderProgram* program, vtkUnstructuredVolumeBufferTexture& list,
    std::size_t first, std::size_t count)
  {
    list.Bind(program, "cellList");
    if (!this->Pulling)
    {
      uvgl::DrawItemsInChunks(program, "listOffset", GL_POINTS, count, 1, first);
    }
    else
    {
      // Culling only here: the full-screen passes' triangle is a front face.
      state->vtkglEnable(GL_CULL_FACE);
      state->vtkglCullFace(GL_FRONT); // back faces: each ray leaves a tetrahedron through one
      for (std::size_t done = 0; done < count; done += ChunkSize)
      {
        const std::size_t chunk = std::min<std::size_t>(ChunkSize, count - done);
        program->SetUniformi("listOffset", static_cast<int>(first + done));
        this->FaceIndices.Draw(GL_TRIANGLES, 12 * chunk);
      }
      state->vtkglCullFace(GL_BACK);
      state->vtkglDisable(GL_CULL_FACE);
    }
    list.Unbind();
  }

  void Release() { this->FaceIndices.Release(); }
  std::size_t GetBytes() const { return this->FaceIndices.GetBytes(); }

private:
  /// The four faces of tetrahedron q as vertices 4q + k, wound outwards when v1 - v0, v2 - v0, v3 - v0
  /// are positively oriented.
  static std::vector<std::uint32_t> FacePattern(int tetrahedra)
  {
    static const int faces[12] = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 };
    std::vector<std::uint32_t> indices(12 * static_cast<std::size_t>(tetrahedra));
    for (int q = 0; q < tetrahedra; ++q)
      for (int i = 0; i < 12; ++i)
        indices[12 * q + i] = static_cast<std::uint32_t>(4 * q + faces[i]);
    return indices;
  }

  vtkUnstructuredVolumeIndexBuffer FaceIndices;
  bool Pulling = true;
};

#endif
