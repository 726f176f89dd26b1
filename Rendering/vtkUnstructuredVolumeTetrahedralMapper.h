/**
 * @class vtkUnstructuredVolumeTetrahedralMapper
 * @brief The base of the two mappers that draw tetrahedra: the mesh, its lists, order and buffers.
 *
 * vtkPreIntegratedTetrahedraMapper and vtkBarycentricShellMapper both turn their input into
 * tetrahedra (vtkuv::TetrahedralMesh), draw a list of them chosen by the transfer function, some in
 * a visibility order, with vertex gradients and a cell scalar's values across faces, from the same
 * GPU buffers. That state (vtkUnstructuredVolumeTetrahedralState) and the steps over it live here,
 * once: the mesh update with its errors and warnings, the isosurfaces' commit, the drawn list, the
 * gradients, the order, the choice of the segment-length table, the drawn bounds and the shared
 * statistics (DrawnTetrahedra, Sorts, GradientComputations). Each subclass keeps its state in an
 * Internals derived from the shared state and hands it over through GetTetrahedralState.
 */
#ifndef vtkUnstructuredVolumeTetrahedralMapper_h
#define vtkUnstructuredVolumeTetrahedralMapper_h

#include "vtkUnstructuredVolumeMapper.h"
#include "vtkUnstructuredVolumeModule.h" // for export macro

struct vtkUnstructuredVolumeTetrahedralState;

class VTKUNSTRUCTUREDVOLUME_EXPORT vtkUnstructuredVolumeTetrahedralMapper : public vtkUnstructuredVolumeMapper
{
public:
  vtkTypeMacro(vtkUnstructuredVolumeTetrahedralMapper, vtkUnstructuredVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkUnstructuredVolumeTetrahedralMapper();
  ~vtkUnstructuredVolumeTetrahedralMapper() override;

  /// The subclass's state (its Internals).
  virtual vtkUnstructuredVolumeTetrahedralState& GetTetrahedralState() = 0;

  /// Brings the mesh to `input` and its rendered `scalar`: rebuilt when the cells or the scalar
  /// changed, the points or values refreshed when only they did (MeshUpdates follows). Reports an
  /// error, warns once of what the mesh left out, and makes the order stale for new cells. False
  /// on error or when no tetrahedron is left.
  bool UpdateTetrahedralMesh(vtkUnstructuredGridBase* input, const vtkuv::RenderedScalar& scalar);

  /// After CommitTransferFunction: the isovalues of the drawn isosurfaces and, for a cell scalar
  /// (`cellScalar`) with some, the values across faces its surfaces are drawn from.
  void CommitIsosurfaces(bool cellScalar);

  /// Vertex gradients where `needed` (NeedGradients), once per change of the mesh or its scalar.
  void UpdateGradients(bool needed);

  /// The drawn list's visibility order from this frame's eye, by VisibilityOrder, sorted again only
  /// when the view, the points or the list changed; `frontToBack` or back to front.
  void UpdateOrder(const vtkUnstructuredVolumeFrame& frame, bool frontToBack);

  /// Whether this frame reads whole segments from the segment-length table: not where the segments
  /// must be cut (`cutsNeeded`: isosurfaces, shading) or SegmentIntegration is EXACT; else TABLE, or
  /// AUTOMATIC within TransferFunctionTolerance. The table is built first where the nodes or the
  /// longest segment changed.
  bool ChooseLengthTable(const vtkUnstructuredVolumeFrame& frame, bool cutsNeeded);

  void GetDrawnBounds(double bounds[6]) override;
  void ReportStatistics(vtkUnstructuredVolumeFrameStatistics* statistics) override;

private:
  vtkUnstructuredVolumeTetrahedralMapper(const vtkUnstructuredVolumeTetrahedralMapper&) = delete;
  void operator=(const vtkUnstructuredVolumeTetrahedralMapper&) = delete;
};

#endif
