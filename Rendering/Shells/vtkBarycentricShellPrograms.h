/**
 * @class vtkBarycentricShellPrograms
 * @brief vtkBarycentricShellMapper's programs for one frame: its passes over the tetrahedra and its
 * full-screen passes, all compiled with the frame's defines and the shared GLSL libraries.
 *
 * The passes over tetrahedra take the chosen route's vertex stage (uvBarycentricPullVS.glsl, or
 * uvBarycentricCellListVS.glsl and the geometry stage uvBarycentricShellGS.glsl) with the tetrahedron
 * library; every fragment stage gets the ray, transfer-function, Phong and segment libraries it marks.
 * (OpenGL layer of the barycentric shell mapper; not wrapped.)
 */
#ifndef vtkBarycentricShellPrograms_h
#define vtkBarycentricShellPrograms_h

#include "uvBarycentricCellListVS.h"
#include "uvBarycentricPullVS.h"
#include "uvBarycentricShellGS.h"
#include "uvFullScreenTriangleVS.h"
#include "vtkUnstructuredVolumeOpenGL.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"

#include <string>
#include <utility>
#include <vector>

class vtkBarycentricShellPrograms
{
public:
  /// What the frame's programs are compiled for.
  struct Options
  {
    int Slices = 7, Targets = 2, Layers = 1; // slices per shell, their render targets, isosurface layers
    bool VertexGradients = false, CellGradients = false; // lighting from vertex or cell gradients
    bool SegmentTable = false, OpaqueGeometry = false, Textured = false, NodeTexture = false;
    bool CellSurfaces = false; // cell projection of a cell scalar with isosurfaces (faces between cells)
    bool CellDensities = false; // shells over tetrahedra that stand for coincident copies
  };

  /// Where the shells' slices hold a tetrahedron of density d, its value (scalar + 1, in [1, 2]) is
  /// raised by this times d - 1: the MAX blend still keeps one cell's value per slice, and the
  /// blending stage reads both back.
  static constexpr float DensityStride = 4.0f;

  static std::string DefinesFor(const Options& options)
  {
    std::string defines = uvgl::TransferFunctionDefines(options.NodeTexture) + "#define UV_SLICES " +
      std::to_string(options.Slices + 1) + "\n#define UV_TARGETS " + std::to_string(options.Targets) +
      "\n#define UV_MAX_LAYERS " + std::to_string(options.Layers) + "\n";
    if (options.VertexGradients)
      defines += "#define UV_GRADIENTS\n";
    else if (options.CellGradients)
      defines += "#define UV_CELL_GRADIENTS\n";
    if (options.SegmentTable)
      defines += "#define UV_SEGMENT_TABLE\n";
    if (options.OpaqueGeometry)
      defines += "#define UV_OPAQUE_GEOMETRY\n";
    if (options.Textured)
      defines += "#define UV_TEXTURE\n";
    if (options.CellSurfaces)
      defines += "#define UV_CELL_SURFACES\n";
    if (options.CellDensities)
      defines += "#define UV_CELL_DENSITIES\n#define UV_DENSITY_STRIDE " + std::to_string(DensityStride) + "\n";
    return defines;
  }

  /// Every flag combination at the default sizes, and the smallest and largest sizes with no flag
  /// (what Testing/Cxx/TestEmbeddedShaders compiles).
  static std::vector<Options> AllOptions()
  {
    std::vector<Options> all;
    for (int lighting = 0; lighting < 3; ++lighting)
      for (int flags = 0; flags < 16; ++flags)
      {
        Options options;
        options.VertexGradients = lighting == 1;
        options.CellGradients = lighting == 2;
        options.SegmentTable = flags & 1;
        options.OpaqueGeometry = flags & 2;
        options.Textured = flags & 4;
        options.NodeTexture = flags & 8;
        all.push_back(options);
      }
    Options cellSurfaces;
    cellSurfaces.CellSurfaces = true;
    all.push_back(cellSurfaces);
    for (bool table : { false, true })
    {
      Options densities;
      densities.CellDensities = true;
      densities.SegmentTable = table;
      all.push_back(densities);
    }
    Options smallest, largest;
    smallest.Slices = 3;
    smallest.Targets = 1;
    largest.Slices = 31;
    largest.Targets = 8;
    largest.Layers = 8;
    all.push_back(smallest);
    all.push_back(largest);
    return all;
  }

  vtkBarycentricShellPrograms(vtkOpenGLRenderWindow* window, std::string defines, bool pulling)
    : Cache(window->GetShaderCache())
    , Defines(std::move(defines))
  {
    this->CellVertex =
      uvgl::ShaderSource(pulling ? uvBarycentricPullVS : uvBarycentricCellListVS, this->Defines);
    if (!pulling)
      this->CellGeometry = uvgl::ShaderSource(uvBarycentricShellGS, this->Defines);
    this->ScreenVertex = uvgl::ShaderSource(uvFullScreenTriangleVS, this->Defines);
  }

  /// A program over the tetrahedra with `fragment`, bound; null when it does not compile.
  vtkShaderProgram* OverCells(const char* fragment) const
  {
    return this->Ready(this->CellVertex, fragment, this->CellGeometry);
  }
  /// A full-screen program with `fragment`, bound; null when it does not compile.
  vtkShaderProgram* FullScreen(const char* fragment) const { return this->Ready(this->ScreenVertex, fragment, ""); }
  /// Binds `program` again (uniforms go to the bound program).
  void Use(vtkShaderProgram* program) const { this->Cache->ReadyShaderProgram(program); }

private:
  vtkShaderProgram* Ready(const std::string& vertex, const char* fragment, const std::string& geometry) const
  {
    const std::string fragmentSource = uvgl::ShaderSource(fragment, this->Defines);
    return this->Cache->ReadyShaderProgram(vertex.c_str(), fragmentSource.c_str(), geometry.c_str());
  }

  vtkOpenGLShaderCache* Cache;
  std::string Defines, CellVertex, CellGeometry, ScreenVertex;
};

#endif
