/**
 * @struct vtkUnstructuredVolumeTetrahedralState
 * @brief What both tetrahedral mappers keep between frames, and its GPU copies.
 *
 * The tetrahedral mesh and what is derived from it (the draw lists, the visibility order, the vertex
 * gradients, a cell scalar's values across faces, the segment-length table), the normalised
 * transfer function and isosurfaces, and the buffers and textures that hold them on the GPU. Each
 * piece carries the version it was built from, so a frame rebuilds or uploads only what changed.
 *
 * Each tetrahedral mapper's Internals derives from it and adds its own passes;
 * vtkUnstructuredVolumeTetrahedralMapper runs the steps that need the mapper (errors, warnings,
 * settings) over it. Not wrapped.
 */
#ifndef vtkUnstructuredVolumeTetrahedralState_h
#define vtkUnstructuredVolumeTetrahedralState_h

#include "uvCellVisibility.h"
#include "uvIsosurfaceList.h"
#include "vtkUnstructuredVolumeBufferTexture.h"
#include "vtkUnstructuredVolumeCellDrawer.h"
#include "vtkUnstructuredVolumeSegmentLengthTable.h"
#include "vtkUnstructuredVolumeTexture.h"
#include "vtkUnstructuredVolumeTransferFunctionTexture.h"
#include "vtkuvNormalisedTransferFunction.h"
#include "vtkuvTetrahedralMesh.h"
#include "vtkuvVertexGradientCache.h"

#include <cstdint>
#include <utility>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkShaderProgram;

struct vtkUnstructuredVolumeTetrahedralState
{
  virtual ~vtkUnstructuredVolumeTetrahedralState() = default;

  // ---- CPU state, each piece versioned for its GPU copy.
  vtkuv::TetrahedralMesh Mesh;
  vtkuv::NormalisedTransferFunction TransferFunction;
  std::vector<uv::Isosurface> DrawnIsosurfaces; // normalised like the scalar
  std::vector<double> Isovalues;                // their values, in order
  uv::CellLists Lists;                          // the drawn tetrahedra, and the volume's and isosurfaces' shares
  vtkuv::VertexGradientCache Gradients;
  vtkuv::VisibilityOrder Order; // for the tetrahedra drawn one by one
  // A cell scalar's isosurfaces lie on the faces between cells: per tetrahedron the values across
  // its faces, and its scalar range widened to them (so a transparent tetrahedron whose face holds a
  // surface is still drawn).
  uv::TetrahedronFaceNeighbours CellSurfaces;
  std::uint64_t CellSurfacesBuiltFor = 0;              // the mesh's CellsVersion
  vtkUnstructuredVolumeSegmentLengthTable LengthTable; // whole segments through tetrahedra, one read each

  // ---- What this frame draws.
  bool NeedGradients = false;    // vertex gradients light something
  bool DrawCellSurfaces = false; // a cell scalar's isosurfaces
  vtkIdType DrawnTetrahedra = 0;

  // ---- GPU copies.
  vtkUnstructuredVolumeBufferTexture TetrahedronPoints, Points, PointGradients, NeighbourValues;
  vtkUnstructuredVolumeTransferFunctionTexture Nodes;
  vtkUnstructuredVolumeTexture Isosurfaces;
  vtkUnstructuredVolumeCellDrawer Cells; // vertex pulling: the faces of each drawn tetrahedron

  /// The values across each tetrahedron's faces, when the cells changed.
  void UpdateCellSurfaces()
  {
    if (this->CellSurfacesBuiltFor == this->Mesh.CellsVersion)
      return;
    this->CellSurfaces = this->Mesh.CellFaceNeighbours();
    this->CellSurfacesBuiltFor = this->Mesh.CellsVersion;
  }

  /// Which tetrahedra are drawn: those with some extinction in their range (every one, unless
  /// `skipInvisible`) or an isovalue in it, a cell scalar's range widened to the values across its
  /// faces. A new list makes the order stale. False when none is drawn.
  bool UpdateLists(bool skipInvisible)
  {
    const auto zeroSet = skipInvisible ? uv::ZeroExtinctionIntervals(this->TransferFunction.Nodes)
                                       : std::vector<std::pair<double, double>>();
    const bool widened = this->DrawCellSurfaces;
    if (this->Lists.Update(2 * this->Mesh.CellsVersion + (widened ? 1 : 0),
          widened ? this->CellSurfaces.Low : this->Mesh.ScalarLow,
          widened ? this->CellSurfaces.High : this->Mesh.ScalarHigh, zeroSet, this->Isovalues, vtkuv::ParallelFor))
      this->Order.Invalidate();
    return !this->Lists.Drawn.empty();
  }

  /// The mesh's buffers, each only when its version changed (a deforming mesh pays the points'
  /// upload alone). True when the cells or the points were uploaded.
  bool UploadMesh(vtkOpenGLRenderWindow* window)
  {
    const bool cells = this->TetrahedronPoints.Sync(window, this->Mesh.TetrahedronPoints, 4, this->Mesh.TopologyVersion);
    const bool points = this->Points.Sync(window, this->Mesh.PointData, 4, this->Mesh.Version);
    if (this->NeedGradients)
      this->PointGradients.Sync(window, this->Gradients.Values, 4, this->Gradients.Version);
    if (this->DrawCellSurfaces)
      this->NeighbourValues.Sync(window, this->CellSurfaces.Values, 4, this->CellSurfacesBuiltFor);
    return cells || points;
  }

  /// The transfer function's nodes and the isosurfaces. True when the nodes were uploaded.
  bool UploadTransferFunction(vtkOpenGLRenderWindow* window)
  {
    const bool nodes = this->Nodes.Sync(window, this->TransferFunction.Nodes);
    this->Isosurfaces.Sync(window, uv::IsosurfaceList::TexelColumns(this->DrawnIsosurfaces), 2, 4,
      uv::IsosurfaceList::Texels(this->DrawnIsosurfaces));
    return nodes;
  }

  /// Binds what every program over the tetrahedra reads: the cells, the points, the nodes and the
  /// isosurfaces, and the gradients and the values across faces where this frame uses them.
  void BindMesh(vtkShaderProgram* program)
  {
    this->TetrahedronPoints.Bind(program, "tetrahedronPoints");
    this->Points.Bind(program, "pointData");
    this->Nodes.Bind(program);
    this->Isosurfaces.Bind(program, "isosurfaces");
    if (this->NeedGradients)
      this->PointGradients.Bind(program, "pointGradients");
    if (this->DrawCellSurfaces)
      this->NeighbourValues.Bind(program, "neighbourValues");
  }

  /// Releases the texture units BindMesh took.
  void UnbindMesh()
  {
    this->TetrahedronPoints.Unbind();
    this->Points.Unbind();
    this->Nodes.Unbind();
    this->Isosurfaces.Unbind();
    if (this->NeedGradients)
      this->PointGradients.Unbind();
    if (this->DrawCellSurfaces)
      this->NeighbourValues.Unbind();
  }

  /// Frees the GPU copies (the context is current).
  void ReleaseTetrahedralGraphics()
  {
    for (vtkUnstructuredVolumeBufferTexture* texture :
      { &this->TetrahedronPoints, &this->Points, &this->PointGradients, &this->NeighbourValues })
      texture->Release();
    this->Nodes.Release();
    this->Isosurfaces.Release();
    this->LengthTable.Release();
    this->Cells.Release();
  }
};

#endif
