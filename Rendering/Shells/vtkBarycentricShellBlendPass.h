/**
 * @class vtkBarycentricShellBlendPass
 * @brief vtkBarycentricShellMapper's integration of one shell into the float target.
 *
 * A full-screen pass (uvBarycentricShellBlendFS.glsl) composites the shell's slices, and the
 * isosurface layers inside it, front to back under what nearer shells left (ONE_MINUS_DST_ALPHA,
 * ONE). Holds the GPU copy of the segment table (vtkBarycentricShellSegmentTable), uploaded when its
 * version changes. (OpenGL layer of the barycentric shell mapper; not wrapped.)
 */
#ifndef vtkBarycentricShellBlendPass_h
#define vtkBarycentricShellBlendPass_h

#include "vtkBarycentricShellPrograms.h"
#include "vtkBarycentricShellSegmentTable.h"
#include "vtkBarycentricShellSlicePass.h"
#include "vtkUnstructuredVolumeFloatTarget.h"
#include "vtkUnstructuredVolumeTexture.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

#include <cstdint>
#include <vector>

class vtkBarycentricShellBlendPass
{
public:
  /// The table's texels, unless this version is the one on the GPU.
  void SyncTable(vtkOpenGLRenderWindow* window, const vtkBarycentricShellSegmentTable& table)
  {
    if (this->Table.IsCreatedFor(window) && table.Version == this->TableVersion)
      return;
    this->Table.Sync(window, table.Size, table.Size, 4, table.Texels, vtkUnstructuredVolumeTexture::Filter::Linear);
    this->TableVersion = table.Version;
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
      program->SetUniformf("segmentTableSize", static_cast<float>(vtkBarycentricShellSegmentTable::Size));
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
    this->TableVersion = 0;
  }

private:
  vtkUnstructuredVolumeTexture Table;
  std::uint64_t TableVersion = 0;
  bool TableBound = false;
};

#endif
