/**
 * @class vtkHexahedralRayCastMapper
 * @brief GPU ray casting of hexahedral meshes with the exact trilinear field along each ray.
 *
 * After "Volume rendering of unstructured hexahedral meshes" (Miranda and Celes). No split into
 * tetrahedra: each ray walks the hexahedra by face adjacency on the GPU (mesh in buffer textures),
 * starting from the boundary faces an entry pass rasterises; depth peeling picks rays up again
 * where they leave a non-convex mesh and re-enter it. Faces are the exact bilinear patches through
 * their corners, parameterised from their smallest point id by every cell that shares them, so the
 * exit one cell finds is bitwise the entry of the next and the walk is watertight; the rasterised
 * triangles of the boundary faces only choose which pixels test a face. A ray that passes within
 * rounding of an edge or corner, where no face claims it, is relocated to the cell just ahead.
 *
 * Along a ray inside a cell the scalar is the cubic of the trilinear field in the cell's affine
 * frame (exact for any parallelepiped, in any orientation); on curved cells, with ExactSegmentEnds
 * (default), the cubic through exact values at the segment's ends and two inner points, otherwise
 * the frame's approximation. The integral is split at the cubic's extrema and at transfer-function
 * nodes (safeguarded Newton per monotonic interval), then:
 * - ACCURATE: Gauss-Legendre on each piece, exact optical depth (the paper's Hexa_ACC);
 * - FAST: the scalar linear between split points, pre-integrated with the Psi table (Hexa_FAST);
 * - FIXED_STEPS: FixedSteps constant steps per cell (Hexa_CONST), for comparison.
 * The math is uvHexahedronRay.h (unit-tested); Shaders/Hexahedra/uvHexahedralTraverseFS.glsl (and its sections)
 * is its GPU twin.
 *
 * Isosurfaces (any number, each with a colour and opacity) are further split points: where the
 * cubic crosses an isovalue the surface is composited, Phong-lit from the vtkVolumeProperty and the
 * renderer's first light with the exact gradient of the cell's trilinear field (GradientMode
 * CELL_GRADIENTS, the default here: faceted on coarse cells), or with VERTEX_GRADIENTS the vertex
 * gradients interpolated by the cell's own trilinear weights at the hit (smooth). Isosurfaces of a
 * cell scalar are lit by their faces either way.
 *
 * Skipped work: rays stop once their opacity reaches OpacityThreshold (default 0.999); with
 * SkipInvisibleCells (default) rays enter only where the cells the transfer function makes visible
 * (or that hold an isovalue) start (after the iSBVR paper's culling surfaces, uvVisibleRegion.h): at
 * the front of that region; over an invisible run inside the mesh they walk a few invisible cells and
 * leave the rest to the next peel's entry faces, and past the box of the visible cells they stop.
 * Rays that meet the region nowhere cost only the entry pass. The image is the full walk's. Without
 * skipping a transparent cell costs one range test, no integration. The traversal program is
 * compiled for the integration mode and for what every cell of the mesh is (uv::MeshCellGeometry):
 * where all are convex with planar faces a ray leaves each through its nearest face plane, and
 * where all are parallelepipeds the curved and collapsed cells' code is left out too (a CPU driver
 * runs every branch that any pixel of a SIMD group takes).
 *
 * The traversal reads transfer-function nodes from uniforms: a function with more than
 * uvgl::MaximumUniformNodes nodes after TransferFunctionTolerance is approximated by fewer (with a
 * warning). Rays begin at the near plane: where it lies inside the mesh (the camera inside it, or
 * just outside with the near plane beyond a boundary face), the first peel starts every ray at its
 * near-plane point, walking there from the cell holding the eye or the near plane's centre.
 *
 * Input: any vtkDataSet of hexahedra, voxels, wedges, pyramids and tetrahedra with a point or cell
 * scalar (the base's selection; a cell scalar is one value per cell, constant along the ray inside
 * it): vtkUnstructuredGrid, and vtkStructuredGrid (blanked cells left out), vtkImageData and
 * vtkRectilinearGrid as they are, with no conversion. Wedges, pyramids and tetrahedra walk as
 * hexahedra with repeated corners, whose trilinear map is their own isoparametric map (a
 * tetrahedron's field is linear along the ray; triangular faces are flat). Higher-order cells are
 * subdivided first (vtkHigherOrderSubdivision). Other 3D cells (polyhedra, pentagonal and hexagonal
 * prisms) are split into tetrahedra on the way (vtkHexahedraToTetrahedra, on the same points), which
 * join the same walk. Meshes of tetrahedra alone are handed to vtkPreIntegratedTetrahedraMapper
 * (DelegateTetrahedralMeshes). Cells touching a NaN scalar are left out (one
 * warning); folded (tangled) cells are rendered, with a warning per mesh build. A ray takes a folded
 * cell's parts as the reference does (the stretches between its face hits that Newton from the
 * centre maps into the cell) and its field by Newton from the centre (a program variant for meshes
 * with such cells). The cells a folded cell overlaps are found once per mesh build (sampled, so an
 * overlap thinner than a sixth of a cell may be missed); where they overlap, the walk adds their
 * media as the reference does, by midpoint steps over that cell's segment, and rays also enter the
 * mesh through their inner faces (a fold may push them out through the boundary). Isosurfaces there
 * keep one cell's medium.
 */
#ifndef vtkHexahedralRayCastMapper_h
#define vtkHexahedralRayCastMapper_h

#include "vtkUnstructuredVolumeMapper.h"
#include "vtkUnstructuredVolumeModule.h" // for export macro

#include <memory> // for std::unique_ptr

class vtkDataArray;
class vtkDataSet;
class vtkVolumeProperty;

class VTKUNSTRUCTUREDVOLUME_EXPORT vtkHexahedralRayCastMapper : public vtkUnstructuredVolumeMapper
{
public:
  static vtkHexahedralRayCastMapper* New();
  vtkTypeMacro(vtkHexahedralRayCastMapper, vtkUnstructuredVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum IntegrationModes
  {
    ACCURATE = 0,
    FAST = 1,
    FIXED_STEPS = 2
  };
  ///@{
  vtkSetClampMacro(IntegrationMode, int, ACCURATE, FIXED_STEPS);
  vtkGetMacro(IntegrationMode, int);
  void SetIntegrationModeToAccurate() { this->SetIntegrationMode(ACCURATE); }
  void SetIntegrationModeToFast() { this->SetIntegrationMode(FAST); }
  void SetIntegrationModeToFixedSteps() { this->SetIntegrationMode(FIXED_STEPS); }
  ///@}

  ///@{
  /// Steps per cell in FIXED_STEPS mode (default 8).
  vtkSetClampMacro(FixedSteps, int, 1, 1024);
  vtkGetMacro(FixedSteps, int);
  ///@}

  ///@{
  /// Curved cells: map each segment's ends and two inner points (a quarter from each end) into
  /// the cell by the isoparametric inverse (Newton) rather than the affine frame (default on). The
  /// field along the ray is then exact at every face crossing, so continuous from cell to cell,
  /// and between them the cubic through the four exact values. Parallelepipeds (no bilinear terms)
  /// skip this: their frame is exact. Off is the frame alone on every cell (cheaper).
  vtkSetMacro(ExactSegmentEnds, bool);
  vtkGetMacro(ExactSegmentEnds, bool);
  vtkBooleanMacro(ExactSegmentEnds, bool);
  ///@}

  ///@{
  /// Depth-peeling passes at most (non-convex meshes, holes); default 8. With skipping, each run of
  /// visible cells along a ray after a gap longer than InvisibleRunLimit takes one too: raise it
  /// where rays cross more of those than that.
  vtkSetClampMacro(MaximumPeels, int, 1, 64);
  vtkGetMacro(MaximumPeels, int);
  ///@}

  ///@{
  /// With skipping, how many invisible cells in a row a ray walks through before it leaves the rest
  /// of its path to the next peel's entry faces. 0 (default): the cells across the mesh (the cube
  /// root of the count, at least 16), since a peel costs more than walking a shorter gap.
  vtkSetClampMacro(InvisibleRunLimit, int, 0, VTK_INT_MAX);
  vtkGetMacro(InvisibleRunLimit, int);
  ///@}

  ///@{
  /// Hand meshes of tetrahedra alone to a vtkPreIntegratedTetrahedraMapper (default on): on them the
  /// field is linear in each cell, that mapper draws it as exactly (its own route, projection or
  /// ray casting), and its walk steps through a tetrahedron with far less work than this one, which
  /// carries every cell shape's code. Not handed over: FIXED_STEPS (a comparison of this walk's
  /// own), a cell scalar's isosurfaces (drawn here as faces between cells) and isosurfaces lit by
  /// CELL_GRADIENTS (that mapper lights with vertex gradients). The mapper's input, scalar
  /// selection, isosurfaces and base settings go with the mesh; IntegrationMode, FixedSteps,
  /// ExactSegmentEnds and MaximumPeels do not apply (SegmentIntegration does). The statistic
  /// Delegated tells whether the last frame was handed over; the others then describe no frame.
  vtkSetMacro(DelegateTetrahedralMeshes, bool);
  vtkGetMacro(DelegateTetrahedralMeshes, bool);
  vtkBooleanMacro(DelegateTetrahedralMeshes, bool);
  ///@}

  /// Cells, points, adjacency, boundary faces and vertex gradients (not the screen-sized images).
  vtkIdType GetMeshMemoryInBytes() override;

  /// Any vtkDataSet (the superclass takes vtkUnstructuredGridBase only).
  using Superclass::SetInputData;
  void SetInputData(vtkDataSet* input) override;

protected:
  /// The statistics (GetFrameStatistics) the caster adds: Delegated (above); of the last frame,
  /// Cells in the mesh, BoundaryFaces, Peels run, TangledCells (folded over themselves; warned
  /// about once per mesh build) and OverlappingPairs (pairs of cells whose volumes overlap, one of
  /// them folded); GradientComputations, the times vtkVertexGradientFilter ran since
  /// creation (VERTEX_GRADIENTS without a gradient array); and with skipping (SkipInvisibleCells)
  /// VisibleCells the walk takes (every cell when off), EntryFaces rays enter them by (the visible
  /// region's boundary, or the mesh's) and VisibleRegionBuilds (only when a transfer-function or
  /// isovalue edit changes which cells are visible).
  void ReportStatistics(vtkUnstructuredVolumeFrameStatistics* statistics) override;

  vtkHexahedralRayCastMapper();
  ~vtkHexahedralRayCastMapper() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  bool Prepare(const vtkUnstructuredVolumeFrame& frame) override;
  bool Upload(const vtkUnstructuredVolumeFrame& frame) override;
  bool Draw(const vtkUnstructuredVolumeFrame& frame, vtkUnstructuredVolumeFloatTarget& target) override;
  void ReleaseMapperGraphics() override;
  void ForgetMesh() override;
  void GetDrawnBounds(double bounds[6]) override;

  int IntegrationMode = ACCURATE;
  int FixedSteps = 8;
  bool ExactSegmentEnds = true;
  int MaximumPeels = 8;
  int InvisibleRunLimit = 0;
  bool DelegateTetrahedralMeshes = true;

private:
  vtkHexahedralRayCastMapper(const vtkHexahedralRayCastMapper&) = delete;
  void operator=(const vtkHexahedralRayCastMapper&) = delete;

  bool UpdateMesh(vtkDataSet* input, const vtkuv::RenderedScalar& scalar);
  bool HandsOver(vtkDataSet* input, const vtkuv::RenderedScalar& scalar);

  class Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
