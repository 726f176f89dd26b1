#include "vtkUnstructuredVolumeReferenceRenderer.h"
#include "vtkUnstructuredVolumeCompatibility.h"

#include "uvChebyshevSeries.h"
#include "uvCurvedCell.h"
#include "uvIsosurfaceList.h"
#include "uvLinearCellSplit.h"
#include "uvOpticalModel.h"
#include "uvRayCellGeometry.h"
#include "uvScalarNormalisation.h"
#include "uvLatticeBasis.h"
#include "vtkuvMeshIntegrity.h"
#include "vtkuvRenderedScalar.h"
#include "vtkuvNormalisedTransferFunction.h"

#include "vtkCamera.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkGenericCell.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkHexahedraToTetrahedra.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkLagrangeHexahedron.h"
#include "vtkLagrangeTetra.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPNGWriter.h"
#include "vtkCellData.h"
#include "vtkPointData.h"
#include "vtkBezierWedge.h"
#include "vtkBiQuadraticQuadraticHexahedron.h"
#include "vtkBiQuadraticQuadraticWedge.h"
#include "vtkQuadraticHexahedron.h"
#include "vtkQuadraticLinearWedge.h"
#include "vtkQuadraticPyramid.h"
#include "vtkQuadraticTetra.h"
#include "vtkQuadraticWedge.h"
#include "vtkSmartPointer.h"
#include "vtkTriQuadraticHexahedron.h"
#include "vtkTriQuadraticPyramid.h"
#include "vtkUnstructuredGrid.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

vtkStandardNewMacro(vtkUnstructuredVolumeReferenceRenderer);
vtkCxxSetObjectMacro(vtkUnstructuredVolumeReferenceRenderer, VolumeProperty, vtkVolumeProperty);
vtkCxxSetObjectMacro(vtkUnstructuredVolumeReferenceRenderer, Camera, vtkCamera);

namespace
{
struct Cell
{
  const uv::IsoparametricShape* Shape; // null for a tetrahedron (linear, clipped by planes)
  std::int64_t Ids[8];
  std::int32_t Curved = -1; // a higher-order cell: its index in Mesh::Curved (Shape and Ids unused)
  int Corners() const { return this->Shape ? this->Shape->Corners : 4; }
};

void SetOrderFromPoints(vtkHigherOrderTetra*, int) {} // a tetrahedron's order follows its points
void SetOrderFromPoints(vtkHigherOrderWedge* wedge, int nodes)
{
  wedge->SetUniformOrderFromNumPoints(nodes);
}
void SetOrderFromPoints(vtkHigherOrderHexahedron* hexahedron, int nodes)
{
  hexahedron->SetUniformOrderFromNumPoints(nodes);
}

/// Per order 1 to 3, the lattice indices of the nodes of a `Cell` in VTK's node order: the
/// parametric coordinates VTK gives each node through `indexAt`. Made from a cell object once per
/// cell kind, before any thread reads them.
template <typename Cell>
std::array<std::vector<uv::SimplexIndex>, 4> MakeNodeLattices(
  int (*nodeCount)(int), uv::SimplexIndex (*indexAt)(int, const glm::dvec3&))
{
  std::array<std::vector<uv::SimplexIndex>, 4> made;
  for (int n = 1; n <= 3; ++n)
  {
    const int nodes = nodeCount(n);
    vtkNew<Cell> cell;
    cell->GetPointIds()->SetNumberOfIds(nodes);
    cell->GetPoints()->SetNumberOfPoints(nodes);
    SetOrderFromPoints(cell, nodes);
    cell->Initialize();
    const double* pcoords = cell->GetParametricCoords();
    for (int k = 0; k < nodes; ++k)
      made[n].push_back(indexAt(n, glm::dvec3(pcoords[3 * k], pcoords[3 * k + 1], pcoords[3 * k + 2])));
  }
  return made;
}

/// A Lagrange or Bezier tetrahedron's nodes (the two share VTK's node order) by lattice index.
const std::vector<uv::SimplexIndex>& TetrahedronLattice(int order)
{
  static const auto lattices = MakeNodeLattices<vtkLagrangeTetra>(
    [](int n) { return (n + 1) * (n + 2) * (n + 3) / 6; }, uv::SimplexIndexAt);
  return lattices[order];
}

/// A Lagrange or Bezier wedge's nodes (the two share VTK's node order) by (triangle index, layer).
const std::vector<uv::SimplexIndex>& WedgeLattice(int order)
{
  static const auto lattices =
    MakeNodeLattices<vtkBezierWedge>([](int n) { return (n + 1) * (n + 2) / 2 * (n + 1); }, uv::WedgeIndexAt);
  return lattices[order];
}

/// A Lagrange or Bezier hexahedron's nodes (the two share VTK's node order) by (i, j, k).
const std::vector<uv::SimplexIndex>& HexahedronLattice(int order)
{
  static const auto lattices = MakeNodeLattices<vtkLagrangeHexahedron>(
    [](int n) { return (n + 1) * (n + 1) * (n + 1); }, uv::HexahedronIndexAt);
  return lattices[order];
}

uv::SimplexBasisKind BasisKind(int type)
{
  const bool lagrange =
    type == VTK_LAGRANGE_HEXAHEDRON || type == VTK_LAGRANGE_WEDGE || type == VTK_LAGRANGE_TETRAHEDRON;
  return lagrange ? uv::SimplexBasisKind::Lagrange : uv::SimplexBasisKind::Bernstein;
}

/// The shape functions of VTK's higher-order 3D cells: VTK's own static functions for its quadratic
/// cells; for Lagrange and Bezier cells uvLatticeBasis.h (VTK 9.1's derivatives of those are
/// interleaved or wrong, and its static wedge and hexahedron functions slow). No cell object, as the
/// reference calls them from every thread at once.
struct CurvedShapeFunctions
{
  int Type = VTK_EMPTY_CELL;
  int Nodes = 0;
  int Order = 0; // Lagrange and Bezier cells (uniform in every direction)

  explicit operator bool() const { return this->Type != VTK_EMPTY_CELL; }

  void operator()(const glm::dvec3& xi, double* weights, double* derivatives) const
  {
    const double p[3] = { xi.x, xi.y, xi.z };
    switch (this->Type)
    {
#define UV_STATIC_SHAPE(TYPE, CLASS)                                                                               \
  case TYPE:                                                                                                       \
    CLASS::InterpolationFunctions(p, weights);                                                                     \
    if (derivatives)                                                                                               \
      CLASS::InterpolationDerivs(p, derivatives);                                                                  \
    return;
      UV_STATIC_SHAPE(VTK_QUADRATIC_TETRA, vtkQuadraticTetra)
      UV_STATIC_SHAPE(VTK_QUADRATIC_HEXAHEDRON, vtkQuadraticHexahedron)
      UV_STATIC_SHAPE(VTK_TRIQUADRATIC_HEXAHEDRON, vtkTriQuadraticHexahedron)
      UV_STATIC_SHAPE(VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON, vtkBiQuadraticQuadraticHexahedron)
      UV_STATIC_SHAPE(VTK_QUADRATIC_WEDGE, vtkQuadraticWedge)
      UV_STATIC_SHAPE(VTK_QUADRATIC_LINEAR_WEDGE, vtkQuadraticLinearWedge)
      UV_STATIC_SHAPE(VTK_BIQUADRATIC_QUADRATIC_WEDGE, vtkBiQuadraticQuadraticWedge)
      UV_STATIC_SHAPE(VTK_QUADRATIC_PYRAMID, vtkQuadraticPyramid)
      UV_STATIC_SHAPE(VTK_TRIQUADRATIC_PYRAMID, vtkTriQuadraticPyramid)
#undef UV_STATIC_SHAPE
      case VTK_LAGRANGE_HEXAHEDRON:
      case VTK_BEZIER_HEXAHEDRON:
        uv::EvaluateHexahedronBasis(BasisKind(this->Type), this->Order, HexahedronLattice(this->Order), xi,
          weights, derivatives);
        return;
      case VTK_LAGRANGE_WEDGE:
      case VTK_BEZIER_WEDGE:
        uv::EvaluateWedgeBasis(BasisKind(this->Type), this->Order, WedgeLattice(this->Order), xi, weights,
          derivatives);
        return;
      case VTK_LAGRANGE_TETRAHEDRON:
      case VTK_BEZIER_TETRAHEDRON:
        uv::EvaluateSimplexBasis(BasisKind(this->Type), this->Order, TetrahedronLattice(this->Order), xi,
          weights, derivatives);
        return;
      default:
        return;
    }
  }
};

struct CurvedType
{
  int Type, Nodes;
  uv::CellFamily Family;
};
constexpr CurvedType CurvedTypes[] = { { VTK_QUADRATIC_TETRA, 10, uv::CellFamily::Tetrahedron },
  { VTK_QUADRATIC_HEXAHEDRON, 20, uv::CellFamily::Hexahedron },
  { VTK_TRIQUADRATIC_HEXAHEDRON, 27, uv::CellFamily::Hexahedron },
  { VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON, 24, uv::CellFamily::Hexahedron },
  { VTK_QUADRATIC_WEDGE, 15, uv::CellFamily::Wedge }, { VTK_QUADRATIC_LINEAR_WEDGE, 12, uv::CellFamily::Wedge },
  { VTK_BIQUADRATIC_QUADRATIC_WEDGE, 18, uv::CellFamily::Wedge },
  { VTK_QUADRATIC_PYRAMID, 13, uv::CellFamily::Pyramid }, { VTK_TRIQUADRATIC_PYRAMID, 19, uv::CellFamily::Pyramid } };

/// The shape functions of a higher-order cell of `type` with `nodes` points (a Lagrange cell's
/// order follows from its point count), or an empty one for any other cell.
CurvedShapeFunctions CurvedShapeFunctionsOf(int type, vtkIdType nodes, uv::CellFamily& family)
{
  CurvedShapeFunctions shape;
  for (const CurvedType& curved : CurvedTypes)
  {
    if (curved.Type == type && curved.Nodes == nodes)
    {
      shape.Type = type;
      shape.Nodes = curved.Nodes;
      family = curved.Family;
    }
  }
  for (int order = 1; order <= 3 && !shape; ++order)
  {
    const vtkIdType hexahedronNodes = (order + 1) * (order + 1) * (order + 1);
    const vtkIdType wedgeNodes = (order + 1) * (order + 2) / 2 * (order + 1);
    const vtkIdType tetrahedronNodes = (order + 1) * (order + 2) * (order + 3) / 6;
    const bool hexahedron = (type == VTK_LAGRANGE_HEXAHEDRON || type == VTK_BEZIER_HEXAHEDRON) && nodes == hexahedronNodes;
    const bool wedge = (type == VTK_LAGRANGE_WEDGE || type == VTK_BEZIER_WEDGE) && nodes == wedgeNodes;
    const bool tetrahedron =
      (type == VTK_LAGRANGE_TETRAHEDRON || type == VTK_BEZIER_TETRAHEDRON) && nodes == tetrahedronNodes;
    if (hexahedron || wedge || tetrahedron)
    {
      shape.Type = type;
      shape.Nodes = static_cast<int>(nodes);
      shape.Order = order;
      family = hexahedron ? uv::CellFamily::Hexahedron : wedge ? uv::CellFamily::Wedge : uv::CellFamily::Tetrahedron;
    }
  }
  return shape;
}

using CurvedCell = uv::CurvedCell<CurvedShapeFunctions>;

struct CurvedCellNodes
{
  uv::CellFamily Family;
  CurvedShapeFunctions Shape;
  std::size_t First; // in Mesh::CurvedIds
};

const uv::IsoparametricShape* ShapeOf(int type)
{
  switch (type)
  {
    case VTK_HEXAHEDRON:
    case VTK_VOXEL:
      return &uv::HexahedronShape();
    case VTK_WEDGE:
      return &uv::WedgeShape();
    case VTK_PYRAMID:
      return &uv::PyramidShape();
    default:
      return nullptr;
  }
}

bool IsUninterpolable3D(int type)
{
  return type == VTK_LAGRANGE_PYRAMID || type == VTK_BEZIER_PYRAMID || type == VTK_HIGHER_ORDER_TETRAHEDRON ||
    type == VTK_HIGHER_ORDER_WEDGE || type == VTK_HIGHER_ORDER_PYRAMID || type == VTK_HIGHER_ORDER_HEXAHEDRON;
}

bool HasRationalBezierCells(vtkDataSet* input)
{
  if (!input->GetPointData()->GetRationalWeights())
    return false;
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
  {
    const int type = input->GetCellType(c);
    if (type == VTK_BEZIER_TETRAHEDRON || type == VTK_BEZIER_HEXAHEDRON || type == VTK_BEZIER_WEDGE)
      return true;
  }
  return false;
}

bool IsPolygonalCell(int type)
{
  return type == VTK_PENTAGONAL_PRISM || type == VTK_HEXAGONAL_PRISM || type == VTK_POLYHEDRON;
}

/// `input` with its prisms and polyhedra replaced by vtkHexahedraToTetrahedra's tetrahedra (the
/// other cells unchanged, the data passed, polyhedra's centre points appended after the input's
/// points); `input` itself when it has none.
vtkSmartPointer<vtkDataSet> PolygonalCellsAsTetrahedra(vtkDataSet* input)
{
  auto* grid = vtkUnstructuredGrid::SafeDownCast(input); // the only type that holds such cells
  bool any = false;
  for (vtkIdType c = 0; grid && c < grid->GetNumberOfCells() && !any; ++c)
    any = IsPolygonalCell(grid->GetCellType(c));
  if (!any)
    return input; // the common case: nothing copied
  std::vector<vtkIdType> others;
  vtkNew<vtkUnstructuredGrid> polygonal; // those cells over all the input's points
  polygonal->SetPoints(grid->GetPoints());
  polygonal->GetPointData()->ShallowCopy(input->GetPointData());
  polygonal->GetCellData()->CopyAllocate(input->GetCellData());
  vtkNew<vtkIdList> ids; // a cell's points, or a polyhedron's face stream
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    if (!IsPolygonalCell(grid->GetCellType(c)))
    {
      others.push_back(c);
      continue;
    }
    if (grid->GetCellType(c) == VTK_POLYHEDRON)
      uvcompat::GetPolyhedronFaceStream(grid, c, ids);
    else
      grid->GetCellPoints(c, ids);
    polygonal->GetCellData()->CopyData(
      input->GetCellData(), c, polygonal->InsertNextCell(grid->GetCellType(c), ids));
  }
  vtkNew<vtkHexahedraToTetrahedra> split;
  split->SetInputData(polygonal);
  split->Update();
  vtkUnstructuredGrid* tets = split->GetOutput();
  auto result = vtkSmartPointer<vtkUnstructuredGrid>::New();
  result->SetPoints(tets->GetPoints());
  result->GetPointData()->ShallowCopy(tets->GetPointData());
  result->Allocate(static_cast<vtkIdType>(others.size()) + tets->GetNumberOfCells());
  result->GetCellData()->CopyAllocate(input->GetCellData());
  for (vtkIdType c : others)
  {
    grid->GetCellPoints(c, ids);
    result->GetCellData()->CopyData(input->GetCellData(), c, result->InsertNextCell(grid->GetCellType(c), ids));
  }
  for (vtkIdType t = 0; t < tets->GetNumberOfCells(); ++t)
  {
    tets->GetCellPoints(t, ids);
    result->GetCellData()->CopyData(tets->GetCellData(), t, result->InsertNextCell(VTK_TETRA, ids));
  }
  return result;
}

/// The input in double precision, recentred on its bounds' centre: every intersection and inverse
/// map then works with coordinates the size of the mesh, wherever the mesh lies.
struct Mesh
{
  glm::dvec3 Centre{ 0.0 };
  std::vector<glm::dvec3> Points;
  std::vector<double> Values;     // per point (point scalar)
  std::vector<double> CellValues; // per input cell (cell scalar), else empty
  std::vector<Cell> Cells;
  std::vector<double> CellScalar; // per entry of Cells, for a cell scalar
  std::vector<CurvedCellNodes> Curved;
  std::vector<std::int64_t> CurvedIds;
  std::vector<uv::BoundingVolumeHierarchy::Box> Boxes;
  vtkIdType NotThreeDimensional = 0;
  vtkIdType NonFinite = 0;
  vtkIdType Unsupported = -1; // the first cell of a type the reference does not take

  bool OnCells() const { return !this->CellValues.empty(); }

  /// Points relative to the bounds' centre, scalars relative to `offset`.
  void LoadPoints(vtkDataSet* input, const vtkuv::RenderedScalar& scalar, double offset)
  {
    double bounds[6];
    input->GetBounds(bounds);
    this->Centre = 0.5 * glm::dvec3(bounds[0] + bounds[1], bounds[2] + bounds[3], bounds[4] + bounds[5]);
    const vtkIdType count = input->GetNumberOfPoints();
    this->Points.resize(count);
    this->Values.assign(scalar.OnCells ? 0 : count, 0.0);
    for (vtkIdType i = 0; i < count; ++i)
    {
      input->GetPoint(i, &this->Points[i].x);
      this->Points[i] -= this->Centre;
      if (!scalar.OnCells)
        this->Values[i] = scalar(i) - offset;
    }
    this->CellValues.resize(scalar.OnCells ? input->GetNumberOfCells() : 0);
    for (std::size_t c = 0; c < this->CellValues.size(); ++c)
      this->CellValues[c] = scalar(static_cast<vtkIdType>(c)) - offset;
  }

  /// A higher-order cell's nodes, values (of a point scalar) and shape functions.
  CurvedCell MakeCurved(const Cell& cell) const
  {
    const CurvedCellNodes& curved = this->Curved[cell.Curved];
    glm::dvec3 positions[CurvedCell::MaximumNodes];
    double values[CurvedCell::MaximumNodes];
    for (int k = 0; k < curved.Shape.Nodes; ++k)
    {
      const std::int64_t id = this->CurvedIds[curved.First + k];
      positions[k] = this->Points[id];
      values[k] = this->OnCells() ? 0.0 : this->Values[id];
    }
    return CurvedCell(curved.Family, curved.Shape, curved.Shape.Nodes, positions, values);
  }

  /// Collects the 3D cells; false at the first cell type it cannot take (Unsupported says which).
  bool LoadCells(vtkDataSet* input)
  {
    vtkNew<vtkIdList> ids;
    vtkNew<vtkGenericCell> probe;
    for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
    {
      const int type = input->GetCellType(c);
      input->GetCellPoints(c, ids);
      uv::CellFamily family;
      const CurvedShapeFunctions curved = CurvedShapeFunctionsOf(type, ids->GetNumberOfIds(), family);
      if (curved)
      {
        this->AddCurved(c, family, curved, ids);
        continue;
      }
      if (type != VTK_TETRA && !ShapeOf(type))
      {
        if (!IsUninterpolable3D(type)) // no VTK 9.1 class for these: the probe would complain
          probe->SetCellType(type);
        if (!IsUninterpolable3D(type) && (type == VTK_EMPTY_CELL || probe->GetCellDimension() < 3))
        {
          ++this->NotThreeDimensional;
          continue;
        }
        this->Unsupported = c;
        return false;
      }
      Cell cell{ ShapeOf(type), {} };
      uv::BoundingVolumeHierarchy::Box box;
      bool finite = !this->OnCells() || std::isfinite(this->CellValues[c]);
      for (int k = 0; k < cell.Corners(); ++k)
      {
        const vtkIdType id = ids->GetId(type == VTK_VOXEL ? uv::VoxelToHexahedronOrder[k] : k);
        cell.Ids[k] = id;
        box.Add({ this->Points[id], this->Points[id] });
        finite = finite && (this->OnCells() || std::isfinite(this->Values[id]));
      }
      if (!finite)
      {
        ++this->NonFinite;
        continue;
      }
      this->Cells.push_back(cell);
      this->Boxes.push_back(uv::BoundingVolumeHierarchy::PaddedForRounding(box));
      if (this->OnCells())
        this->CellScalar.push_back(this->CellValues[c]);
    }
    return true;
  }

private:
  void AddCurved(vtkIdType c, uv::CellFamily family, const CurvedShapeFunctions& shape, vtkIdList* ids)
  {
    bool finite = !this->OnCells() || std::isfinite(this->CellValues[c]);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      finite = finite && (this->OnCells() || std::isfinite(this->Values[ids->GetId(k)]));
    if (!finite)
    {
      ++this->NonFinite;
      return;
    }
    Cell cell{ nullptr, {}, static_cast<std::int32_t>(this->Curved.size()) };
    this->Curved.push_back({ family, shape, this->CurvedIds.size() });
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      this->CurvedIds.push_back(ids->GetId(k));
    this->Cells.push_back(cell);
    this->Boxes.push_back(CurvedBox(this->MakeCurved(cell), family));
    if (this->OnCells())
      this->CellScalar.push_back(this->CellValues[c]);
  }

  /// A box holding the curved cell: its map sampled densely over the parametric domain, padded
  /// (the map may bulge past its nodes, and between the samples).
  static uv::BoundingVolumeHierarchy::Box CurvedBox(const CurvedCell& cell, uv::CellFamily family)
  {
    constexpr int N = 8;
    uv::BoundingVolumeHierarchy::Box box;
    for (int i = 0; i <= N; ++i)
      for (int j = 0; j <= N; ++j)
        for (int k = 0; k <= N; ++k)
        {
          const glm::dvec3 xi(double(i) / N, double(j) / N, double(k) / N);
          if (uv::InFamilyDomain(family, xi, 0.0))
          {
            const glm::dvec3 x = cell.Point(xi);
            box.Add({ x, x });
          }
        }
    const glm::dvec3 pad(0.02 * cell.Diameter());
    box.Add({ box.Low - pad, box.High + pad });
    return box;
  }
};

struct Segment
{
  uv::Interval Span;
  std::int64_t Cell;
  glm::dvec3 Xi[2]; // a higher-order cell's parametric coordinates at the ends: Newton's start
};

/// The scalar along one segment of a ray: the cell's value for a cell scalar; linear in a
/// tetrahedron; in an isoparametric cell a certified Chebyshev fit (17 inverse solves stand in for
/// the hundreds the quadrature makes), or the inverse map itself where the fit is not resolved.
class SegmentScalar
{
public:
  SegmentScalar(const Mesh& mesh, const Segment& segment, const uv::Ray& ray)
    : Ray(ray)
    , T0(segment.Span.Enter)
    , T1(segment.Span.Exit)
  {
    if (mesh.OnCells())
    {
      this->S0 = this->S1 = mesh.CellScalar[segment.Cell]; // constant: no shape needed
      return;
    }
    const Cell& cell = mesh.Cells[segment.Cell];
    if (cell.Curved >= 0)
    {
      this->FitCurved(mesh.MakeCurved(cell), segment);
      return;
    }
    for (int k = 0; k < cell.Corners(); ++k)
    {
      this->P[k] = mesh.Points[cell.Ids[k]];
      this->F[k] = mesh.Values[cell.Ids[k]];
    }
    if (!cell.Shape)
    {
      this->S0 = uv::TetrahedronScalar(this->P, this->F, this->At(this->T0));
      this->S1 = uv::TetrahedronScalar(this->P, this->F, this->At(this->T1));
      return;
    }
    this->Shape = cell.Shape;
    this->Xi0 = this->Xi1 = cell.Shape->Centre;
    uv::InverseIsoparametric(*this->Shape, this->P, this->At(this->T0), this->Xi0);
    uv::InverseIsoparametric(*this->Shape, this->P, this->At(this->T1), this->Xi1);
    double magnitude = 1.0;
    for (int k = 0; k < cell.Corners(); ++k)
    {
      magnitude = std::max(magnitude, 1.0 + std::abs(this->F[k]));
    }
    this->Fitted = this->Series.Fit([this](double t) { return this->Exact(t); }, this->T0, this->T1, 1e-12 * magnitude);
  }

  double operator()(double t) const
  {
    if (!this->Shape && !this->Curved)
    {
      return this->S0 + (this->S1 - this->S0) * (t - this->T0) / (this->T1 - this->T0);
    }
    return this->Fitted ? this->Series(t) : this->Exact(t);
  }

private:
  glm::dvec3 At(double t) const { return this->Ray.Origin + t * this->Ray.Direction; }

  double Exact(double t) const
  {
    glm::dvec3 xi = this->Xi0 + (this->Xi1 - this->Xi0) * ((t - this->T0) / (this->T1 - this->T0));
    if (this->Curved)
    {
      this->Curved->Inverse(this->At(t), xi);
      return this->Curved->Scalar(xi);
    }
    uv::InverseIsoparametric(*this->Shape, this->P, this->At(t), xi);
    return uv::IsoparametricScalar(*this->Shape, this->F, xi);
  }

  /// A higher-order cell's field along the segment, fitted as for the linear isoparametric cells.
  void FitCurved(const CurvedCell& cell, const Segment& segment)
  {
    this->Curved.emplace(cell);
    this->Xi0 = segment.Xi[0];
    this->Xi1 = segment.Xi[1];
    this->Curved->Inverse(this->At(this->T0), this->Xi0);
    this->Curved->Inverse(this->At(this->T1), this->Xi1);
    double magnitude = 1.0;
    for (int k = 0; k < 2; ++k)
      magnitude = std::max(magnitude, 1.0 + std::abs(this->Curved->Scalar(k ? this->Xi1 : this->Xi0)));
    this->Fitted = this->Series.Fit([this](double t) { return this->Exact(t); }, this->T0, this->T1, 1e-12 * magnitude);
  }

  uv::Ray Ray;
  double T0, T1, S0 = 0.0, S1 = 0.0;
  const uv::IsoparametricShape* Shape = nullptr;
  std::optional<CurvedCell> Curved;
  glm::dvec3 P[8];
  double F[8] = {};
  glm::dvec3 Xi0{ 0.0 }, Xi1{ 0.0 };
  uv::ChebyshevSeries Series;
  bool Fitted = false;
};

/// Per-thread scratch of one ray.
struct RayScratch
{
  std::vector<Segment> Segments;
  std::vector<uv::Interval> Parts;
  std::vector<std::array<glm::dvec3, 2>> PartsXi; // of a higher-order cell's parts
  std::vector<CurvedCell::Hit> CurvedHits;
  std::vector<double> Hits;
  std::vector<double> Events;
  std::vector<SegmentScalar> Scalars;                              // of a run of overlapping segments
  std::vector<std::reference_wrapper<const SegmentScalar>> Active; // those present on one stretch
};

/// The isosurfaces of a cell scalar as the reference draws them: on the faces between cells
/// (uv::ForEachSurfaceBetweenCells), unlit.
struct CellFaceSurfaces
{
  std::vector<uv::Isosurface> Drawn; // ascending, in the scalar's own values
  double Shading = 1.0;              // the property's ambient + diffuse
  double Touching = 0.0;             // how near a segment's start to the last one's end is a face
                                     // (and how much overlap is rounding)

  /// Composites the surfaces on the face where a ray leaves a cell of value `from` at `exit` and
  /// enters one of value `to` at `entry`.
  void Cross(double exit, double from, double entry, double to, uv::RayAccumulator& accumulator) const
  {
    if (std::abs(entry - exit) > this->Touching)
      return; // a gap: the ray left the mesh between them
    uv::ForEachSurfaceBetweenCells(this->Drawn, from, to, [&](const uv::Isosurface& surface) {
      const glm::dvec3 colour(surface.Color[0], surface.Color[1], surface.Color[2]);
      const double depth = surface.Opacity < 1.0 ? -std::log1p(-surface.Opacity) : HUGE_VAL;
      accumulator.Composite(surface.Opacity * this->Shading * colour, depth);
    });
  }
};

/// Every ray's segments, in order, integrated exactly.
class RayIntegrator
{
public:
  RayIntegrator(const Mesh& mesh, const uv::BoundingVolumeHierarchy& hierarchy,
    const uv::TransferFunction& transfer, double tolerance, const CellFaceSurfaces& surfaces)
    : TheMesh(mesh)
    , Hierarchy(hierarchy)
    , Transfer(transfer)
    , Tolerance(tolerance)
    , Surfaces(surfaces)
  {
  }

  uv::RayAccumulator Integrate(const uv::Ray& ray, RayScratch& scratch) const
  {
    this->Gather(ray, scratch);
    std::vector<Segment>& segments = scratch.Segments;
    std::sort(segments.begin(), segments.end(),
      [](const Segment& a, const Segment& b) { return a.Span.Enter < b.Span.Enter; });
    uv::RayAccumulator accumulator;
    const bool surfaces = this->TheMesh.OnCells() && !this->Surfaces.Drawn.empty();
    std::optional<std::size_t> previous; // the last segment integrated alone, for the faces between cells
    for (std::size_t first = 0; first < segments.size();)
    {
      if (accumulator.Transmittance < 1e-12)
      {
        break; // what lies behind cannot change any channel by more than 1e-12
      }
      // A run of segments that overlap one another (tangled or overlapping cells). Neighbours whose
      // shared face two different intersections put within rounding of each other (a pyramid's
      // triangle and a tetrahedron's plane) only touch.
      std::size_t last = first + 1;
      double end = segments[first].Span.Exit;
      for (; last < segments.size() && segments[last].Span.Enter < end - this->Surfaces.Touching; ++last)
      {
        end = std::max(end, segments[last].Span.Exit);
      }
      if (last == first + 1)
      {
        const Segment& segment = segments[first];
        if (surfaces && previous)
        {
          const Segment& before = segments[*previous];
          this->Surfaces.Cross(before.Span.Exit, this->TheMesh.CellScalar[before.Cell], segment.Span.Enter,
            this->TheMesh.CellScalar[segment.Cell], accumulator);
        }
        previous = first;
        uv::IntegrateSegment(this->Transfer, SegmentScalar(this->TheMesh, segment, ray), segment.Span.Enter,
          segment.Span.Exit, this->Tolerance, accumulator);
      }
      else
      {
        this->IntegrateOverlapping(ray, first, last, scratch, accumulator);
        previous.reset(); // overlapping cells: no face between two of them
      }
      first = last;
    }
    return accumulator;
  }

private:
  /// The parts of the ray inside each cell whose box it crosses, at t >= 0.
  void Gather(const uv::Ray& ray, RayScratch& scratch) const
  {
    scratch.Segments.clear();
    this->Hierarchy.Traverse(ray, [&](std::int64_t index) {
      const Cell& cell = this->TheMesh.Cells[index];
      scratch.Parts.clear();
      scratch.PartsXi.clear();
      if (cell.Curved >= 0)
      {
        this->TheMesh.MakeCurved(cell).Intersect(ray, scratch.Parts, scratch.PartsXi, scratch.CurvedHits);
        this->KeepParts(index, scratch);
        return;
      }
      glm::dvec3 p[8];
      for (int k = 0; k < cell.Corners(); ++k)
      {
        p[k] = this->TheMesh.Points[cell.Ids[k]];
      }
      if (cell.Shape)
      {
        uv::IntersectIsoparametric(*cell.Shape, ray, p, cell.Ids, scratch.Parts, scratch.Hits);
      }
      else
      {
        uv::Interval span;
        if (uv::IntersectTetrahedron(ray, p, cell.Ids, span))
        {
          scratch.Parts.push_back(span);
        }
      }
      this->KeepParts(index, scratch);
    });
  }

  /// The cell's parts at t >= 0 become segments.
  static void KeepParts(std::int64_t index, RayScratch& scratch)
  {
    for (std::size_t i = 0; i < scratch.Parts.size(); ++i)
    {
      uv::Interval part = scratch.Parts[i];
      part.Enter = std::max(part.Enter, 0.0);
      if (part.Exit > part.Enter)
      {
        const bool curved = i < scratch.PartsXi.size();
        scratch.Segments.push_back({ part, index,
          { curved ? scratch.PartsXi[i][0] : glm::dvec3(0.0), curved ? scratch.PartsXi[i][1] : glm::dvec3(0.0) } });
      }
    }
  }

  /// Segments [first, last) overlap: between consecutive end points the cells present superpose.
  void IntegrateOverlapping(const uv::Ray& ray, std::size_t first, std::size_t last, RayScratch& scratch,
    uv::RayAccumulator& accumulator) const
  {
    std::vector<double>& events = scratch.Events;
    events.clear();
    for (std::size_t i = first; i < last; ++i)
    {
      events.push_back(scratch.Segments[i].Span.Enter);
      events.push_back(scratch.Segments[i].Span.Exit);
    }
    std::sort(events.begin(), events.end());
    events.erase(std::unique(events.begin(), events.end()), events.end());
    // Each segment's scalar once, over its whole span (the fit holds on every stretch of it).
    scratch.Scalars.clear();
    for (std::size_t i = first; i < last; ++i)
    {
      scratch.Scalars.emplace_back(this->TheMesh, scratch.Segments[i], ray);
    }
    for (std::size_t e = 0; e + 1 < events.size(); ++e)
    {
      const double a = events[e], b = events[e + 1];
      scratch.Active.clear();
      for (std::size_t i = first; i < last; ++i)
      {
        const Segment& segment = scratch.Segments[i];
        if (segment.Span.Enter <= a && segment.Span.Exit >= b)
        {
          scratch.Active.push_back(std::cref(scratch.Scalars[i - first]));
        }
      }
      if (scratch.Active.size() == 1)
      {
        uv::IntegrateSegment(this->Transfer, scratch.Active.front(), a, b, this->Tolerance, accumulator);
      }
      else if (!scratch.Active.empty())
      {
        uv::IntegrateOverlap(this->Transfer, scratch.Active, a, b, this->Tolerance, accumulator);
      }
    }
  }

  const Mesh& TheMesh;
  const uv::BoundingVolumeHierarchy& Hierarchy;
  const uv::TransferFunction& Transfer;
  double Tolerance;
  const CellFaceSurfaces& Surfaces;
};

/// Pixel rays of a camera, in the mesh's recentred frame: the camera is moved by the same offset
/// before its matrices are taken, so no large coordinate enters the unprojection.
class PixelRays
{
public:
  PixelRays(vtkCamera* camera, const glm::dvec3& centre, int width, int height)
    : Width(width)
    , Height(height)
  {
    vtkNew<vtkCamera> local;
    local->DeepCopy(camera);
    double position[3], focal[3];
    camera->GetPosition(position);
    camera->GetFocalPoint(focal);
    local->SetPosition(position[0] - centre.x, position[1] - centre.y, position[2] - centre.z);
    local->SetFocalPoint(focal[0] - centre.x, focal[1] - centre.y, focal[2] - centre.z);
    local->SetViewUp(camera->GetViewUp());
    this->Unproject->DeepCopy(
      local->GetCompositeProjectionTransformMatrix(static_cast<double>(width) / height, -1, 1));
    this->Unproject->Invert();
  }

  /// The ray through a pixel's centre, from the near plane.
  uv::Ray operator()(vtkIdType pixel) const
  {
    const double x = 2.0 * ((pixel % this->Width) + 0.5) / this->Width - 1.0;
    const double y = 2.0 * ((pixel / this->Width) + 0.5) / this->Height - 1.0;
    const glm::dvec3 nearPoint = this->Point(x, y, -1.0);
    return uv::Ray{ nearPoint, glm::normalize(this->Point(x, y, 1.0) - nearPoint) };
  }

private:
  glm::dvec3 Point(double x, double y, double z) const
  {
    double in[4] = { x, y, z, 1.0 }, out[4];
    this->Unproject->MultiplyPoint(in, out);
    return glm::dvec3(out[0], out[1], out[2]) / out[3];
  }

  int Width, Height;
  vtkNew<vtkMatrix4x4> Unproject;
};
} // namespace

void vtkUnstructuredVolumeReferenceRenderer::AddIsosurface(
  double value, double red, double green, double blue, double opacity)
{
  this->Isosurfaces->Add(value, red, green, blue, opacity);
  this->Modified();
}

void vtkUnstructuredVolumeReferenceRenderer::RemoveAllIsosurfaces()
{
  if (this->Isosurfaces->Clear())
    this->Modified();
}

int vtkUnstructuredVolumeReferenceRenderer::GetNumberOfIsosurfaces()
{
  return this->Isosurfaces->Size();
}

vtkUnstructuredVolumeReferenceRenderer::vtkUnstructuredVolumeReferenceRenderer()
  : Isosurfaces(new uv::IsosurfaceList)
{
  this->Output = vtkImageData::New();
}

vtkUnstructuredVolumeReferenceRenderer::~vtkUnstructuredVolumeReferenceRenderer()
{
  this->SetInputData(nullptr);
  this->SetVolumeProperty(nullptr);
  this->SetCamera(nullptr);
  this->SetScalarArrayName(nullptr);
  this->Output->Delete();
  delete this->Isosurfaces;
}

void vtkUnstructuredVolumeReferenceRenderer::SetInputData(vtkDataSet* input)
{
  vtkSetObjectBodyMacro(Input, vtkDataSet, input);
}

vtkuv::RenderedScalar vtkUnstructuredVolumeReferenceRenderer::FindScalar(vtkDataSet* input)
{
  const char* name = this->ScalarArrayName;
  int mode = this->ScalarMode;
  if (mode == VTK_SCALAR_MODE_DEFAULT && name)
  {
    // A name alone: the point array of that name, else the cell array.
    mode = input->GetPointData()->GetArray(name) ? VTK_SCALAR_MODE_USE_POINT_FIELD_DATA
                                                       : VTK_SCALAR_MODE_USE_CELL_FIELD_DATA;
  }
  if (!name && mode == VTK_SCALAR_MODE_USE_POINT_FIELD_DATA)
    mode = VTK_SCALAR_MODE_USE_POINT_DATA;
  if (!name && mode == VTK_SCALAR_MODE_USE_CELL_FIELD_DATA)
    mode = VTK_SCALAR_MODE_USE_CELL_DATA;
  return vtkuv::FindRenderedScalar(
    input, mode, VTK_GET_ARRAY_BY_NAME, -1, name ? name : "", this->VolumeProperty);
}

namespace
{
/// The least finite value of the rendered scalar (0 when there is none).
double ScalarOffset(vtkDataSet* input, const vtkuv::RenderedScalar& scalar)
{
  const vtkIdType count = scalar.OnCells ? input->GetNumberOfCells() : input->GetNumberOfPoints();
  return uv::ScalarNormalisation::OfFiniteValues(
    static_cast<std::size_t>(count), [&](std::size_t i) { return scalar(static_cast<vtkIdType>(i)); })
    .Offset;
}

/// Makes `image` a width x height image of transparent premultiplied RGBA: its "RGBA" array.
vtkFloatArray* TransparentImage(vtkImageData* image, int width, int height)
{
  image->Initialize();
  image->SetDimensions(width, height, 1);
  vtkNew<vtkFloatArray> rgba;
  rgba->SetName("RGBA");
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  rgba->Fill(0.0);
  image->GetPointData()->SetScalars(rgba);
  return rgba;
}

/// Each pixel's ray integrated into `rgba` (premultiplied colour, opacity), pixels in parallel.
void IntegratePixels(const RayIntegrator& integrator, const PixelRays& rays, vtkFloatArray* rgba)
{
  float* pixels = rgba->GetPointer(0);
  vtkSMPThreadLocal<RayScratch> threadScratch;
  vtkSMPTools::For(0, rgba->GetNumberOfTuples(), [&](vtkIdType begin, vtkIdType end) {
    RayScratch& scratch = threadScratch.Local();
    for (vtkIdType pixel = begin; pixel < end; ++pixel)
    {
      const uv::RayAccumulator accumulator = integrator.Integrate(rays(pixel), scratch);
      float* out = pixels + 4 * pixel;
      out[0] = static_cast<float>(accumulator.Color.x);
      out[1] = static_cast<float>(accumulator.Color.y);
      out[2] = static_cast<float>(accumulator.Color.z);
      out[3] = static_cast<float>(accumulator.Opacity());
    }
  });
  rgba->Modified();
}
} // namespace

bool vtkUnstructuredVolumeReferenceRenderer::Render()
{
  const int width = this->ImageSize[0], height = this->ImageSize[1];
  if (width < 1 || height < 1)
  {
    vtkErrorMacro("ImageSize must be positive.");
    return false;
  }
  if (!this->Camera || !this->VolumeProperty)
  {
    vtkErrorMacro("A camera and a volume property are required.");
    return false;
  }
  vtkFloatArray* rgba = TransparentImage(this->Output, width, height);
  if (!this->Input || this->Input->GetNumberOfCells() == 0)
  {
    return true; // nothing to render: a transparent image
  }
  if (auto* cells = vtkUnstructuredGridBase::SafeDownCast(this->Input))
  {
    const std::string broken = vtkuv::FindMeshIntegrityError(cells);
    if (!broken.empty())
    {
      vtkErrorMacro(<< broken);
      return false;
    }
  }

  // Prisms and polyhedra as the project's conforming split defines their field (every mapper draws
  // that split too); the other cells as they are.
  const vtkSmartPointer<vtkDataSet> input = PolygonalCellsAsTetrahedra(this->Input);
  const vtkuv::RenderedScalar scalar = this->FindScalar(input);
  if (!scalar)
  {
    vtkErrorMacro("No " << (this->ScalarMode == VTK_SCALAR_MODE_USE_CELL_FIELD_DATA ? "cell" : "point or cell")
                        << " array " << (this->ScalarArrayName ? this->ScalarArrayName : "(active scalars)")
                        << " on the input.");
    return false;
  }
  std::vector<uv::TransferFunction::Node> nodes = vtkuv::TransferFunctionNodes(this->VolumeProperty);
  if (nodes.empty())
  {
    vtkErrorMacro("The volume property has no scalar opacity function.");
    return false;
  }
  // Scalars, nodes and isovalues are taken relative to the least finite scalar: a field of small
  // range far from zero (int64 values near 2^62) keeps its digits through interpolation.
  const double offset = ScalarOffset(input, scalar);
  for (uv::TransferFunction::Node& node : nodes)
    node.Scalar -= offset;
  const uv::TransferFunction transfer(nodes);
  if (transfer.IsInvisible() && this->Isosurfaces->Drawn(offset, 1.0).empty())
  {
    return true;
  }

  if (HasRationalBezierCells(input))
  {
    vtkErrorMacro("Rational Bezier cells (a RationalWeights point array) are not rendered by the reference.");
    return false;
  }
  Mesh mesh;
  mesh.LoadPoints(input, scalar, offset);
  if (!mesh.LoadCells(input))
  {
    vtkErrorMacro("The reference renderer takes linear tetrahedra, hexahedra, voxels, wedges, pyramids, "
                  "pentagonal and hexagonal prisms, polyhedra, quadratic and triquadratic cells, and Lagrange "
                  "and non-rational Bezier tetrahedra, hexahedra and wedges up to order 3; a cell is a "
      << uvcompat::CellTypeName(input->GetCellType(mesh.Unsupported)) << ".");
    return false;
  }
  if (mesh.NotThreeDimensional > 0)
  {
    vtkWarningMacro("Ignored " << mesh.NotThreeDimensional << " cells that are not 3D.");
  }
  if (mesh.NonFinite > 0)
  {
    vtkWarningMacro("Left out " << mesh.NonFinite << " cells with non-finite scalars.");
  }
  CellFaceSurfaces surfaces;
  surfaces.Drawn = this->Isosurfaces->Drawn(offset, 1.0);
  surfaces.Shading = this->VolumeProperty->GetAmbient() + this->VolumeProperty->GetDiffuse();
  surfaces.Touching = 1e-7 * input->GetLength(); // shared faces meet exactly; internal walls nearly
  if (!surfaces.Drawn.empty() && !mesh.OnCells())
  {
    vtkWarningMacro("Isosurfaces of a point scalar are not drawn by the reference renderer.");
  }
  const uv::BoundingVolumeHierarchy hierarchy(std::move(mesh.Boxes));
  const RayIntegrator integrator(mesh, hierarchy, transfer, this->Tolerance, surfaces);
  const PixelRays rays(this->Camera, mesh.Centre, width, height);

  IntegratePixels(integrator, rays, rgba);
  return true;
}

bool vtkUnstructuredVolumeReferenceRenderer::WritePNG(vtkImageData* image, const char* fileName,
  double backgroundRed, double backgroundGreen, double backgroundBlue)
{
  vtkDataArray* rgba = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!rgba || rgba->GetNumberOfComponents() != 4 || !fileName)
  {
    return false;
  }
  vtkNew<vtkImageData> rgb;
  rgb->SetDimensions(image->GetDimensions());
  vtkNew<vtkUnsignedCharArray> bytes;
  bytes->SetNumberOfComponents(3);
  bytes->SetNumberOfTuples(rgba->GetNumberOfTuples());
  const double background[3] = { backgroundRed, backgroundGreen, backgroundBlue };
  for (vtkIdType i = 0; i < rgba->GetNumberOfTuples(); ++i)
  {
    const double* pixel = rgba->GetTuple4(i);
    for (int c = 0; c < 3; ++c)
    {
      const double value = pixel[c] + (1.0 - pixel[3]) * background[c];
      bytes->SetValue(3 * i + c, static_cast<unsigned char>(std::lround(255.0 * std::clamp(value, 0.0, 1.0))));
    }
  }
  rgb->GetPointData()->SetScalars(bytes);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(rgb);
  writer->SetFileName(fileName);
  writer->Write();
  return writer->GetErrorCode() == 0;
}

void vtkUnstructuredVolumeReferenceRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ImageSize: " << this->ImageSize[0] << " x " << this->ImageSize[1] << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "ScalarArrayName: " << (this->ScalarArrayName ? this->ScalarArrayName : "(active)") << "\n";
  os << indent << "ScalarMode: " << this->ScalarMode << "\n";
}
