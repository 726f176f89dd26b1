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
#include "uvBarycentricRayLib.h"
#include "uvBarycentricShellGS.h"
#include "uvBarycentricTetrahedronLib.h"
#include "uvFullScreenTriangleVS.h"
#include "uvPhongLib.h"
#include "uvSegmentIntegrationLib.h"
#include "uvTransferFunctionLib.h"
#include "vtkUnstructuredVolumeOpenGL.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"

#include <string>
#include <utility>

class vtkBarycentricShellPrograms
{
public:
  vtkBarycentricShellPrograms(vtkOpenGLRenderWindow* window, std::string defines, bool pulling)
    : Cache(window->GetShaderCache())
    , Defines(std::move(defines))
  {
    const std::initializer_list<std::pair<const char*, const char*>> tetrahedron = {
      { "//UV::BarycentricTetrahedron", uvBarycentricTetrahedronLib }
    };
    this->CellVertex =
      uvgl::ShaderSource(pulling ? uvBarycentricPullVS : uvBarycentricCellListVS, this->Defines, tetrahedron);
    if (!pulling)
      this->CellGeometry = uvgl::ShaderSource(uvBarycentricShellGS, this->Defines, tetrahedron);
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
    const std::string fragmentSource = uvgl::ShaderSource(fragment, this->Defines,
      { { "//UV::BarycentricRay", uvBarycentricRayLib }, { "//UV::TransferFunction", uvTransferFunctionLib },
        { "//UV::Phong", uvPhongLib }, { "//UV::SegmentIntegration", uvSegmentIntegrationLib } });
    return this->Cache->ReadyShaderProgram(vertex.c_str(), fragmentSource.c_str(), geometry.c_str());
  }

  vtkOpenGLShaderCache* Cache;
  std::string Defines, CellVertex, CellGeometry, ScreenVertex;
};

#endif
