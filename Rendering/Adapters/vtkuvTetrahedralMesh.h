// The tetrahedra of a mapper's input as the tetrahedral mappers upload them (vtkPreIntegratedTetrahedra-
// Mapper, vtkBarycentricShellMapper): other linear cells split, a normalised scalar, recentred float
// positions, per-tetrahedron scalar ranges and centroids; the cells the transfer function makes
// invisible (vertex gradients: vtkuvVertexGradientCache.h). Reads VTK data; the mappers'
// GPU code is elsewhere.
#ifndef vtkuvTetrahedralMesh_h
#define vtkuvTetrahedralMesh_h

#include "uvBoundaryGapOrder.h"
#include "uvCellVisibility.h"
#include "uvFaceAdjacencyOrder.h"
#include "uvCoincidentCells.h"
#include "uvHexahedralMesh.h"
#include "uvOpticalModel.h"
#include "uvVisibilitySort.h"
#include "vtkuvMeshContent.h"
#include "vtkuvMeshIntegrity.h"
#include "vtkuvRecentredPoints.h"
#include "vtkuvRenderedScalar.h"
#include "vtkuvVertexGradientCache.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkHexahedraToTetrahedra.h"
#include "vtkIdTypeArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace vtkuv
{

/// vtkSMPTools::For over [0, count) in the (begin, end) form the VTK-free helpers take.
inline void ParallelFor(std::size_t count, const std::function<void(std::size_t, std::size_t)>& function)
{
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), [&](vtkIdType begin, vtkIdType end) {
    function(static_cast<std::size_t>(begin), static_cast<std::size_t>(end));
  });
}

class TetrahedralMesh
{
public:
  /// What the last Update changed.
  enum class Change
  {
    Nothing,
    Points, ///< only the point positions (a deforming mesh): PointData's xyz
    Values, ///< the scalar's values (and maybe the points: PositionsVersion), the same tetrahedra drawn
    All
  };

  vtkSmartPointer<vtkUnstructuredGrid> Tetrahedra; // the input, or its split
  vtkSmartPointer<vtkDataArray> Scalars;           // the rendered array of Tetrahedra
  RenderedScalar Scalar;                           // what of it is rendered (Array == Scalars)
  std::vector<std::uint32_t> TetrahedronPoints;    // 4 uploaded point ids per drawable tetrahedron
  std::vector<float> PointData;                    // recentred position and normalised scalar
  // For a cell scalar every tetrahedron has 4 points of its own carrying its value (the field is
  // constant in it and jumps at its faces); this is the Tetrahedra point each one copies. Empty for a
  // point scalar, whose points are Tetrahedra's.
  std::vector<std::uint32_t> CornerPoints;
  std::vector<float> ScalarLow, ScalarHigh;        // per tetrahedron, normalised
  glm::dvec3 Center{ 0.0 };
  uv::ScalarNormalisation Normalisation;          // of the rendered scalar's finite values
  vtkIdType SplitCells = 0;       // input cells that were not tetrahedra, as of the last build
  vtkIdType NaNTetrahedra = 0;    // tetrahedra left out for a NaN scalar
  int Builds = 0, PointRefreshes = 0, ValueRefreshes = 0;
  // Versions of what the GPU copies: bumped by every change (so from 1 after the first build).
  std::uint64_t Version = 0;      // anything: positions, scalar, cells
  std::uint64_t CellsVersion = 0; // ScalarLow/High and TetrahedronPoints (not a point-only refresh)
  std::uint64_t TopologyVersion = 0; // TetrahedronPoints alone (not a refresh leaving the same drawn)
  std::uint64_t PositionsVersion = 0; // PointData's positions: builds and refreshes that moved points

  std::size_t Size() const { return this->TetrahedronPoints.size() / 4; }
  /// The bounds of the drawn tetrahedra's points (a curved cell's subdivision can reach beyond the
  /// input's nodes); false before the first build.
  bool DrawnBounds(double bounds[6]) const
  {
    if (!this->Tetrahedra)
      return false;
    this->Tetrahedra->GetBounds(bounds);
    return true;
  }
  /// Host bytes of the copies above (not the input or its split).
  std::size_t GetBytes() const
  {
    return sizeof(std::uint32_t) * (this->TetrahedronPoints.capacity() + this->CornerPoints.capacity()) +
      sizeof(float) * (this->PointData.capacity() + this->ScalarLow.capacity() + this->ScalarHigh.capacity());
  }
  /// Recentred corner k of tetrahedron t.
  glm::vec3 Corner(std::size_t t, int k) const
  {
    const float* p = &this->PointData[4 * std::size_t(this->TetrahedronPoints[4 * t + k])];
    return glm::vec3(p[0], p[1], p[2]);
  }
  /// Recentred centroid of tetrahedron t, computed when asked (kept, it would cost 12 bytes a cell).
  glm::vec3 Centroid(std::size_t t) const
  {
    return 0.25f * (this->Corner(t, 0) + this->Corner(t, 1) + this->Corner(t, 2) + this->Corner(t, 3));
  }
  bool OnCells() const { return this->Scalar.OnCells; }
  /// For a cell scalar's isosurfaces: per tetrahedron the values across its faces (shared faces of
  /// the input cells, matched by the input's point ids) and its scalar range widened to them.
  uv::TetrahedronFaceNeighbours CellFaceNeighbours() const
  {
    std::vector<std::uint32_t> corners(this->TetrahedronPoints.size());
    for (std::size_t i = 0; i < corners.size(); ++i)
      corners[i] = this->CornerPoints[this->TetrahedronPoints[i]];
    return uv::MakeTetrahedronFaceNeighbours(
      corners, this->ScalarLow, ParallelFor, [](auto begin, auto end) { vtkSMPTools::Sort(begin, end); });
  }
  /// Forgets the build: the next Update rebuilds.
  void Invalidate()
  {
    this->Seen.Forget();
    this->Built = false;
  }

  /// Brings the mesh up to date with `input` and its rendered scalar, judged by content, not by
  /// which objects hold it (a reader's time steps are new objects): when the cells are the same and
  /// only the points moved, just the positions are refreshed; when the scalar's values changed, the
  /// split, the drawn tetrahedra (unless a NaN left one out or brought one back) and what depends on
  /// them only are kept. Returns an error message, empty on success.
  std::string Update(vtkUnstructuredGridBase* input, const RenderedScalar& scalar,
    const std::function<void(double)>& progress, Change& change)
  {
    change = Change::Nothing;
    const MeshChanges changed = this->Seen.Update(input, scalar);
    if (!changed.Any())
    {
      return std::string();
    }
    const std::string broken = FindMeshIntegrityError(input, changed.Cells, changed.Points);
    if (!broken.empty())
    {
      this->Invalidate();
      return broken;
    }
    auto* grid = vtkUnstructuredGrid::SafeDownCast(input);
    if (this->Built && !changed.Cells && grid && this->KeepsInputPoints)
    {
      this->Adopt(grid, scalar, changed);
      ++this->Version;
      this->PositionsVersion += changed.Points ? 1 : 0;
      if (!changed.Values)
      {
        this->RefreshPoints();
        ++this->PointRefreshes;
        change = Change::Points;
        return std::string();
      }
      ++this->CellsVersion;
      ++this->ValueRefreshes;
      change = this->RefreshValues() ? Change::Values : Change::All;
      return std::string();
    }
    change = Change::All;
    ++this->Version;
    ++this->CellsVersion;
    ++this->TopologyVersion;
    ++this->PositionsVersion;
    std::string error = this->Build(input, scalar, progress);
    this->Built = error.empty();
    if (!this->Built)
    {
      this->Invalidate();
      return error;
    }
    this->KeepsInputPoints = this->SplitCells == 0 || (grid && this->Tetrahedra->GetPoints() == grid->GetPoints());
    ++this->Builds;
    return error;
  }

private:
  MeshContent Seen;
  bool Built = false;
  bool KeepsInputPoints = false; // the tetrahedra are the input's cells, or their split on its points

  /// Makes Tetrahedra show `grid`'s points and scalar, its cells being the same as those built from.
  void Adopt(vtkUnstructuredGrid* grid, const RenderedScalar& scalar, const MeshChanges& changed)
  {
    if (this->SplitCells == 0)
    {
      this->Tetrahedra = grid;
    }
    else
    {
      if (changed.Points)
        this->Tetrahedra->SetPoints(grid->GetPoints());
      if (changed.Values && !scalar.OnCells)
        this->Tetrahedra->GetPointData()->ShallowCopy(grid->GetPointData());
      if (changed.Values && scalar.OnCells)
        this->MoveCellScalar(scalar);
    }
    this->Scalar = this->SplitCells == 0 ? scalar : scalar.On(this->Tetrahedra);
    this->Scalars = this->Scalar.Array;
  }

  /// A cell scalar of the input onto the split's tetrahedra, through their original cell ids.
  void MoveCellScalar(const RenderedScalar& scalar)
  {
    vtkCellData* cells = this->Tetrahedra->GetCellData();
    auto* original = vtkIdTypeArray::SafeDownCast(cells->GetArray("vtkOriginalCellIds"));
    vtkSmartPointer<vtkDataArray> moved = vtk::TakeSmartPointer(scalar.Array->NewInstance());
    moved->SetName(scalar.Array->GetName());
    moved->SetNumberOfComponents(scalar.Array->GetNumberOfComponents());
    moved->SetNumberOfTuples(this->Tetrahedra->GetNumberOfCells());
    if (original)
    {
      vtkSMPTools::For(0, this->Tetrahedra->GetNumberOfCells(), [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType t = begin; t < end; ++t)
          moved->SetTuple(t, original->GetValue(t), scalar.Array);
      });
    }
    if (moved->GetName())
      cells->AddArray(moved);
    else
      cells->SetScalars(moved);
  }

  /// The normalised scalar, the drawn tetrahedra and their ranges again, from Tetrahedra's scalar.
  /// False when the drawn tetrahedra changed (a NaN appeared or went), which is then a new topology.
  bool RefreshValues()
  {
    RecentredPoints recentred;
    recentred.Build(this->Tetrahedra, this->Scalar, &this->Normalisation);
    this->PointData = std::move(recentred.Values);
    this->Center = recentred.Center;
    this->Normalisation = recentred.Normalisation;
    const std::vector<std::uint32_t> drawn = std::move(this->TetrahedronPoints);
    this->ReadTetrahedra(recentred.CellValues);
    this->WriteScalarRanges();
    if (this->TetrahedronPoints == drawn)
      return true;
    ++this->TopologyVersion;
    return false;
  }

  std::string Build(vtkUnstructuredGridBase* input, const RenderedScalar& scalar,
    const std::function<void(double)>& progress)
  {
    progress(0.0); // preparation (split, arrays) can take seconds on large meshes
    std::string error = this->SplitIntoTetrahedra(input, scalar, progress);
    error = error.empty() ? IndexRangeError("points", this->Tetrahedra->GetNumberOfPoints(), 1) : error;
    error = error.empty() ? IndexRangeError("tetrahedra", this->Tetrahedra->GetNumberOfCells(), 4) : error;
    if (!error.empty())
    {
      return error;
    }
    // Normalised scalar and recentred positions, in double then float.
    RecentredPoints recentred;
    recentred.Build(this->Tetrahedra, this->Scalar);
    this->PointData = std::move(recentred.Values);
    this->Center = recentred.Center;
    this->Normalisation = recentred.Normalisation;
    this->ReadTetrahedra(recentred.CellValues);
    this->WriteScalarRanges();
    progress(1.0);
    return std::string();
  }

  /// Tetrahedra := the input's cells as tetrahedra (the input itself when it has only those), and
  /// Scalar the same selection on it.
  std::string SplitIntoTetrahedra(
    vtkUnstructuredGridBase* input, const RenderedScalar& scalar, const std::function<void(double)>& progress)
  {
    vtkSmartPointer<vtkUnstructuredGrid> grid = vtkUnstructuredGrid::SafeDownCast(input);
    if (!grid)
    {
      grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
      grid->DeepCopy(input);
    }
    this->SplitCells = 0;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    {
      this->SplitCells += grid->GetCellType(c) != VTK_TETRA ? 1 : 0;
    }
    this->Scalar = scalar;
    if (this->SplitCells > 0)
    {
      vtkNew<vtkHexahedraToTetrahedra> split;
      split->SetInputData(grid);
      if (!scalar.OnCells)
        split->SetFieldArrayName(scalar.Array->GetName()); // higher-order cells: refine for what is drawn
      split->Update();
      vtkUnstructuredGrid* tets = vtkUnstructuredGrid::SafeDownCast(split->GetOutputDataObject(0));
      if (!tets || tets->GetNumberOfCells() == 0)
      {
        return "the input's cells cannot be split into tetrahedra (no 3D cells, or Lagrange or Bezier pyramids?)";
      }
      grid = tets;
      progress(0.5);
      this->Scalar = scalar.On(grid);
      if (!this->Scalar)
      {
        return "lost the scalar array while splitting the cells";
      }
    }
    this->Tetrahedra = grid;
    this->Scalars = this->Scalar.Array;
    return std::string();
  }

  /// TetrahedronPoints (and for a cell scalar CornerPoints and the corners' PointData) from the
  /// tetrahedra whose scalar is finite; `cellValues` holds a cell scalar's normalised values.
  void ReadTetrahedra(const std::vector<float>& cellValues)
  {
    vtkUnstructuredGrid* grid = this->Tetrahedra;
    const bool onCells = this->Scalar.OnCells;
    this->TetrahedronPoints.clear();
    this->TetrahedronPoints.reserve(4 * grid->GetNumberOfCells());
    this->CornerPoints.clear();
    if (onCells)
      this->CornerPoints.reserve(4 * grid->GetNumberOfCells());
    this->NaNTetrahedra = 0;
    std::vector<float> corners; // cell scalar: the corners' values
    vtkIdType npts;
    const vtkIdType* ids;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    {
      if (grid->GetCellType(c) != VTK_TETRA)
        continue;
      grid->GetCellPoints(c, npts, ids);
      if (onCells ? !std::isfinite(cellValues[c]) : !uv::ScalarsFinite(this->PointData, ids, 4))
      {
        ++this->NaNTetrahedra;
        continue;
      }
      for (int k = 0; k < 4; ++k)
      {
        const auto point = static_cast<std::uint32_t>(ids[k]);
        this->TetrahedronPoints.push_back(onCells ? static_cast<std::uint32_t>(this->CornerPoints.size()) : point);
        if (onCells)
        {
          this->CornerPoints.push_back(point);
          corners.push_back(cellValues[c]);
        }
      }
    }
    // Kept between frames: no room for the cells left out.
    this->TetrahedronPoints.shrink_to_fit();
    this->CornerPoints.shrink_to_fit();
    if (onCells)
    {
      this->PointData.assign(4 * corners.size(), 0.0f);
      for (std::size_t i = 0; i < corners.size(); ++i)
        this->PointData[4 * i + 3] = corners[i];
      this->WritePositions();
    }
  }

  void WriteScalarRanges()
  {
    const std::size_t tetCount = this->Size();
    this->ScalarLow.resize(tetCount);
    this->ScalarHigh.resize(tetCount);
    vtkSMPTools::For(0, static_cast<vtkIdType>(tetCount), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType t = begin; t < end; ++t)
      {
        float lo = std::numeric_limits<float>::infinity(), hi = -lo;
        for (int k = 0; k < 4; ++k)
        {
          const float s = this->PointData[4 * this->TetrahedronPoints[4 * t + k] + 3];
          lo = std::min(lo, s);
          hi = std::max(hi, s);
        }
        this->ScalarLow[t] = lo;
        this->ScalarHigh[t] = hi;
      }
    });
  }

  /// Positions relative to Center (of each corner's point, for a cell scalar).
  void WritePositions()
  {
    vtkPoints* points = this->Tetrahedra->GetPoints();
    const glm::dvec3 center = this->Center;
    const bool corners = this->Scalar.OnCells;
    const vtkIdType count =
      corners ? static_cast<vtkIdType>(this->CornerPoints.size()) : this->Tetrahedra->GetNumberOfPoints();
    vtkSMPTools::For(0, count, [&](vtkIdType begin, vtkIdType end) {
      double x[3];
      for (vtkIdType p = begin; p < end; ++p)
      {
        points->GetPoint(corners ? this->CornerPoints[p] : p, x);
        for (int d = 0; d < 3; ++d)
          this->PointData[4 * p + d] = static_cast<float>(x[d] - center[d]);
      }
    });
  }

  void RefreshPoints()
  {
    double bounds[6]; // recentred on the moved points, so far moves keep float's digits
    this->Tetrahedra->GetPoints()->GetBounds(bounds);
    this->Center = glm::dvec3(bounds[0] + bounds[1], bounds[2] + bounds[3], bounds[4] + bounds[5]) * 0.5;
    this->WritePositions();
  }
};

/// The warnings a mesh update owes the user as (key, message), for a mapper to give once per key:
/// cells split into tetrahedra and tetrahedra left out for a NaN scalar.
inline std::vector<std::pair<std::string, std::string>> MeshUpdateWarnings(
  const TetrahedralMesh& mesh, vtkIdType inputCells)
{
  std::vector<std::pair<std::string, std::string>> messages;
  if (mesh.SplitCells > 0)
  {
    messages.emplace_back("split cells", std::to_string(mesh.SplitCells) + " of " + std::to_string(inputCells) +
        " cells are not tetrahedra: splitting them with vtkHexahedraToTetrahedra (once per data change; "
        "split upstream to skip this)");
  }
  if (mesh.NaNTetrahedra > 0)
  {
    messages.emplace_back(
      "NaN cells", std::to_string(mesh.NaNTetrahedra) + " tetrahedra touch a NaN scalar and are not drawn");
  }
  return messages;
}

/// Tetrahedra in back-to-front order of their centroids' distance from the eye (along the view under
/// parallel projection; parallel radix sort), and with `exact`, that order changed where the faces
/// between tetrahedra say it is wrong (uvFaceAdjacencyOrder.h; the face adjacency is built on the
/// first exact order of new cells). Sorted again only when the view, `exact` or the mesh's positions
/// change, or after Invalidate (new cells).
class VisibilityOrder
{
public:
  std::vector<std::uint32_t> Order;
  int Sorts = 0;
  std::size_t CyclesBroken = 0; ///< of the last exact order
  std::size_t GapConstraints = 0; ///< pairs across a non-convex mesh's gaps in the last exact order
  std::uint64_t Version = 0; ///< bumped by every sort

  void Invalidate() { this->Valid = false; }

  /// Eye and view direction in the mesh's recentred frame; back to front, or front to back as its
  /// exact reverse (so that compositing either way sums the same terms). True when the order changed.
  /// With `exact`, `pixels` are the image's rays: across the gaps of a non-convex mesh the order is
  /// made exact along them (uvBoundaryGapOrder.h).
  bool Update(const TetrahedralMesh& mesh, const std::vector<std::uint32_t>& cells, const glm::dvec3& eye,
    const glm::dvec3& direction, bool parallel, bool frontToBack = false, bool exact = false,
    const uv::PixelGrid& pixels = {})
  {
    if (this->Valid && mesh.PositionsVersion == this->PositionsFor && eye == this->Eye &&
      direction == this->Direction && parallel == this->Parallel && exact == this->Exact &&
      (!exact || pixels == this->Pixels))
    {
      if (frontToBack == this->FrontToBack)
        return false;
      std::reverse(this->Order.begin(), this->Order.end());
      this->FrontToBack = frontToBack;
      ++this->Version;
      return true;
    }
    this->SortByCentroids(mesh, cells, eye, direction, parallel);
    this->CyclesBroken = 0;
    this->GapConstraints = 0;
    if (exact)
      this->FollowFaces(mesh, parallel ? -direction : eye, parallel, pixels);
    if (frontToBack)
      std::reverse(this->Order.begin(), this->Order.end());
    this->FrontToBack = frontToBack;
    this->Eye = eye;
    this->Direction = direction;
    this->Parallel = parallel;
    this->Exact = exact;
    this->Pixels = pixels;
    this->PositionsFor = mesh.PositionsVersion;
    this->Valid = true;
    ++this->Sorts;
    ++this->Version;
    return true;
  }

  /// Bytes kept between frames (the order and the face adjacency; sort keys and the exact order's
  /// state live only while sorting).
  std::size_t GetBytes() const
  {
    return sizeof(std::uint32_t) *
      (this->Order.capacity() + this->Copies.capacity() + this->Kept.capacity() + this->SetOf.capacity()) +
      sizeof(std::int32_t) * this->Adjacency.capacity() + sizeof(this->Boundary[0]) * this->Boundary.capacity() +
      this->Faces.GetBytes();
  }

private:
  void SortByCentroids(const TetrahedralMesh& mesh, const std::vector<std::uint32_t>& cells, const glm::dvec3& eye,
    const glm::dvec3& direction, bool parallel)
  {
    const std::size_t n = cells.size();
    std::vector<std::uint32_t> keys(n), scratchKeys, scratchOrder; // freed after the sort: memory per cell
    this->Order = cells;
    const glm::vec3 eyeF(eye), directionF(direction);
    vtkSMPTools::For(0, static_cast<vtkIdType>(n), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const glm::vec3 offset = mesh.Centroid(this->Order[i]) - eyeF;
        const float distance = parallel ? glm::dot(offset, directionF) : glm::dot(offset, offset);
        keys[i] = uv::OrderedKey(-distance); // farthest first
      }
    });
    auto parallelChunks = [](int count, const auto& function) {
      vtkSMPTools::For(0, count, 1, [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType chunk = begin; chunk < end; ++chunk)
          function(static_cast<int>(chunk));
      });
    };
    uv::RadixSortPairs(keys, this->Order, scratchKeys, scratchOrder, parallelChunks);
  }

  /// parallelFor(count, run(begin, end)) of the VTK-free order code, on vtkSMPTools.
  static void ParallelFor(std::size_t count, const std::function<void(std::size_t, std::size_t)>& run)
  {
    vtkSMPTools::For(0, static_cast<vtkIdType>(count), [&](vtkIdType begin, vtkIdType end) {
      run(static_cast<std::size_t>(begin), static_cast<std::size_t>(end));
    });
  }

  /// The back-to-front centroid order made exact across faces, and across gaps along `pixels`;
  /// `eye` is the direction towards the eye under parallel projection.
  void FollowFaces(const TetrahedralMesh& mesh, const glm::dvec3& eye, bool parallel, const uv::PixelGrid& pixels)
  {
    // Faces match by the input's point ids (a cell scalar gives each tetrahedron points of its own).
    const std::vector<std::uint32_t>& drawn = mesh.TetrahedronPoints;
    std::vector<std::uint32_t> corners;
    const bool ownPoints = !mesh.CornerPoints.empty();
    if (ownPoints)
    {
      corners.resize(drawn.size());
      for (std::size_t i = 0; i < drawn.size(); ++i)
        corners[i] = mesh.CornerPoints[drawn[i]];
    }
    const std::vector<std::uint32_t>& allIds = ownPoints ? corners : drawn;
    if (this->AdjacencyFor != mesh.TopologyVersion)
    {
      this->UpdateCopies(allIds);
      this->Adjacency = uv::MakeTetrahedronFaceAdjacency(this->Copies.empty() ? allIds : this->Compact(allIds), ParallelFor);
      this->AdjacencyFor = mesh.TopologyVersion;
    }
    if (!this->Copies.empty())
    {
      // Copies of a tetrahedron (a mesh appended to itself) share its faces, which then join none of
      // them: the faces of one tetrahedron of each set order the sets, each drawn next to its copies.
      const std::vector<std::uint32_t> ids = this->Compact(allIds);
      const auto position = [&](std::size_t u, int k) { return glm::dvec3(mesh.Corner(this->Kept[u], k)); };
      std::vector<std::uint32_t> sets = this->SetsInOrder();
      this->SortByFaces(mesh, ids, position, eye, parallel, pixels, sets);
      this->ExpandSets(sets);
      return;
    }
    const auto position = [&mesh](std::size_t t, int k) { return glm::dvec3(mesh.Corner(t, k)); };
    this->SortByFaces(mesh, allIds, position, eye, parallel, pixels, this->Order);
  }

  /// `order` (cells of `ids`) made exact across faces and gaps.
  template <typename Position>
  void SortByFaces(const TetrahedralMesh& mesh, const std::vector<std::uint32_t>& ids, const Position& position,
    const glm::dvec3& eye, bool parallel, const uv::PixelGrid& pixels, std::vector<std::uint32_t>& order)
  {
    this->UpdateBoundary(mesh, ids, position);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> gaps;
    if (!this->Boundary.empty() && pixels.Width > 0 && pixels.Height > 0)
      gaps = uv::GapConstraints(this->Boundary, position, pixels, ParallelFor);
    this->GapConstraints = gaps.size();
    this->Faces.Sort(order, ids, position, this->Adjacency, eye, parallel, ParallelFor, gaps);
    this->CyclesBroken = this->Faces.CyclesBroken;
  }

  /// Which tetrahedra repeat another's ids (Copies: per tetrahedron the first of its set; empty when
  /// none does), and the first of each set in order (Kept) with each tetrahedron's set (SetOf).
  void UpdateCopies(const std::vector<std::uint32_t>& ids)
  {
    this->Copies = uv::FirstCopies<4>(ids, [](auto begin, auto end, auto less) { vtkSMPTools::Sort(begin, end, less); });
    this->Kept.clear();
    this->SetOf.assign(this->Copies.size(), 0);
    for (std::size_t t = 0; t < this->Copies.size(); ++t)
    {
      if (this->Copies[t] == t)
        this->Kept.push_back(static_cast<std::uint32_t>(t));
      this->SetOf[t] = this->Copies[t] == t ? static_cast<std::uint32_t>(this->Kept.size() - 1) : this->SetOf[this->Copies[t]];
    }
  }

  /// The ids of the first tetrahedron of each set.
  std::vector<std::uint32_t> Compact(const std::vector<std::uint32_t>& ids) const
  {
    std::vector<std::uint32_t> compact(4 * this->Kept.size());
    for (std::size_t u = 0; u < this->Kept.size(); ++u)
      std::copy_n(ids.begin() + 4 * std::size_t(this->Kept[u]), 4, compact.begin() + 4 * u);
    return compact;
  }

  /// The sets of Order's tetrahedra, each once, where its first member stands in Order.
  std::vector<std::uint32_t> SetsInOrder() const
  {
    std::vector<std::uint32_t> sets;
    std::vector<unsigned char> seen(this->Kept.size(), 0);
    for (std::uint32_t t : this->Order)
      if (!seen[this->SetOf[t]])
      {
        seen[this->SetOf[t]] = 1;
        sets.push_back(this->SetOf[t]);
      }
    return sets;
  }

  /// Order again from the sorted sets: each set's members of Order together, where the set stands.
  void ExpandSets(const std::vector<std::uint32_t>& sets)
  {
    std::vector<std::uint32_t> start(this->Kept.size() + 1, 0), members(this->Order.size());
    for (std::uint32_t t : this->Order)
      ++start[this->SetOf[t] + 1];
    for (std::size_t u = 0; u < this->Kept.size(); ++u)
      start[u + 1] += start[u];
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::uint32_t t : this->Order)
      members[next[this->SetOf[t]]++] = t;
    this->Order.clear();
    for (std::uint32_t u : sets)
      this->Order.insert(this->Order.end(), members.begin() + start[u], members.begin() + start[u + 1]);
  }

  /// The boundary faces a pixel's ray can cross between two others (none on a convex mesh), once
  /// per mesh and positions.
  template <typename Position>
  void UpdateBoundary(const TetrahedralMesh& mesh, const std::vector<std::uint32_t>& ids, const Position& position)
  {
    const std::pair<std::uint64_t, std::uint64_t> versions(mesh.TopologyVersion, mesh.PositionsVersion);
    if (this->BoundaryFor == versions)
      return;
    this->Boundary.clear();
    if (!uv::BoundaryIsConvex(ids, position, this->Adjacency))
      this->Boundary = uv::FacesOffTheHull(uv::BoundaryFaces(this->Adjacency), position, ParallelFor);
    this->Boundary.shrink_to_fit();
    this->BoundaryFor = versions;
  }

  std::vector<std::int32_t> Adjacency; // of the first tetrahedron of each set when some repeat (Kept)
  std::uint64_t AdjacencyFor = 0; // the mesh's TopologyVersion
  std::vector<std::uint32_t> Copies, Kept, SetOf; // UpdateCopies (empty when no tetrahedron repeats)
  std::vector<std::pair<std::uint32_t, int>> Boundary; // boundary faces off a non-convex mesh's hull
  std::pair<std::uint64_t, std::uint64_t> BoundaryFor{ 0, 0 }; // TopologyVersion, PositionsVersion
  uv::PixelGrid Pixels;
  uv::FaceAdjacencyOrder Faces;
  glm::dvec3 Eye{ 0.0 }, Direction{ 0.0 };
  bool Parallel = false, Valid = false, FrontToBack = false, Exact = false;
  std::uint64_t PositionsFor = 0; // the mesh's PositionsVersion sorted for
};

} // namespace vtkuv

#endif
