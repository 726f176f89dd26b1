// The cells of any vtkDataSet as vtkHexahedralRayCastMapper's passes read them: 8 point ids per
// cell (tetrahedra, pyramids and wedges as collapsed hexahedra), the recentred points with the normalised point scalar (vtkuvRecentredPoints.h) or
// one normalised value per cell for cell data, face adjacency and boundary faces (uvHexahedralMesh.h),
// rebuilt only when the input's cells or its scalar's selection change (positions and values alone are
// refreshed); the dataset they index, for vertex gradients. Reads VTK data through the generic cell API,
// so no input type needs a conversion.
#ifndef vtkuvHexahedralMesh_h
#define vtkuvHexahedralMesh_h

#include "uvHexahedralMesh.h"
#include "uvNonConformingFaces.h"
#include "uvOverlappingCells.h"
#include "uvLinearCellSplit.h"
#include "uvScalarNormalisation.h"
#include "vtkuvMeshContent.h"
#include "vtkuvMeshIntegrity.h"
#include "vtkuvRecentredPoints.h"
#include "vtkuvTetrahedralMesh.h"

#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkHexahedraToTetrahedra.h"
#include "vtkHigherOrderSubdivision.h"
#include "vtkCellData.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace vtkuv
{

/// Unstructured grids; structured grids, whose blanked cells are empty and skipped; image data and
/// rectilinear grids, as voxels. Cells touching a NaN scalar are left out; folded cells are counted.
class HexahedralMesh
{
public:
  std::vector<std::uint32_t> CellPoints; // 8 per cell, VTK hexahedron order
  std::vector<float> CellScalars;        // per cell, normalised, for a cell scalar (else empty)
  std::vector<float> CellDensities;      // per cell, the copies it stands for (else empty: none repeats)
  uv::CellGeometry Geometry = uv::CellGeometry::Any; // what every cell is: the walk compiles only that
  RecentredPoints Points;
  uv::HexahedralFaces Faces;
  // What CellPoints' ids index (the input, or its subdivision) and the scalar rendered on it, as of
  // the last build: vertex gradients are computed on these.
  vtkSmartPointer<vtkDataSet> Drawn;
  RenderedScalar DrawnScalar;
  vtkIdType TangledCells = 0, NaNCells = 0;
  // Where cells fold, which cells overlap which (uvOverlappingCells.h; empty without folded cells),
  // and the same packed for the GPU.
  uv::OverlapPartners Overlaps;
  std::vector<std::int32_t> PackedOverlaps;
  std::size_t NonConformingFaces = 0; ///< boundary faces lying against another cell's (faults)
  vtkIdType FlatCells = 0; // vertices, lines and polygons: not volumes, left out
  int Builds = 0, PointRefreshes = 0, ValueRefreshes = 0;
  std::uint64_t Version = 0;      // bumped by every change: positions, values, cells
  std::uint64_t CellsVersion = 0; // CellPoints and Faces: bumped by builds only

  std::size_t CellCount() const { return this->CellPoints.size() / 8; }
  std::size_t BoundaryCount() const { return this->Faces.Boundary.size() / 4; }

  /// Brings the mesh up to date with `input` and its rendered scalar (`built` true when it was
  /// rebuilt), judged by content, not by which objects hold it: an unstructured grid whose cells are
  /// those built from (a reader's time step) only has its positions or values refreshed, keeping the
  /// face adjacency, unless a NaN left a cell out or brought one back. Returns an error message,
  /// empty on success. `progress` goes from 0 to 1 over a build.
  std::string Update(
    vtkDataSet* input, const RenderedScalar& scalar, const std::function<void(double)>& progress, bool& built)
  {
    built = false;
    const MeshChanges changed = this->Seen.Update(input, scalar);
    if (!changed.Any())
    {
      return std::string();
    }
    auto* cells = vtkUnstructuredGridBase::SafeDownCast(input);
    const std::string broken = cells ? FindMeshIntegrityError(cells, changed.Cells, changed.Points) : std::string();
    if (!broken.empty())
    {
      this->Invalidate();
      return broken;
    }
    if (this->Valid && !changed.Cells && !this->Subdivided && this->Refresh(input, scalar, changed))
    {
      ++this->Version;
      ++(changed.Values ? this->ValueRefreshes : this->PointRefreshes);
      return std::string();
    }
    std::string error = this->Build(input, scalar, progress);
    if (!error.empty())
    {
      this->Invalidate();
      return error;
    }
    this->Valid = built = true;
    return error;
  }

  /// Forgets the build: the next Update rebuilds.
  void Invalidate()
  {
    this->Valid = false;
    this->Seen.Forget();
  }

private:
  MeshContent Seen;
  bool Valid = false; // built from what Seen holds

  /// New positions and values of the cells built from; false when the cells drawn would differ.
  bool Refresh(vtkDataSet* input, const RenderedScalar& scalar, const MeshChanges& changed)
  {
    if (!this->CellDensities.empty())
      return false; // which cells coincide may change with the points or values: built again
    std::vector<std::uint32_t> cells = std::move(this->CellPoints);
    std::vector<float> cellScalars = std::move(this->CellScalars);
    const uv::ScalarNormalisation normalisation = this->Points.Normalisation;
    this->Points.Build(input, scalar, &normalisation);
    if (changed.Values)
    {
      this->ReadCells(input);
      if (this->CellPoints != cells)
        return false;
    }
    else
    {
      this->CellPoints = std::move(cells);
      this->CellScalars = std::move(cellScalars);
    }
    if (changed.Points)
    {
      this->FindFoldedCells();
      this->Geometry = uv::MeshCellGeometry(this->CellPoints, this->Points.Values, vtkuv::ParallelFor);
      // Which faces lie against which depends on where the points are; the neighbours' GPU copy
      // follows the cells' version, so a mesh with such faces is built again.
      if (this->NonConformingFaces > 0 ||
        uv::LinkNonConformingFaces(this->CellPoints, this->Points.Values, this->Faces) > 0)
        return false;
    }
    this->Drawn = input;
    this->DrawnScalar = scalar;
    return true;
  }

  std::string Build(vtkDataSet* input, const RenderedScalar& scalar, const std::function<void(double)>& progress)
  {
    progress(0.0); // the adjacency can take seconds on large meshes
    ++this->Version;
    ++this->CellsVersion;
    this->Drawn = nullptr;
    this->DrawnScalar = RenderedScalar();
    RenderedScalar drawn = scalar;
    vtkDataSet* linear = this->Linearise(input, drawn);
    if (!linear)
    {
      return "the higher-order cells cannot be subdivided, or the prisms and polyhedra split (see the errors above)";
    }
    std::string range = IndexRangeError("points", linear->GetNumberOfPoints(), 1);
    range = range.empty() ? IndexRangeError("cells", linear->GetNumberOfCells(), 8) : range;
    if (!range.empty())
    {
      return range;
    }
    this->Points.Build(linear, drawn);
    const vtkIdType others = this->ReadCells(linear);
    if (others > 0)
    {
      this->CellPoints.clear();
      this->Faces = uv::HexahedralFaces();
      return std::to_string(others) + " 3D cells are of types the walk cannot take nor split";
    }
    const std::vector<std::uint32_t> samePoint = uv::CoincidentPointRepresentatives(
      this->Points.Values, [](auto begin, auto end, auto less) { vtkSMPTools::Sort(begin, end, less); });
    this->MergeCoincidentCells(samePoint);
    this->FindFoldedCells();
    this->Geometry = uv::MeshCellGeometry(this->CellPoints, this->Points.Values, vtkuv::ParallelFor);
    this->Faces = uv::MakeHexahedralFaces(
      this->CellPoints, samePoint, vtkuv::ParallelFor, [](auto begin, auto end) { vtkSMPTools::Sort(begin, end); },
      [&progress](double fraction) { progress(0.8 * fraction); });
    this->NonConformingFaces = uv::LinkNonConformingFaces(this->CellPoints, this->Points.Values, this->Faces);
    this->Drawn = linear;
    this->DrawnScalar = drawn;
    ++this->Builds;
    progress(1.0);
    return std::string();
  }

  /// TangledCells, and where there are any, which cells overlap (OverlapPartners).
  void FindFoldedCells()
  {
    this->TangledCells =
      static_cast<vtkIdType>(uv::CountTangledHexahedra(this->CellPoints, this->Points.Values, vtkuv::ParallelFor));
    this->Overlaps = uv::OverlapPartners();
    this->PackedOverlaps.clear();
    if (this->TangledCells == 0)
      return;
    this->Overlaps = uv::FindOverlapPartners(this->CellPoints, this->Points.Values, vtkuv::ParallelFor);
    this->PackedOverlaps = this->Overlaps.Packed();
  }

public:
  std::size_t Bytes() const
  {
    return sizeof(std::uint32_t) * this->CellPoints.size() + sizeof(float) * this->Points.Values.size() +
      sizeof(float) * (this->CellScalars.size() + this->CellDensities.size()) +
      sizeof(std::int32_t) * (this->Faces.Neighbours.size() + this->Faces.Boundary.size() + this->PackedOverlaps.size());
  }

private:
  /// `input` itself, or where it holds higher-order cells, its subdivision into linear ones
  /// (vtkHigherOrderSubdivision, its field tolerance on the rendered array), with `scalar` moved
  /// onto it. Null when the subdivision fails.
  vtkDataSet* Linearise(vtkDataSet* input, RenderedScalar& scalar)
  {
    this->Subdivided = nullptr;
    this->Mixed = nullptr;
    bool curved = false;
    for (vtkIdType c = 0; c < input->GetNumberOfCells() && !curved; ++c)
      curved = vtkHigherOrderSubdivision::IsSubdividedCellType(input->GetCellType(c));
    vtkDataSet* linear = input;
    if (curved)
    {
      vtkNew<vtkHigherOrderSubdivision> subdivision;
      subdivision->SetInputData(input);
      if (!scalar.OnCells)
        subdivision->SetFieldArrayName(scalar.Array->GetName());
      subdivision->Update();
      this->Subdivided = subdivision->GetOutput();
      scalar = scalar.On(this->Subdivided);
      if (!(this->Subdivided->GetNumberOfCells() > 0 && scalar))
        return nullptr;
      linear = this->Subdivided;
    }
    return this->SplitOthers(linear, scalar);
  }

  /// `grid` itself, or where it holds 3D cells the walk does not take as collapsed hexahedra
  /// (pentagonal and hexagonal prisms, polyhedra), a grid with those split into tetrahedra by
  /// vtkHexahedraToTetrahedra and the rest as they are. The split keeps the point ids (polyhedra
  /// may add centres after them), so the tetrahedra join the same walk: by ids where the faces
  /// match, and through uvNonConformingFaces.h where a quad of a hexahedron meets two triangles.
  vtkDataSet* SplitOthers(vtkDataSet* grid, RenderedScalar& scalar)
  {
    vtkNew<vtkIdList> others;
    VolumeCellTypes volume;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    {
      const int type = grid->GetCellType(c);
      if (!AsHexahedron(type) && type != VTK_EMPTY_CELL && volume(type))
        others->InsertNextId(c);
    }
    auto* unstructured = vtkUnstructuredGrid::SafeDownCast(grid);
    if (others->GetNumberOfIds() == 0 || !unstructured)
      return grid;
    vtkNew<vtkUnstructuredGrid> toSplit; // the other cells alone, on all the points
    toSplit->SetPoints(unstructured->GetPoints());
    toSplit->GetPointData()->ShallowCopy(unstructured->GetPointData());
    toSplit->Allocate(others->GetNumberOfIds());
    vtkNew<vtkIdList> ids;
    for (vtkIdType i = 0; i < others->GetNumberOfIds(); ++i)
    {
      unstructured->GetFaceStream(others->GetId(i), ids);
      toSplit->InsertNextCell(unstructured->GetCellType(others->GetId(i)), ids);
    }
    vtkNew<vtkHexahedraToTetrahedra> split;
    split->SetInputData(toSplit);
    split->Update();
    vtkUnstructuredGrid* tetrahedra = split->GetOutput();
    vtkDataArray* parents = tetrahedra->GetCellData()->GetArray("vtkOriginalCellIds");
    this->Mixed = vtkSmartPointer<vtkUnstructuredGrid>::New();
    this->Mixed->SetPoints(tetrahedra->GetPoints());
    this->Mixed->GetPointData()->ShallowCopy(tetrahedra->GetPointData());
    vtkCellData* cellData = this->Mixed->GetCellData();
    cellData->CopyAllocate(unstructured->GetCellData());
    this->Mixed->Allocate(grid->GetNumberOfCells() + tetrahedra->GetNumberOfCells());
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    {
      if (!AsHexahedron(grid->GetCellType(c)))
        continue;
      unstructured->GetCellPoints(c, ids);
      cellData->CopyData(unstructured->GetCellData(), c, this->Mixed->InsertNextCell(grid->GetCellType(c), ids));
    }
    for (vtkIdType t = 0; t < tetrahedra->GetNumberOfCells() && parents; ++t)
    {
      tetrahedra->GetCellPoints(t, ids);
      const vtkIdType parent = others->GetId(static_cast<vtkIdType>(parents->GetComponent(t, 0)));
      cellData->CopyData(unstructured->GetCellData(), parent, this->Mixed->InsertNextCell(VTK_TETRA, ids));
    }
    scalar = scalar.On(this->Mixed);
    return scalar ? this->Mixed.Get() : nullptr;
  }

  vtkSmartPointer<vtkUnstructuredGrid> Subdivided; // the linear hexahedra drawn for higher-order ones
  vtkSmartPointer<vtkUnstructuredGrid> Mixed;      // with prisms and polyhedra split into tetrahedra

  /// Cells that repeat another (uv::CoincidentCellDensities) become one cell of their count's density.
  void MergeCoincidentCells(const std::vector<std::uint32_t>& samePoint)
  {
    std::vector<float> density = uv::CoincidentCellDensities<8>(this->CellPoints, samePoint, this->Points.Values,
      this->CellScalars, [](auto begin, auto end, auto less) { vtkSMPTools::Sort(begin, end, less); });
    this->CellDensities.clear();
    if (density.empty())
      return;
    std::size_t kept = 0;
    for (std::size_t c = 0; c < density.size(); ++c)
    {
      if (density[c] == 0.0f)
        continue; // merged into the first of its copies
      std::copy_n(this->CellPoints.begin() + 8 * c, 8, this->CellPoints.begin() + 8 * kept);
      if (!this->CellScalars.empty())
        this->CellScalars[kept] = this->CellScalars[c];
      this->CellDensities.push_back(density[c]);
      ++kept;
    }
    this->CellPoints.resize(8 * kept);
    if (!this->CellScalars.empty())
      this->CellScalars.resize(kept);
  }

  /// Where a cell's points go among a hexahedron's 8 corners (uvHexahedralMesh.h's orders), or
  /// null for a cell the walk cannot take.
  static const std::array<int, 8>* AsHexahedron(int type)
  {
    static constexpr std::array<int, 8> identity = { 0, 1, 2, 3, 4, 5, 6, 7 };
    switch (type)
    {
      case VTK_HEXAHEDRON:
        return &identity;
      case VTK_VOXEL:
        return &uv::VoxelToHexahedronOrder;
      case VTK_TETRA:
        return &uv::TetrahedronAsHexahedron;
      case VTK_PYRAMID:
        return &uv::PyramidAsHexahedron;
      case VTK_WEDGE:
        return &uv::WedgeAsHexahedron;
      default:
        return nullptr;
    }
  }

  /// Whether cells of `type` are 3D (VTK's own cell says; the higher-order tetrahedra to hexahedra,
  /// which VTK 9.1 cannot stand up empty, are).
  static bool IsVolumeCell(int type)
  {
    if (type == VTK_LAGRANGE_PYRAMID || type == VTK_BEZIER_PYRAMID ||
      (type >= VTK_HIGHER_ORDER_TETRAHEDRON && type <= VTK_HIGHER_ORDER_HEXAHEDRON))
      return true;
    vtkNew<vtkGenericCell> probe;
    probe->SetCellType(type);
    return probe->GetCellDimension() == 3;
  }

  /// IsVolumeCell, asked once per cell type (it stands a cell up to ask).
  struct VolumeCellTypes
  {
    std::array<signed char, 256> Known; // per cell type: 1 3D, 0 not, -1 not asked yet
    VolumeCellTypes() { this->Known.fill(-1); }
    bool operator()(int type)
    {
      signed char& known = this->Known[static_cast<std::size_t>(type)];
      if (known < 0)
        known = IsVolumeCell(type) ? 1 : 0;
      return known == 1;
    }
  };

  /// The hexahedra, voxels (reordered), tetrahedra, pyramids and wedges (as collapsed hexahedra) of
  /// `grid` into CellPoints, leaving out those that touch a NaN point scalar or hold a NaN cell
  /// scalar, and the cells that are not 3D (counted in FlatCells). Returns how many 3D cells are none
  /// of these (not drawable here).
  vtkIdType ReadCells(vtkDataSet* grid)
  {
    const bool onCells = !this->Points.CellValues.empty();
    this->CellPoints.clear();
    this->CellScalars.clear();
    this->NaNCells = 0;
    this->FlatCells = 0;
    vtkIdType others = 0;
    VolumeCellTypes volume;
    vtkNew<vtkIdList> cellIds;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    {
      const int type = grid->GetCellType(c);
      if (type == VTK_EMPTY_CELL)
        continue; // blanked
      const std::array<int, 8>* order = AsHexahedron(type);
      if (!order)
      {
        ++(volume(type) ? others : this->FlatCells);
        continue;
      }
      grid->GetCellPoints(c, cellIds);
      const vtkIdType* ids = cellIds->GetPointer(0);
      std::array<std::uint32_t, 8> corners;
      for (int k = 0; k < 8; ++k)
        corners[k] = static_cast<std::uint32_t>(ids[(*order)[k]]);
      const bool finite = onCells ? std::isfinite(this->Points.CellValues[c])
                                  : uv::ScalarsFinite(this->Points.Values, corners.data(), 8);
      if (!finite)
      {
        ++this->NaNCells;
        continue;
      }
      this->CellPoints.insert(this->CellPoints.end(), corners.begin(), corners.end());
      if (onCells)
        this->CellScalars.push_back(this->Points.CellValues[c]);
    }
    return others;
  }
};

} // namespace vtkuv

#endif
