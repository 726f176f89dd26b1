/**
 * @class vtkPreIntegratedTetrahedraPrograms
 * @brief Every shader program vtkPreIntegratedTetrahedraMapper can use, by its options.
 *
 * The mapper compiles Sources(options) for the frame's options; Testing/Cxx/TestEmbeddedShaders
 * compiles Sources of every entry of AllOptions(), so a define combination that does not compile
 * fails a test rather than a user's frame. (OpenGL layer; not wrapped.)
 */
#ifndef vtkPreIntegratedTetrahedraPrograms_h
#define vtkPreIntegratedTetrahedraPrograms_h

#include "uvBarycentricPullVS.h"
#include "uvFullScreenTriangleVS.h"
#include "uvPreIntegratedTetrahedraFS.h"
#include "uvPreIntegratedTetrahedraGS.h"
#include "uvPreIntegratedTetrahedraVS.h"
#include "uvTetrahedralWalkFS.h"
#include "vtkUnstructuredVolumeOpenGL.h"

#include <string>
#include <vector>

struct vtkPreIntegratedTetrahedraPrograms
{
  /// What of the view volume may cut the mesh's faces: nothing; only its sides or far plane; or the
  /// near plane, where rays begin (the fans then ray-cast the tetrahedra it cuts).
  enum class Clipping
  {
    None,
    Sides,
    NearPlane
  };

  struct Options
  {
    bool VertexPulling = true; // faces pulled (UV_FACES); else a geometry shader emits the fans
    bool Gradients = false;    // vertex gradients for lighting
    bool NodeTexture = false;  // more transfer-function nodes than fit in uniforms
    bool CellSurfaces = false; // a cell scalar's isosurfaces, on the faces between cells
    bool SegmentTable = false; // one table read per segment (no isosurfaces, no shading)
    bool OpaqueDepth = true;   // opaque geometry may have been drawn: its depth ends segments
    bool RayCasting = false;   // full screen, rays walk the tetrahedra (no cell surfaces; ignores the route)
    Clipping Clips = Clipping::NearPlane; // NearPlane: UV_NEAR_PLANE_CUTS; None: faces carry their ray
  };

  static uvgl::ProgramSources Sources(const Options& options)
  {
    std::string defines = uvgl::TransferFunctionDefines(options.NodeTexture);
    if (options.Gradients)
      defines += "#define UV_GRADIENTS\n";
    if (options.CellSurfaces)
      defines += "#define UV_CELL_SURFACES\n";
    if (options.SegmentTable)
      defines += "#define UV_SEGMENT_TABLE\n";
    if (options.Clips == Clipping::NearPlane)
      defines += "#define UV_NEAR_PLANE_CUTS\n";
    if (options.OpaqueDepth)
      defines += "#define UV_OPAQUE_DEPTH\n";
    if (options.VertexPulling && !options.RayCasting)
    {
      defines += "#define UV_FACES\n#define UV_DEPTH_RAY\n";
      // A pixel's ray is affine on screen, so the faces can carry it (uvBarycentricTetrahedronLib.glsl)
      // where nothing clips them: Mesa's clipper interpolates such attributes wrongly at the vertices
      // it makes.
      if (options.Clips == Clipping::None)
        defines += "#define UV_RAY_ATTRIBUTE\n";
    }
    uvgl::ProgramSources sources;
    if (options.RayCasting)
    {
      // At the far plane: the walk's depth test against the entry depth skips pixels no ray enters.
      sources.Vertex = uvgl::ShaderSource(uvFullScreenTriangleVS, "#define UV_AT_FAR_PLANE\n");
      sources.Fragment = uvgl::ShaderSource(uvTetrahedralWalkFS, defines);
      return sources;
    }
    if (options.VertexPulling)
    {
      sources.Vertex = uvgl::ShaderSource(uvBarycentricPullVS, defines);
    }
    else
    {
      sources.Vertex = uvgl::ShaderSource(uvPreIntegratedTetrahedraVS, defines);
      sources.Geometry = uvgl::ShaderSource(uvPreIntegratedTetrahedraGS, defines);
    }
    sources.Fragment = uvgl::ShaderSource(uvPreIntegratedTetrahedraFS, defines);
    return sources;
  }

  static std::vector<Options> AllOptions()
  {
    std::vector<Options> all;
    for (bool depth : { true, false })
      for (bool pulling : { true, false })
        for (Clipping clips : { Clipping::NearPlane, Clipping::Sides, Clipping::None })
        {
          if (!pulling && clips == Clipping::None)
            continue; // the fans' sources are those of Clipping::Sides
          for (bool gradients : { false, true })
            for (bool nodeTexture : { false, true })
              all.push_back({ pulling, gradients, nodeTexture, false, false, depth, false, clips });
          all.push_back({ pulling, false, false, true, false, depth, false, clips });
          all.push_back({ pulling, false, false, false, true, depth, false, clips });
        }
    for (bool depth : { true, false })
    {
      for (bool gradients : { false, true })
        for (bool nodeTexture : { false, true })
          all.push_back({ true, gradients, nodeTexture, false, false, depth, true, Clipping::Sides });
      all.push_back({ true, false, false, false, true, depth, true, Clipping::Sides });
    }
    return all;
  }
};

#endif
