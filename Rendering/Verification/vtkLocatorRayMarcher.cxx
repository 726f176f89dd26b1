#include "vtkLocatorRayMarcher.h"
#include "vtkUnstructuredVolumeCompatibility.h"

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkCell.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFloatArray.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolygon.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkStaticCellLocator.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <string>

vtkStandardNewMacro(vtkLocatorRayMarcher);

namespace
{
/// A piecewise-linear function of the scalar with constant extension: (x, values) nodes.
template <int NV>
struct LinearNodes
{
  std::vector<double> X;
  std::vector<std::array<double, NV>> V;

  /// Value at s (linear between nodes, the end values outside them).
  std::array<double, NV> operator()(double s) const
  {
    if (s <= this->X.front())
    {
      return this->V.front();
    }
    if (s >= this->X.back())
    {
      return this->V.back();
    }
    // First node strictly above s; its predecessor is <= s.
    const std::size_t hi =
      static_cast<std::size_t>(std::upper_bound(this->X.begin(), this->X.end(), s) - this->X.begin());
    const std::size_t lo = hi - 1;
    const double width = this->X[hi] - this->X[lo];
    const double f = width > 0 ? (s - this->X[lo]) / width : 0.0;
    std::array<double, NV> out;
    for (int c = 0; c < NV; ++c)
    {
      out[c] = this->V[lo][c] + f * (this->V[hi][c] - this->V[lo][c]);
    }
    return out;
  }
};

/// The optical model: extinction and colour linear in s between the union nodes.
struct OpticalModel
{
  LinearNodes<4> Nodes; // tau, r, g, b

  /// Extinction tau(s) and emission c(s) tau(s).
  void Evaluate(double s, double& tau, double emission[3]) const
  {
    const std::array<double, 4> v = this->Nodes(s);
    tau = v[0];
    for (int c = 0; c < 3; ++c)
    {
      emission[c] = v[c + 1] * v[0];
    }
  }
};

bool IsPlainNode(double midpoint, double sharpness)
{
  return midpoint == 0.5 && sharpness == 0.0;
}

/// Reads a vtkPiecewiseFunction into nodes; false (and a reason) when it is not plain.
bool ReadPiecewise(vtkPiecewiseFunction* function, const char* what, LinearNodes<1>& nodes,
  std::string& reason)
{
  if (!function || function->GetSize() < 1)
  {
    reason = std::string("The ") + what + " has no nodes.";
    return false;
  }
  for (int i = 0; i < function->GetSize(); ++i)
  {
    double node[4];
    function->GetNodeValue(i, node);
    if (!IsPlainNode(node[2], node[3]))
    {
      reason = std::string("The ") + what +
        " has a node with midpoint != 0.5 or sharpness != 0; only piecewise-linear functions are supported.";
      return false;
    }
    nodes.X.push_back(node[0]);
    nodes.V.push_back({ node[1] });
  }
  return true;
}

/// Builds the optical model from component 0 of the property; false (and a reason) if unsupported.
bool BuildOpticalModel(vtkVolumeProperty* property, OpticalModel& model, std::string& reason)
{
  if (property->GetTransferFunctionMode() != vtkVolumeProperty::TF_1D)
  {
    reason = "Only 1D transfer functions are supported.";
    return false;
  }
  const double unitDistance = property->GetScalarOpacityUnitDistance(0);
  if (!(unitDistance > 0) || !std::isfinite(unitDistance))
  {
    reason = "The scalar opacity unit distance must be positive.";
    return false;
  }
  LinearNodes<1> opacity;
  if (!ReadPiecewise(property->GetScalarOpacity(0), "scalar opacity function", opacity, reason))
  {
    return false;
  }
  LinearNodes<3> colour;
  if (property->GetColorChannels(0) == 1)
  {
    LinearNodes<1> gray;
    if (!ReadPiecewise(property->GetGrayTransferFunction(0), "gray transfer function", gray, reason))
    {
      return false;
    }
    colour.X = gray.X;
    for (const auto& v : gray.V)
    {
      colour.V.push_back({ v[0], v[0], v[0] });
    }
  }
  else
  {
    vtkColorTransferFunction* function = property->GetRGBTransferFunction(0);
    if (!function || function->GetSize() < 1)
    {
      reason = "The colour transfer function has no nodes.";
      return false;
    }
    if (function->GetColorSpace() != VTK_CTF_RGB)
    {
      reason = "The colour transfer function's colour space is not RGB; only RGB-linear colour is supported.";
      return false;
    }
    if (function->GetScale() != VTK_CTF_LINEAR)
    {
      reason = "The colour transfer function's scale is not linear.";
      return false;
    }
    for (int i = 0; i < function->GetSize(); ++i)
    {
      double node[6];
      function->GetNodeValue(i, node);
      if (!IsPlainNode(node[4], node[5]))
      {
        reason = "The colour transfer function has a node with midpoint != 0.5 or sharpness != 0; "
                 "only piecewise-linear functions are supported.";
        return false;
      }
      colour.X.push_back(node[0]);
      colour.V.push_back({ node[1], node[2], node[3] });
    }
  }

  std::vector<double> xs = opacity.X;
  xs.insert(xs.end(), colour.X.begin(), colour.X.end());
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  for (double x : xs)
  {
    if (!std::isfinite(x))
    {
      reason = "A transfer-function node has a non-finite scalar.";
      return false;
    }
    const double alpha = std::min(std::max(opacity(x)[0], 0.0), 1.0 - 1e-9);
    const double tau = -std::log(1.0 - alpha) / unitDistance;
    const std::array<double, 3> c = colour(x);
    model.Nodes.X.push_back(x);
    model.Nodes.V.push_back({ tau, c[0], c[1], c[2] });
  }
  return true;
}

/// For cells with polygonal faces (prisms of 5 and 6 sides, polyhedra) VTK's parametric
/// coordinates span the cell's bounding box, so EvaluatePosition cannot tell what is inside: x must
/// be behind every face's plane (the face's normal oriented away from the mean of the cell's
/// points). Exact for convex cells, which is what this check is meant for.
bool InsideConvexFaces(vtkCell* cell, const double x[3])
{
  double centre[3] = { 0, 0, 0 }, p[3];
  vtkPoints* points = cell->GetPoints();
  const vtkIdType n = points->GetNumberOfPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->GetPoint(i, p);
    for (int d = 0; d < 3; ++d)
      centre[d] += p[d] / n;
  }
  for (int f = 0; f < cell->GetNumberOfFaces(); ++f)
  {
    vtkCell* face = cell->GetFace(f);
    double normal[3], origin[3];
    vtkPolygon::ComputeNormal(face->GetPoints(), normal);
    face->GetPoints()->GetPoint(0, origin);
    const double side = vtkMath::Dot(normal, centre) - vtkMath::Dot(normal, origin);
    const double at = vtkMath::Dot(normal, x) - vtkMath::Dot(normal, origin);
    if (at * side < 0.0 || at == 0.0)
      return false;
  }
  return true;
}

/// Strict containment: pcoords inside the cell's parametric domain (VTK's EvaluatePosition
/// accepts a tolerance of 1e-3 around it, under which neighbouring cells would overlap).
bool StrictlyInside(vtkCell* cell, const double pcoords[3], const double x[3])
{
  if (cell->GetParametricDistance(pcoords) > 0.0)
  {
    return false;
  }
  switch (cell->GetCellType())
  {
    case VTK_WEDGE:
    case VTK_QUADRATIC_WEDGE:
    case VTK_QUADRATIC_LINEAR_WEDGE:
    case VTK_BIQUADRATIC_QUADRATIC_WEDGE:
    case VTK_LAGRANGE_WEDGE:
    case VTK_BEZIER_WEDGE:
      return pcoords[0] + pcoords[1] <= 1.0;
    case VTK_TETRA:
    case VTK_QUADRATIC_TETRA:
    case VTK_LAGRANGE_TETRAHEDRON:
    case VTK_BEZIER_TETRAHEDRON:
      // vtkTetra's parametric distance looks at r, s, t only, not at 1 - r - s - t.
      return pcoords[0] + pcoords[1] + pcoords[2] <= 1.0;
    case VTK_PENTAGONAL_PRISM:
    case VTK_HEXAGONAL_PRISM:
    case VTK_POLYHEDRON:
      return InsideConvexFaces(cell, x);
    default:
      return true;
  }
}

/// Grows a higher-order cell's bounds (of its points) to its shape sampled densely over its
/// parametric box, padded by a twentieth of its size; returns how far they grew.
double ExtendToSampledShape(vtkCell* cell, double bounds[6])
{
  const double original[6] = { bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5] };
  std::vector<double> weights(static_cast<std::size_t>(cell->GetNumberOfPoints()));
  constexpr int N = 8;
  for (int i = 0; i <= N; ++i)
    for (int j = 0; j <= N; ++j)
      for (int k = 0; k <= N; ++k)
      {
        double pcoords[3] = { double(i) / N, double(j) / N, double(k) / N }, x[3];
        int subId = 0;
        cell->EvaluateLocation(subId, pcoords, x, weights.data());
        if (!StrictlyInside(cell, pcoords, x))
          continue; // outside a simplex's or a wedge's domain the map extrapolates
        for (int a = 0; a < 3; ++a)
        {
          bounds[2 * a] = std::min(bounds[2 * a], x[a]);
          bounds[2 * a + 1] = std::max(bounds[2 * a + 1], x[a]);
        }
      }
  const double size = std::sqrt(
    (bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) + (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  double grown = 0.0;
  for (int a = 0; a < 6; ++a)
  {
    bounds[a] += (a % 2 ? 1.0 : -1.0) * 0.05 * size;
    grown = std::max(grown, std::abs(bounds[a] - original[a]));
  }
  return grown;
}

std::mutex BezierWedgeMutex;

/// Whether VTK 9.1's InterpolateDerivs of this higher-order cell type is right (checked against
/// differences of its shape functions): not for Lagrange and Bezier hexahedra (interleaved per
/// node) nor Bezier tetrahedra and wedges (wrong).
bool VtkDerivativesUsable(int type)
{
  return type != VTK_LAGRANGE_HEXAHEDRON && type != VTK_BEZIER_HEXAHEDRON && type != VTK_BEZIER_TETRAHEDRON &&
    type != VTK_BEZIER_WEDGE;
}

/// d(weights)/d(pcoords) by central differences of VTK's own shape functions, in VTK's layout (all
/// d/dr, then d/ds, then d/dt), for the cells whose InterpolateDerivs cannot serve
/// (VtkDerivativesUsable). Newton needs the Jacobian only to step; its fixed point is exact whatever
/// the small error of the differences.
void ShapeDerivativesByDifferences(vtkCell* cell, const double pcoords[3], double* derivatives, std::vector<double>& scratch)
{
  const int n = cell->GetNumberOfPoints();
  scratch.resize(2 * static_cast<std::size_t>(n));
  const double h = 1e-6;
  for (int axis = 0; axis < 3; ++axis)
  {
    double ahead[3] = { pcoords[0], pcoords[1], pcoords[2] }, behind[3] = { pcoords[0], pcoords[1], pcoords[2] };
    ahead[axis] += h;
    behind[axis] -= h;
    cell->InterpolateFunctions(ahead, scratch.data());
    cell->InterpolateFunctions(behind, scratch.data() + n);
    for (int k = 0; k < n; ++k)
      derivatives[axis * n + k] = (scratch[k] - scratch[n + k]) / (2 * h);
  }
}

/// A higher-order cell's pcoords of x by Newton from `pcoords`, through VTK's shape functions, and
/// the weights there; false if it does not converge. VTK's own EvaluatePosition stops at a loose
/// tolerance (seen as field error) and gives up near curved faces (seen as lost matter).
bool SolveParametricCoordinates(vtkCell* cell, const double x[3], double pcoords[3], double* weights)
{
  const int n = cell->GetNumberOfPoints();
  std::vector<double> derivatives(3 * static_cast<std::size_t>(n)), scratch;
  for (int iteration = 0; iteration < 40; ++iteration)
  {
    cell->InterpolateFunctions(pcoords, weights);
    if (VtkDerivativesUsable(cell->GetCellType()))
      cell->InterpolateDerivs(pcoords, derivatives.data());
    else
      ShapeDerivativesByDifferences(cell, pcoords, derivatives.data(), scratch);
    double residual[3] = { -x[0], -x[1], -x[2] }, columns[3][3] = {};
    for (int k = 0; k < n; ++k)
    {
      double p[3];
      cell->GetPoints()->GetPoint(k, p);
      for (int i = 0; i < 3; ++i)
      {
        residual[i] += weights[k] * p[i];
        for (int d = 0; d < 3; ++d)
          columns[d][i] += derivatives[d * n + k] * p[i];
      }
    }
    double jacobian[3][3];
    for (int i = 0; i < 3; ++i)
      for (int d = 0; d < 3; ++d)
        jacobian[i][d] = columns[d][i];
    double* rows[3] = { jacobian[0], jacobian[1], jacobian[2] };
    if (vtkMath::SolveLinearSystem(rows, residual, 3) == 0) // residual becomes the step
      return false;
    const double longest = std::max({ std::abs(residual[0]), std::abs(residual[1]), std::abs(residual[2]) });
    const double scale = longest > 0.5 ? 0.5 / longest : 1.0; // a damped start far from x
    for (int i = 0; i < 3; ++i)
      pcoords[i] -= scale * residual[i];
    if (cell->GetParametricDistance(pcoords) > 1.0)
      return false; // far outside: x is not in the cell
    if (longest < 1e-13)
    {
      cell->InterpolateFunctions(pcoords, weights);
      return true;
    }
  }
  return false;
}

/// One component of every tuple, or (component -1) the tuple's Euclidean norm.
std::vector<double> ComponentOrNorm(vtkDataArray* array, int component)
{
  std::vector<double> values(static_cast<std::size_t>(array->GetNumberOfTuples()));
  std::vector<double> tuple(static_cast<std::size_t>(array->GetNumberOfComponents()));
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    array->GetTuple(i, tuple.data());
    double norm = 0;
    for (double v : tuple)
      norm += v * v;
    values[i] = component < 0 ? std::sqrt(norm) : tuple[component];
  }
  return values;
}

/// 1 for the cells the marcher samples: 3D, every point scalar (or the cell's scalar) finite.
/// Single-threaded; it also makes VTK's lazy cell initialisation happen before any thread calls
/// GetCell.
std::vector<unsigned char> UsableCells(vtkDataSet* input, const std::vector<double>& scalars, bool cellScalars)
{
  const vtkIdType numberOfCells = input->GetNumberOfCells();
  vtkNew<vtkGenericCell> cell;
  input->GetCell(0, cell);
  std::map<int, int> dimensionOfType;
  vtkNew<vtkGenericCell> typeProbe;
  vtkNew<vtkIdList> pointIds;
  std::vector<unsigned char> usable(static_cast<std::size_t>(numberOfCells), 0);
  for (vtkIdType c = 0; c < numberOfCells; ++c)
  {
    const int type = input->GetCellType(c);
    auto found = dimensionOfType.find(type);
    if (found == dimensionOfType.end())
    {
      typeProbe->SetCellType(type);
      found = dimensionOfType.emplace(type, typeProbe->GetCellDimension()).first;
    }
    if (found->second != 3)
      continue;
    input->GetCellPoints(c, pointIds);
    bool finite = pointIds->GetNumberOfIds() > 0 && (!cellScalars || std::isfinite(scalars[c]));
    for (vtkIdType j = 0; j < pointIds->GetNumberOfIds() && finite && !cellScalars; ++j)
      finite = std::isfinite(scalars[pointIds->GetId(j)]);
    usable[c] = finite ? 1 : 0;
  }
  return usable;
}

/// The index of the first pixel outside a width x height image, or -1.
vtkIdType FirstPixelOutside(vtkIdTypeArray* pixels, int width, int height)
{
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
  {
    const vtkIdType p = pixels->GetValue(i);
    if (p < 0 || p >= static_cast<vtkIdType>(width) * height)
      return i;
  }
  return -1;
}

/// Everything the pixel workers read (shared, read-only) and their per-thread scratch.
struct MarchPixelsWorker
{
  vtkDataSet* Input;
  vtkStaticCellLocator* Locator;
  const double* CellBounds;
  const std::vector<unsigned char>* UsableCell;
  const std::vector<double>* Scalars; // per point, or per cell when CellScalars
  bool CellScalars;
  const OpticalModel* Model;
  double InverseProjection[16];
  double Bounds[6];
  double Pad; // 1e-9 of the bounds' diagonal: query boxes, cell-bounds tests, membership shift
  double Reach; // how far past a cell's points it may reach (curved cells), at least Pad
  int Width, Height, Steps;
  const vtkIdType* Pixels;
  float* Output;

  vtkSMPThreadLocalObject<vtkGenericCell> Cells;
  vtkSMPThreadLocalObject<vtkIdList> Candidates;
  vtkSMPThreadLocal<std::vector<double>> Weights;
  int MaxCellSize;

  void Initialize()
  {
    this->Weights.Local().resize(static_cast<std::size_t>(std::max(this->MaxCellSize, 1)));
    this->Candidates.Local()->Allocate(64);
  }

  bool InCellBounds(vtkIdType cellId, const double x[3]) const
  {
    const double* b = this->CellBounds + 6 * cellId;
    return x[0] >= b[0] - this->Pad && x[0] <= b[1] + this->Pad && x[1] >= b[2] - this->Pad &&
      x[1] <= b[3] + this->Pad && x[2] >= b[4] - this->Pad && x[2] <= b[5] + this->Pad;
  }

  /// Whether `cell` contains x, with its pcoords and weights there. Linear cells: VTK's
  /// EvaluatePosition. Higher-order cells: this file's Newton from where VTK's EvaluatePosition
  /// ended, or from the centre where that gave up; for the cells whose VTK 9.1 derivatives are wrong
  /// or interleaved (ShapeDerivativesByDifferences), VTK's own Newton is no guide and this one starts
  /// from the centre. VTK 9.1's Bezier wedges share a scratch triangle between all threads: their
  /// evaluations are serialised.
  bool Contains(vtkGenericCell* cell, const double x[3], double pcoords[3], std::vector<double>& weights)
  {
    double closest[3], dist2;
    int subId = 0;
    if (cell->IsLinear())
      return cell->EvaluatePosition(x, closest, subId, pcoords, dist2, weights.data()) == 1;
    const int type = cell->GetCellType();
    std::unique_lock<std::mutex> serialised(BezierWedgeMutex, std::defer_lock);
    if (type == VTK_BEZIER_WEDGE)
      serialised.lock();
    const int status =
      VtkDerivativesUsable(type) ? cell->EvaluatePosition(x, closest, subId, pcoords, dist2, weights.data()) : -1;
    if (status == 0 && cell->GetParametricDistance(pcoords) > 0.01)
      return false; // VTK's Newton converged well outside
    if (status == -1)
      cell->GetParametricCenter(pcoords); // it gave up (seen near curved faces), or is no guide
    return SolveParametricCoordinates(cell, x, pcoords, weights.data());
  }

  /// Visits every usable cell containing x with its interpolated scalar; `visit` returns false to
  /// stop. Returns the number of containing cells visited.
  ///
  /// Membership is decided at x moved by Pad in a fixed generic direction (simulation of
  /// simplicity): a point on a face between two cells (a whole ray does lie in one where an
  /// axis-aligned grid is seen along an axis) then belongs to exactly one of them, while cells that
  /// overlap over a volume still all count. The scalar moves by Pad times its gradient.
  template <typename Visit>
  int ForEachContainingCell(const double point[3], Visit&& visit)
  {
    static constexpr double generic[3] = { 0.4015393566, 0.5823305244, 0.7068016279 };
    const double x[3] = { point[0] + this->Pad * generic[0], point[1] + this->Pad * generic[1],
      point[2] + this->Pad * generic[2] };
    vtkGenericCell* cell = this->Cells.Local();
    vtkIdList* candidates = this->Candidates.Local();
    std::vector<double>& weights = this->Weights.Local();
    // The locator bins cells by their points' bounds, which a curved cell bulges past.
    double box[6] = { x[0] - this->Reach, x[0] + this->Reach, x[1] - this->Reach, x[1] + this->Reach,
      x[2] - this->Reach, x[2] + this->Reach };
    this->Locator->FindCellsWithinBounds(box, candidates);
    int found = 0;
    const vtkIdType n = candidates->GetNumberOfIds();
    for (vtkIdType i = 0; i < n; ++i)
    {
      const vtkIdType cellId = candidates->GetId(i);
      if (!(*this->UsableCell)[cellId] || !this->InCellBounds(cellId, x))
      {
        continue;
      }
      this->Input->GetCell(cellId, cell);
      double pcoords[3];
      if (!this->Contains(cell, x, pcoords, weights) || !StrictlyInside(cell, pcoords, x))
      {
        continue;
      }
      double s = 0;
      const vtkIdType np = cell->GetNumberOfPoints();
      for (vtkIdType j = 0; j < np && !this->CellScalars; ++j)
      {
        s += weights[j] * (*this->Scalars)[cell->GetPointId(j)];
      }
      if (this->CellScalars)
      {
        s = (*this->Scalars)[cellId];
      }
      ++found;
      if (!visit(s))
      {
        break;
      }
    }
    return found;
  }

  bool Inside(const double x[3])
  {
    return this->ForEachContainingCell(x, [](double) { return false; }) > 0;
  }

  /// Total extinction and emission at x (superposition over all containing cells); returns how
  /// many cells contain x.
  int Sample(const double x[3], double& tau, double emission[3])
  {
    tau = 0;
    emission[0] = emission[1] = emission[2] = 0;
    return this->ForEachContainingCell(x, [&](double s) {
      double t, e[3];
      this->Model->Evaluate(s, t, e);
      tau += t;
      for (int c = 0; c < 3; ++c)
      {
        emission[c] += e[c];
      }
      return true;
    });
  }

  /// The pixel's ray from the near to the far plane, cut to the mesh's bounds: x(t) = Origin +
  /// t Direction for t in [Begin, End]. False when it misses the bounds.
  struct Ray
  {
    double Origin[3], Direction[3];
    double Length; // |Direction|: world units per unit of t
    double Begin, End;

    void At(double t, double x[3]) const
    {
      for (int i = 0; i < 3; ++i)
        x[i] = this->Origin[i] + t * this->Direction[i];
    }
  };

  bool PixelRay(vtkIdType p, Ray& ray) const
  {
    const int px = static_cast<int>(p % this->Width), py = static_cast<int>(p / this->Width);
    const double ndcX = 2.0 * (px + 0.5) / this->Width - 1.0;
    const double ndcY = 2.0 * (py + 0.5) / this->Height - 1.0;
    double nearPoint[4], farPoint[4];
    const double nearNdc[4] = { ndcX, ndcY, -1.0, 1.0 }, farNdc[4] = { ndcX, ndcY, 1.0, 1.0 };
    vtkMatrix4x4::MultiplyPoint(this->InverseProjection, nearNdc, nearPoint);
    vtkMatrix4x4::MultiplyPoint(this->InverseProjection, farNdc, farPoint);
    if (nearPoint[3] == 0 || farPoint[3] == 0)
    {
      return false;
    }
    for (int i = 0; i < 3; ++i)
    {
      ray.Origin[i] = nearPoint[i] / nearPoint[3];
      ray.Direction[i] = farPoint[i] / farPoint[3] - ray.Origin[i];
    }
    ray.Length = std::sqrt(ray.Direction[0] * ray.Direction[0] + ray.Direction[1] * ray.Direction[1] +
      ray.Direction[2] * ray.Direction[2]);
    if (!(ray.Length > 0) || !std::isfinite(ray.Length))
    {
      return false;
    }
    // Cut the segment t in [0, 1] (near to far) to the bounding box.
    ray.Begin = 0.0;
    ray.End = 1.0;
    for (int i = 0; i < 3; ++i)
    {
      const double lo = this->Bounds[2 * i], hi = this->Bounds[2 * i + 1];
      if (ray.Direction[i] == 0.0)
      {
        if (ray.Origin[i] < lo || ray.Origin[i] > hi)
          return false;
        continue;
      }
      double a = (lo - ray.Origin[i]) / ray.Direction[i], b = (hi - ray.Origin[i]) / ray.Direction[i];
      if (a > b)
        std::swap(a, b);
      ray.Begin = std::max(ray.Begin, a);
      ray.End = std::min(ray.End, b);
    }
    return ray.End > ray.Begin;
  }

  /// Front-to-back compositing along one ray.
  struct Accumulation
  {
    double Transmittance = 1.0, Colour[3] = { 0, 0, 0 };

    /// A homogeneous piece of `h` world units (the medium sampled at its middle).
    void Composite(double h, double tau, const double emission[3])
    {
      if (tau > 0)
      {
        const double absorbed = -std::expm1(-tau * h);
        for (int c = 0; c < 3; ++c)
          this->Colour[c] += this->Transmittance * emission[c] / tau * absorbed;
        this->Transmittance *= 1.0 - absorbed;
      }
      else
      {
        for (int c = 0; c < 3; ++c)
          this->Colour[c] += this->Transmittance * emission[c] * h;
      }
    }
  };

  /// The medium over [a, b] (ray parameters) sampled at its middle.
  void Integrate(const Ray& ray, double a, double b, Accumulation& sum)
  {
    const double h = (b - a) * ray.Length;
    if (h > 0)
    {
      double x[3], tau, emission[3];
      ray.At(0.5 * (a + b), x);
      this->Sample(x, tau, emission);
      sum.Composite(h, tau, emission);
    }
  }

  /// The mesh boundary between lo (inside the mesh or not: loInside) and hi (the other), by bisection.
  double Crossing(const Ray& ray, double lo, double hi, bool loInside)
  {
    double x[3];
    for (int iteration = 0; iteration < 40; ++iteration)
    {
      const double mid = 0.5 * (lo + hi);
      ray.At(mid, x);
      (this->Inside(x) == loInside ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }

  /// One step [ta, tb] whose ends are inside the mesh or not (insideA, insideB): only the inside
  /// parts are integrated, boundaries found by bisection.
  void MarchStep(const Ray& ray, double ta, double tb, bool insideA, bool insideB, Accumulation& sum)
  {
    const double tm = 0.5 * (ta + tb);
    double x[3];
    if (insideA && insideB)
    {
      double tau, emission[3];
      ray.At(tm, x);
      if (this->Sample(x, tau, emission) > 0)
      {
        sum.Composite((tb - ta) * ray.Length, tau, emission);
      }
      else
      {
        // A gap of the mesh around the step's middle: integrate up to it and after it.
        this->Integrate(ray, ta, this->Crossing(ray, ta, tm, true), sum);
        this->Integrate(ray, this->Crossing(ray, tm, tb, false), tb, sum);
      }
    }
    else if (insideA != insideB)
    {
      // The boundary lies in (ta, tb): integrate only the inside part.
      const double boundary = this->Crossing(ray, ta, tb, insideA);
      if (insideA)
        this->Integrate(ray, ta, boundary, sum);
      else
        this->Integrate(ray, boundary, tb, sum);
    }
    else
    {
      // Both ends outside: a thin part of the mesh may still hold the step's middle.
      ray.At(tm, x);
      if (this->Inside(x))
        this->Integrate(ray, this->Crossing(ray, ta, tm, false), this->Crossing(ray, tm, tb, true), sum);
    }
  }

  void MarchOne(vtkIdType p, float* out)
  {
    out[0] = out[1] = out[2] = out[3] = 0.0f;
    Ray ray;
    if (!this->PixelRay(p, ray))
    {
      return;
    }
    Accumulation sum;
    double x[3];
    double ta = ray.Begin;
    ray.At(ta, x);
    bool insideA = this->Inside(x);
    for (int step = 0; step < this->Steps && sum.Transmittance >= 1e-7; ++step)
    {
      const double tb = step + 1 == this->Steps
        ? ray.End
        : ray.Begin + (ray.End - ray.Begin) * (static_cast<double>(step + 1) / this->Steps);
      ray.At(tb, x);
      const bool insideB = this->Inside(x);
      this->MarchStep(ray, ta, tb, insideA, insideB, sum);
      ta = tb;
      insideA = insideB;
    }
    for (int c = 0; c < 3; ++c)
      out[c] = static_cast<float>(sum.Colour[c]);
    out[3] = static_cast<float>(1.0 - sum.Transmittance);
  }

  void operator()(vtkIdType begin, vtkIdType end)
  {
    for (vtkIdType i = begin; i < end; ++i)
    {
      this->MarchOne(this->Pixels[i], this->Output + 4 * i);
    }
  }

  void Reduce() {}
};
} // namespace

//------------------------------------------------------------------------------
vtkLocatorRayMarcher::vtkLocatorRayMarcher() = default;

//------------------------------------------------------------------------------
vtkLocatorRayMarcher::~vtkLocatorRayMarcher()
{
  this->SetScalarArrayName(nullptr);
}

//------------------------------------------------------------------------------
void vtkLocatorRayMarcher::SetInputData(vtkDataSet* input)
{
  vtkSetSmartPointerBodyMacro(Input, vtkDataSet, input);
}
vtkCxxSetSmartPointerMacro(vtkLocatorRayMarcher, VolumeProperty, vtkVolumeProperty);
vtkCxxSetSmartPointerMacro(vtkLocatorRayMarcher, Camera, vtkCamera);

vtkDataSet* vtkLocatorRayMarcher::GetInput()
{
  return this->Input;
}

vtkVolumeProperty* vtkLocatorRayMarcher::GetVolumeProperty()
{
  return this->VolumeProperty;
}

vtkCamera* vtkLocatorRayMarcher::GetCamera()
{
  return this->Camera;
}

//------------------------------------------------------------------------------
void vtkLocatorRayMarcher::UpdateLocator()
{
  if (this->Locator && this->Locator->GetDataSet() == this->Input &&
    this->Input->GetMTime() <= this->LocatorBuildTime.GetMTime())
  {
    return;
  }
  this->Locator = vtkSmartPointer<vtkStaticCellLocator>::New();
  this->Locator->SetDataSet(this->Input);
  this->Locator->BuildLocator();
  const vtkIdType numberOfCells = this->Input->GetNumberOfCells();
  this->CellBounds.assign(static_cast<std::size_t>(6 * numberOfCells), 0.0);
  this->CurvedReach = 0.0;
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType i = 0; i < numberOfCells; ++i)
  {
    double* bounds = this->CellBounds.data() + 6 * i;
    this->Input->GetCellBounds(i, bounds);
    if (uvcompat::IsLinearCellType(this->Input->GetCellType(i)))
    {
      continue; // by type: no cell built for the common case
    }
    this->Input->GetCell(i, cell);
    this->CurvedReach = std::max(this->CurvedReach, ExtendToSampledShape(cell, bounds));
  }
  this->LocatorBuildTime.Modified();
}

//------------------------------------------------------------------------------
vtkDataArray* vtkLocatorRayMarcher::ValidatedScalars(vtkIdTypeArray* pixels, vtkFloatArray* rgba)
{
  if (!pixels || !rgba)
  {
    vtkErrorMacro("MarchPixels needs a pixel array and an output array.");
    return nullptr;
  }
  if (!this->Input)
  {
    vtkErrorMacro("No input.");
    return nullptr;
  }
  if (!this->Camera)
  {
    vtkErrorMacro("No camera.");
    return nullptr;
  }
  if (!this->VolumeProperty)
  {
    vtkErrorMacro("No volume property.");
    return nullptr;
  }
  const int width = this->ImageSize[0], height = this->ImageSize[1];
  if (width < 1 || height < 1)
  {
    vtkErrorMacro("Bad image size " << width << "x" << height << ".");
    return nullptr;
  }
  if (pixels->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro("The pixel array must have one component.");
    return nullptr;
  }
  const vtkIdType outside = FirstPixelOutside(pixels, width, height);
  if (outside >= 0)
  {
    vtkErrorMacro("Pixel index " << pixels->GetValue(outside) << " is outside the " << width << "x" << height
                                 << " image.");
    return nullptr;
  }
  vtkDataSetAttributes* attributes = this->CellScalars
    ? static_cast<vtkDataSetAttributes*>(this->Input->GetCellData())
    : static_cast<vtkDataSetAttributes*>(this->Input->GetPointData());
  vtkDataArray* array =
    this->ScalarArrayName ? attributes->GetArray(this->ScalarArrayName) : attributes->GetScalars();
  const char* where = this->CellScalars ? "cell" : "point";
  if (!array)
  {
    vtkErrorMacro("The input has no " << where << " array "
      << (this->ScalarArrayName ? this->ScalarArrayName : "(active scalars)") << ".");
    return nullptr;
  }
  const vtkIdType expected = this->CellScalars ? this->Input->GetNumberOfCells() : this->Input->GetNumberOfPoints();
  if (array->GetNumberOfTuples() != expected || array->GetNumberOfComponents() <= this->ScalarComponent)
  {
    vtkErrorMacro("The scalar array has " << array->GetNumberOfTuples() << " tuples of "
      << array->GetNumberOfComponents() << " components for " << expected << " " << where << "s (component "
      << this->ScalarComponent << " asked for).");
    return nullptr;
  }
  return array;
}

//------------------------------------------------------------------------------
bool vtkLocatorRayMarcher::MarchPixels(vtkIdTypeArray* pixels, vtkFloatArray* rgba)
{
  vtkDataArray* array = this->ValidatedScalars(pixels, rgba);
  if (!array)
  {
    return false;
  }
  OpticalModel model;
  std::string reason;
  if (!BuildOpticalModel(this->VolumeProperty, model, reason))
  {
    vtkErrorMacro(<< reason);
    return false;
  }
  const int width = this->ImageSize[0], height = this->ImageSize[1];
  const vtkIdType numberOfPixels = pixels->GetNumberOfTuples();
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(numberOfPixels);
  if (numberOfPixels == 0)
  {
    return true;
  }
  std::fill_n(rgba->GetPointer(0), 4 * numberOfPixels, 0.0f);
  const vtkIdType numberOfCells = this->Input->GetNumberOfCells();
  if (numberOfCells == 0)
  {
    return true;
  }

  const std::vector<double> scalars = ComponentOrNorm(array, this->ScalarComponent);
  const std::vector<unsigned char> usable = UsableCells(this->Input, scalars, this->CellScalars);
  this->UpdateLocator();

  MarchPixelsWorker worker;
  worker.Input = this->Input;
  worker.Locator = this->Locator;
  worker.CellBounds = this->CellBounds.data();
  worker.UsableCell = &usable;
  worker.Scalars = &scalars;
  worker.CellScalars = this->CellScalars;
  worker.Model = &model;
  this->Input->GetBounds(worker.Bounds);
  const double dx = worker.Bounds[1] - worker.Bounds[0], dy = worker.Bounds[3] - worker.Bounds[2],
               dz = worker.Bounds[5] - worker.Bounds[4];
  worker.Pad = 1e-9 * std::sqrt(dx * dx + dy * dy + dz * dz);
  worker.Reach = std::max(worker.Pad, this->CurvedReach);
  for (int i = 0; i < 6; ++i)
  {
    worker.Bounds[i] += (i % 2 ? 1.0 : -1.0) * this->CurvedReach;
  }
  worker.Width = width;
  worker.Height = height;
  worker.Steps = this->NumberOfSteps;
  worker.Pixels = pixels->GetPointer(0);
  worker.Output = rgba->GetPointer(0);
  worker.MaxCellSize = this->Input->GetMaxCellSize();
  vtkMatrix4x4* projection = this->Camera->GetCompositeProjectionTransformMatrix(
    width / static_cast<double>(height), -1.0, 1.0);
  vtkMatrix4x4::Invert(projection->GetData(), worker.InverseProjection);

  vtkSMPTools::For(0, numberOfPixels, 1, worker);
  rgba->Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkLocatorRayMarcher::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Input: " << this->Input.Get() << "\n";
  os << indent << "ScalarArrayName: " << (this->ScalarArrayName ? this->ScalarArrayName : "(none)")
     << "\n";
  os << indent << "CellScalars: " << this->CellScalars << "\n";
  os << indent << "ScalarComponent: " << this->ScalarComponent << "\n";
  os << indent << "VolumeProperty: " << this->VolumeProperty.Get() << "\n";
  os << indent << "Camera: " << this->Camera.Get() << "\n";
  os << indent << "ImageSize: " << this->ImageSize[0] << " " << this->ImageSize[1] << "\n";
  os << indent << "NumberOfSteps: " << this->NumberOfSteps << "\n";
}
