/**
 * @class vtkBarycentricShellBlendPass
 * @brief vtkBarycentricShellMapper's integration of one shell into the float target.
 *
 * A full-screen pass (uvBarycentricShellBlendFS.glsl) composites the shell's slices, and the
 * isosurface layers inside it, front to back under what nearer shells left (ONE_MINUS_DST_ALPHA,
 * ONE). Owns the fixed-length segment table (uvPreIntegration.h SegmentTable), rebuilt only when the
 * nodes or the sample distance it was built for change, compared exactly. (OpenGL layer of the
 * barycentric shell mapper; not wrapped.)
 */
#ifndef vtkBarycentricShellBlendPass_h
#define vtkBarycentricShellBlendPass_h

#include "uvOpticalModel.h"
#include "uvPreIntegration.h"
#include "vtkBarycentricShellPrograms.h"
#include "vtkBarycentricShellSlicePass.h"
#include "vtkUnstructuredVolumeFloatTarget.h"
#include "vtkUnstructuredVolumeTexture.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <vector>

class vtkBarycentricShellBlendPass
{
public:
  static constexpr int TableSize = 256; // texels per side of the segment table
  int TableBuilds = 0;                  ///< since creation

  /// The table of whole segments of `length` under `nodes`, unless it is the one on the GPU.
  void SyncTable(vtkOpenGLRenderWindow* window, const std::vector<uv::TransferFunction::Node>& nodes, double length)
  {
    if (this->Table.IsCreatedFor(window) && length == this->TableLength && nodes == this->TableNodes)
      return;
    const std::vector<float> texels =
      uv::SegmentTable(uv::TransferFunction(nodes), length, TableSize, [](int count, const auto& function) {
        vtkSMPTools::For(0, count, 1, [&](vtkIdType begin, vtkIdType end) {
          for (vtkIdType row = begin; row < end; ++row)
            function(static_cast<int>(row));
        });
      });
    this->Table.Sync(window, TableSize, TableSize, 4, texels, vtkUnstructuredVolumeTexture::Filter::Linear);
    this->TableLength = length;
    this->TableNodes = nodes;
    ++this->TableBuilds;
  }

  /// The uniforms that hold for every shell (`program` bound, its integration uniforms and the
  /// isosurface layers set): `layers` drawn, the sample distance and, with `table`, the table.
  void Begin(vtkShaderProgram* program, int layers, double sampleDistance, bool table)
  {
    program->SetUniformf("sampleDistance", static_cast<float>(sampleDistance));
    program->SetUniformi("isosurfaceLayers", layers);
    if (table)
    {
      this->Table.Bind(program, "segmentTable");
      program->SetUniformf("segmentTableSize", static_cast<float>(TableSize));
    }
    this->TableBound = table;
  }

  /// Composites the shell starting at `shellStart` from `slices` under the target's image.
  void Run(vtkOpenGLState* state, const vtkBarycentricShellPrograms& programs, vtkShaderProgram* program,
    vtkUnstructuredVolumeFloatTarget& target, vtkBarycentricShellSlicePass& slices, float shellStart)
  {
    target.GetFramebuffer()->Bind();
    target.GetFramebuffer()->ActivateDrawBuffers(1);
    programs.Use(program);
    program->SetUniformf("shellStart", shellStart);
    slices.BindSlices(program);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ONE_MINUS_DST_ALPHA, GL_ONE);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    slices.UnbindSlices();
  }

  void End()
  {
    if (this->TableBound)
      this->Table.Unbind();
    this->TableBound = false;
  }

  void Release()
  {
    this->Table.Release();
    this->TableNodes.clear();
    this->TableLength = 0.0;
  }

private:
  vtkUnstructuredVolumeTexture Table;
  std::vector<uv::TransferFunction::Node> TableNodes;
  double TableLength = 0.0;
  bool TableBound = false;
};

#endif
