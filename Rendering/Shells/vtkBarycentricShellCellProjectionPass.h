/**
 * @class vtkBarycentricShellCellProjectionPass
 * @brief vtkBarycentricShellMapper's cell projection: every drawn tetrahedron, back to front,
 * integrates its whole segment (uvBarycentricCellProjectionFS.glsl) over the float target.
 *
 * Owns the visibility order's list, uploaded only when the order is sorted again. (OpenGL layer of
 * the barycentric shell mapper; not wrapped.)
 */
#ifndef vtkBarycentricShellCellProjectionPass_h
#define vtkBarycentricShellCellProjectionPass_h

#include "vtkUnstructuredVolumeCellDrawer.h"
#include "vtkUnstructuredVolumeBufferTexture.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkUnstructuredVolumeCompatibility.h" // the OpenGL loader

#include <cstdint>
#include <vector>

class vtkBarycentricShellCellProjectionPass
{
public:
  /// The order (uploaded when `version` is new).
  void SyncOrder(vtkOpenGLRenderWindow* window, const std::vector<std::uint32_t>& order, std::uint64_t version)
  {
    if (!order.empty())
      this->Order.Sync(window, order, 1, version);
  }

  /// Draws the first `count` tetrahedra of the order with `program` (bound, its uniforms set).
  void Run(vtkOpenGLState* state, vtkShaderProgram* program, vtkUnstructuredVolumeCellDrawer& drawer, std::size_t count)
  {
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_FALSE);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    drawer.Draw(state, program, this->Order, 0, count);
  }

  std::size_t GetBytes() const { return this->Order.GetBytes(); }
  void Release() { this->Order.Release(); }

private:
  vtkUnstructuredVolumeBufferTexture Order;
};

#endif
