/**
 * @class vtkHexahedralRayCastPrograms
 * @brief Every shader program vtkHexahedralRayCastMapper can use, by its options.
 *
 * Two programs per peel: the entry pass (boundary faces, no options) and the full-screen traversal,
 * whose defines follow the transfer function's node count, the scalar's kind, skipping and the
 * isosurfaces' gradients. The mapper resamples the transfer
 * function to the uniform capacity, so it uses NodeTexture = false; the traversal also builds with
 * the node texture, and Testing/Cxx/TestEmbeddedShaders compiles both, so lifting that limit needs
 * no shader work. (OpenGL layer; not wrapped.)
 */
#ifndef vtkHexahedralRayCastPrograms_h
#define vtkHexahedralRayCastPrograms_h

#include "uvFullScreenTriangleVS.h"
#include "uvHexahedralEntryFS.h"
#include "uvHexahedralEntryVS.h"
#include "uvHexahedralTraverseFS.h"
#include "vtkUnstructuredVolumeOpenGL.h"

#include <string>
#include <vector>

struct vtkHexahedralRayCastPrograms
{
  struct TraversalOptions
  {
    bool NodeTexture = false; // more transfer-function nodes than fit in uniforms
    bool CellScalars = false; // one scalar per cell (cell data), constant inside it
    bool SkipInvisibleCells = false; // rays leave the visible region to the next peel
    bool VertexGradients = false; // isosurfaces lit by interpolated vertex gradients (point scalars only)
    bool CellDensities = false;   // some cells stand for coincident copies: their media add up
    int IntegrationMode = 0;      // vtkHexahedralRayCastMapper's: only its code is compiled
    int CellGeometry = 0;         // what every cell is (uv::MeshCellGeometry): only its code is compiled
    bool TangledCells = false;    // some cells fold over themselves: their parts are found as the reference's

    bool operator==(const TraversalOptions& other) const
    {
      return this->NodeTexture == other.NodeTexture && this->CellScalars == other.CellScalars &&
        this->SkipInvisibleCells == other.SkipInvisibleCells && this->VertexGradients == other.VertexGradients &&
        this->CellDensities == other.CellDensities && this->IntegrationMode == other.IntegrationMode &&
        this->CellGeometry == other.CellGeometry && this->TangledCells == other.TangledCells;
    }
  };

  static uvgl::ProgramSources Entry()
  {
    uvgl::ProgramSources sources;
    sources.Vertex = uvgl::ShaderSource(uvHexahedralEntryVS, "");
    sources.Fragment = uvgl::ShaderSource(uvHexahedralEntryFS, "");
    return sources;
  }

  static uvgl::ProgramSources Traversal(const TraversalOptions& options)
  {
    uvgl::ProgramSources sources;
    sources.Vertex = uvFullScreenTriangleVS;
    std::string defines = uvgl::TransferFunctionDefines(options.NodeTexture);
    if (options.CellScalars)
      defines += "#define UV_CELL_SCALARS\n";
    if (options.SkipInvisibleCells)
      defines += "#define UV_SKIP_INVISIBLE_CELLS\n";
    if (options.VertexGradients)
      defines += "#define UV_VERTEX_GRADIENTS\n";
    if (options.CellDensities)
      defines += "#define UV_CELL_DENSITIES\n";
    defines += "#define UV_INTEGRATION_MODE " + std::to_string(options.IntegrationMode) + "\n";
    if (options.CellGeometry >= 1)
      defines += "#define UV_ALL_CELLS_CONVEX\n"; // no bilinear face to solve
    if (options.CellGeometry >= 2)
      defines += "#define UV_ALL_PARALLELEPIPEDS\n"; // no collapsed or curved cell either
    if (options.TangledCells && options.CellGeometry == 0)
      defines += "#define UV_TANGLED_CELLS\n"; // a convex cell does not fold
    sources.Fragment = uvgl::ShaderSource(uvHexahedralTraverseFS, defines);
    return sources;
  }

  /// The variants a test compiles: every combination of the flags, each with an integration mode and
  /// a cell geometry taken in turn, so that every pair of those two appears (all of their products
  /// with the flags would be nine times as many programs to link, for no define they share); every
  /// other variant of the general geometry has folded cells.
  static std::vector<TraversalOptions> AllTraversalOptions()
  {
    std::vector<TraversalOptions> all;
    for (bool nodeTexture : { false, true })
      for (bool cellScalars : { false, true })
        for (bool skip : { false, true })
          for (bool vertexGradients : { false, true })
            for (bool densities : { false, true })
              if (!(cellScalars && vertexGradients)) // a cell scalar's surfaces are lit by their faces
              {
                const int turn = static_cast<int>(all.size());
                const int geometry = (turn / 3) % 3;
                all.push_back({ nodeTexture, cellScalars, skip, vertexGradients, densities, turn % 3, geometry,
                  geometry == 0 && turn % 2 == 0 });
              }
    return all;
  }
};

#endif
