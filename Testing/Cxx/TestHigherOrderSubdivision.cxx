// vtkHigherOrderSubdivision: the error trend of its linear interpolation, the level choice,
// conformity across cells and families, the real higher-order meshes, and degenerate input.
#include "uvTestMeshChecks.h"
#include "vtkHexahedraToTetrahedra.h"
#include "vtkHigherOrderSubdivision.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>
#include <set>

namespace
{
vtkSmartPointer<vtkUnstructuredGrid> Subdivide(vtkDataSet* input, int level = 0,
  uvtest::EventCounter** counter = nullptr, vtkSmartPointer<vtkHigherOrderSubdivision>* filterOut = nullptr)
{
  auto filter = vtkSmartPointer<vtkHigherOrderSubdivision>::New();
  uvtest::EventCounter* watched = uvtest::WatchEvents(filter);
  if (counter)
  {
    *counter = watched;
  }
  filter->SetLevel(level);
  filter->SetInputData(input);
  filter->Update();
  if (filterOut)
  {
    *filterOut = filter;
  }
  return filter->GetOutput();
}

vtkSmartPointer<vtkUnstructuredGrid> Tetrahedralize(vtkDataSet* input)
{
  vtkNew<vtkHexahedraToTetrahedra> split;
  split->SetInputData(input);
  split->Update();
  return split->GetOutput();
}

double Quadratic(const double x[3])
{
  return x[0] * x[0] + x[1] * x[2];
}

/// One curved quadratic tet: unit corners, mid-edge nodes pushed off the edges; point array "f"
/// holds x^2 + y z at the nodes.
vtkSmartPointer<vtkUnstructuredGrid> CurvedQuadraticTet()
{
  const double xyz[10][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0.5, -0.08, 0.04 },
    { 0.55, 0.55, 0.05 }, { -0.06, 0.5, 0.03 }, { 0.04, -0.05, 0.5 }, { 0.55, 0.03, 0.55 },
    { -0.04, 0.56, 0.52 } };
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> f;
  f->SetName("f");
  for (const auto& p : xyz)
  {
    points->InsertNextPoint(p);
    f->InsertNextValue(Quadratic(p));
  }
  grid->SetPoints(points);
  grid->GetPointData()->SetScalars(f);
  const vtkIdType ids[10] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9 };
  grid->InsertNextCell(VTK_QUADRATIC_TETRA, 10, ids);
  return grid;
}

/// RMS difference at random points between the input cell's own field and the output's linear
/// interpolation (points the linear cells miss, near the curved boundary, are skipped).
double RmsFieldError(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output, int samples)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  vtkNew<vtkGenericCell> cell, child;
  input->GetCell(0, cell);
  vtkDataArray* f = input->GetPointData()->GetArray("f");
  vtkDataArray* g = output->GetPointData()->GetArray("f");
  double sum = 0.0;
  int found = 0;
  std::vector<double> weights(10);
  for (int s = 0; s < samples; ++s)
  {
    double pc[3] = { unit(random), unit(random), unit(random) };
    if (pc[0] + pc[1] + pc[2] > 1.0)
    {
      continue;
    }
    double x[3], own = 0.0;
    int subId = 0;
    cell->EvaluateLocation(subId, pc, x, weights.data());
    for (int n = 0; n < 10; ++n)
    {
      own += weights[n] * f->GetTuple1(cell->GetPointId(n));
    }
    for (vtkIdType c = 0; c < output->GetNumberOfCells(); ++c)
    {
      output->GetCell(c, child);
      double closest[3], childPc[3], dist2, w[4];
      if (child->EvaluatePosition(x, closest, subId, childPc, dist2, w) == 1)
      {
        double linear = 0.0;
        for (int v = 0; v < 4; ++v)
        {
          linear += w[v] * g->GetTuple1(child->GetPointId(v));
        }
        sum += (linear - own) * (linear - own);
        ++found;
        break;
      }
    }
  }
  EXPECT_GT(found, samples / 8);
  return std::sqrt(sum / std::max(found, 1));
}

/// Sum of the output's linear cells' volumes, through the conforming tet split.
double LinearVolume(vtkUnstructuredGrid* linear)
{
  const std::vector<double> volumes = uvtest::TetVolumes(Tetrahedralize(linear));
  return std::accumulate(volumes.begin(), volumes.end(), 0.0);
}

/// The volume of a mesh of higher-order tets, hexahedra and wedges: Gauss-Legendre quadrature of the
/// isoparametric Jacobian (tets and wedges through the collapsed cube). vtkIntegrateAttributes of
/// VTK 9.1 skips triquadratic hexahedra and quadratic wedges, so it cannot be the reference.
double IsoparametricVolume(vtkDataSet* mesh)
{
  const double gx[5] = { -0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640 };
  const double gw[5] = { 0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
    0.2369268850561891 };
  vtkNew<vtkGenericCell> cell;
  double volume = 0.0;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCell(c, cell);
    const int faces = cell->GetNumberOfFaces();
    const int corners = faces == 4 ? 4 : faces == 6 ? 8 : 6;
    const vtkIdType n = cell->GetNumberOfPoints();
    std::vector<double> derivs(static_cast<std::size_t>(3 * n));
    for (int a = 0; a < 125; ++a)
    {
      const double u = 0.5 * (gx[a % 5] + 1), v = 0.5 * (gx[(a / 5) % 5] + 1), w = 0.5 * (gx[a / 25] + 1);
      const double weight = gw[a % 5] * gw[(a / 5) % 5] * gw[a / 25] / 8.0;
      double pc[3] = { u, v, w }, collapse = 1.0;
      if (corners == 4)
      {
        pc[1] = v * (1 - u), pc[2] = w * (1 - u) * (1 - v), collapse = (1 - u) * (1 - u) * (1 - v);
      }
      else if (corners == 6)
      {
        pc[1] = v * (1 - u), collapse = 1 - u;
      }
      cell->InterpolateDerivs(pc, derivs.data());
      double j[3][3] = {};
      for (vtkIdType node = 0; node < n; ++node)
      {
        double x[3];
        cell->GetPoints()->GetPoint(node, x);
        for (int r = 0; r < 3; ++r)
        {
          for (int d = 0; d < 3; ++d)
          {
            j[r][d] += x[r] * derivs[static_cast<std::size_t>(d * n + node)];
          }
        }
      }
      const double det = j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) -
        j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) + j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
      volume += std::abs(det) * collapse * weight;
    }
  }
  return volume;
}

/// No two points at the same coordinates.
void ExpectDistinctPoints(vtkDataSet* mesh)
{
  std::set<std::array<double, 3>> seen;
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    std::array<double, 3> x;
    mesh->GetPoint(p, x.data());
    seen.insert(x);
  }
  EXPECT_EQ(static_cast<vtkIdType>(seen.size()), mesh->GetNumberOfPoints()) << "coincident points";
}

/// Conforming after the tet split: no face of three tets, and the boundary the subdivision of the
/// input's boundary must have (a crack would add boundary triangles).
void ExpectConforming(vtkDataSet* input, vtkUnstructuredGrid* subdivided, int level)
{
  vtkSmartPointer<vtkUnstructuredGrid> tets = Tetrahedralize(subdivided);
  const uvtest::FaceCensus census = uvtest::CountFaces(tets);
  EXPECT_EQ(census.Overshared, 0);
  EXPECT_EQ(census.Boundary, uvtest::ExpectedSubdividedBoundaryTriangles(input, level));
  EXPECT_EQ(4 * tets->GetNumberOfCells(), 2 * census.Interior + census.Boundary);
}

void Bend(double* x)
{
  const double y = x[1], z = x[2];
  x[0] += 0.06 * std::sin(2.0 * y + z);
  x[1] += 0.05 * std::sin(1.5 * x[0]) * z;
  x[2] += 0.04 * std::cos(x[0] + y);
}

vtkSmartPointer<vtkUnstructuredGrid> Load(const std::string& path)
{
  if (path.size() > 4 && path.substr(path.size() - 4) == ".vtu")
  {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    return reader->GetOutput();
  }
  vtkNew<vtkUnstructuredGridReader> reader;
  reader->ReadAllScalarsOn();
  reader->ReadAllVectorsOn();
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}
} // namespace

TEST(HigherOrderSubdivision, QuadraticFieldErrorFallsFourfoldPerDoubling)
{
  vtkSmartPointer<vtkUnstructuredGrid> tet = CurvedQuadraticTet();
  double previous = 0.0, previousReported = 0.0;
  for (int level : { 2, 4, 8 })
  {
    SCOPED_TRACE(level);
    vtkSmartPointer<vtkHigherOrderSubdivision> filter;
    vtkSmartPointer<vtkUnstructuredGrid> out = Subdivide(tet, level, nullptr, &filter);
    EXPECT_EQ(out->GetNumberOfCells(), level * level * level);
    EXPECT_EQ(filter->GetChosenLevel(), level);
    const double error = RmsFieldError(tet, out, 3000);
    if (previous > 0.0)
    {
      EXPECT_GT(previous / error, 3.0);
      EXPECT_LT(previous / error, 5.5);
      EXPECT_GT(previousReported / filter->GetFieldError(), 3.0);
      EXPECT_LT(previousReported / filter->GetFieldError(), 5.5);
    }
    previous = error;
    previousReported = filter->GetFieldError();
    EXPECT_GT(filter->GetChordError(), 0.0);
  }
}

TEST(HigherOrderSubdivision, StraightTetWithALinearFieldIsItsCornerTet)
{
  vtkSmartPointer<vtkUnstructuredGrid> tet = CurvedQuadraticTet();
  const double corners[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
  vtkDataArray* f = tet->GetPointData()->GetArray("f");
  for (int n = 0; n < 10; ++n)
  {
    double x[3];
    for (int d = 0; d < 3; ++d)
    {
      x[d] = n < 4 ? corners[n][d] : 0.5 * (corners[edges[n - 4][0]][d] + corners[edges[n - 4][1]][d]);
    }
    tet->GetPoints()->SetPoint(n, x);
    f->SetTuple1(n, 2.0 * x[0] - x[1] + 3.0 * x[2] + 1.0);
  }
  vtkSmartPointer<vtkHigherOrderSubdivision> filter;
  uvtest::EventCounter* events = nullptr;
  vtkSmartPointer<vtkUnstructuredGrid> out = Subdivide(tet, 0, &events, &filter);
  EXPECT_EQ(events->Errors + events->Warnings, 0);
  EXPECT_EQ(filter->GetChosenLevel(), 1);
  EXPECT_LT(filter->GetFieldError(), 1e-12);
  EXPECT_LT(filter->GetChordError(), 1e-12);
  ASSERT_EQ(out->GetNumberOfCells(), 1);
  EXPECT_EQ(out->GetCellType(0), VTK_TETRA);
  EXPECT_EQ(out->GetNumberOfPoints(), 10);
  vtkNew<vtkIdList> ids;
  out->GetCellPoints(0, ids);
  for (vtkIdType v = 0; v < 4; ++v)
  {
    EXPECT_EQ(ids->GetId(v), v);
  }
}

TEST(HigherOrderSubdivision, TwoTetsSharingAFaceConform)
{
  // The second tet lists the shared face {1, 2, 3} in another order, its nodes on that face shared.
  vtkSmartPointer<vtkUnstructuredGrid> grid = CurvedQuadraticTet();
  const double apex[3] = { 0.8, 0.8, 0.8 };
  const double mids[3][3] = { { 0.42, 0.38, 0.93 }, { 0.92, 0.42, 0.38 }, { 0.38, 0.93, 0.42 } };
  vtkPoints* points = grid->GetPoints();
  const vtkIdType a = points->InsertNextPoint(apex);
  const vtkIdType m3 = points->InsertNextPoint(mids[0]), m1 = points->InsertNextPoint(mids[1]),
                  m2 = points->InsertNextPoint(mids[2]);
  vtkDataArray* f = grid->GetPointData()->GetArray("f");
  for (vtkIdType p = f->GetNumberOfTuples(); p < points->GetNumberOfPoints(); ++p)
  {
    f->InsertNextTuple1(Quadratic(points->GetPoint(p)));
  }
  // Corners (3, 1, 2, a): edges 3-1 (node 8), 1-2 (5), 2-3 (9), 3-a, 1-a, 2-a.
  const vtkIdType second[10] = { 3, 1, 2, a, 8, 5, 9, m3, m1, m2 };
  grid->InsertNextCell(VTK_QUADRATIC_TETRA, 10, second);
  for (int level : { 1, 2, 3, 5 })
  {
    SCOPED_TRACE(level);
    vtkSmartPointer<vtkUnstructuredGrid> out = Subdivide(grid, level);
    EXPECT_EQ(out->GetNumberOfCells(), 2 * level * level * level);
    const std::size_t perTet = static_cast<std::size_t>((level + 1) * (level + 2) * (level + 3) / 6);
    const std::size_t onFace = static_cast<std::size_t>((level + 1) * (level + 2) / 2);
    std::set<vtkIdType> used;
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
    {
      out->GetCellPoints(c, ids);
      used.insert(ids->GetPointer(0), ids->GetPointer(0) + ids->GetNumberOfIds());
    }
    EXPECT_EQ(used.size(), 2 * perTet - onFace);
    ExpectConforming(grid, out, level);
    ExpectDistinctPoints(out);
  }
}

TEST(HigherOrderSubdivision, CurvedMixedCellsConformAcrossFamilies)
{
  const std::map<int, int> quadratic = { { VTK_HEXAHEDRON, VTK_TRIQUADRATIC_HEXAHEDRON },
    { VTK_WEDGE, VTK_BIQUADRATIC_QUADRATIC_WEDGE }, { VTK_PYRAMID, VTK_TRIQUADRATIC_PYRAMID },
    { VTK_TETRA, VTK_QUADRATIC_TETRA } };
  const std::map<int, int> serendipity = { { VTK_HEXAHEDRON, VTK_QUADRATIC_HEXAHEDRON },
    { VTK_WEDGE, VTK_QUADRATIC_WEDGE }, { VTK_PYRAMID, VTK_QUADRATIC_PYRAMID },
    { VTK_TETRA, VTK_QUADRATIC_TETRA } };
  for (const auto* types : { &quadratic, &serendipity })
  {
    vtkSmartPointer<vtkUnstructuredGrid> mixed = uvtest::Elevate(uvtest::MixedMesh(), *types, Bend);
    for (int level : { 1, 2, 3, 4 })
    {
      SCOPED_TRACE(level);
      uvtest::EventCounter* events = nullptr;
      vtkSmartPointer<vtkUnstructuredGrid> out = Subdivide(mixed, level, &events);
      EXPECT_EQ(events->Errors, 0);
      EXPECT_EQ(events->Warnings, 1);
      EXPECT_NE(events->LastMessage.find("Dropped 2 cells"), std::string::npos) << events->LastMessage;
      const vtkIdType cube = level * level * level;
      EXPECT_EQ(out->GetNumberOfCells(), 3 * cube + level * (4 * level * level - 1) / 3);
      ExpectConforming(mixed, out, level);
      ExpectDistinctPoints(out);
      // Every child names its input cell and carries its cell data; every point has every array.
      vtkDataArray* original = out->GetCellData()->GetArray("vtkOriginalCellIds");
      vtkDataArray* label = out->GetCellData()->GetArray("label");
      ASSERT_TRUE(original && label);
      for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
      {
        EXPECT_EQ(label->GetTuple1(c), 10 + original->GetTuple1(c));
      }
      vtkDataArray* rank = out->GetPointData()->GetArray("rank");
      ASSERT_TRUE(rank && vtkIntArray::SafeDownCast(rank));
      EXPECT_EQ(rank->GetNumberOfTuples(), out->GetNumberOfPoints());
      EXPECT_EQ(out->GetPointData()->GetArray("f")->GetNumberOfTuples(), out->GetNumberOfPoints());
      for (vtkIdType p = 0; p < mixed->GetNumberOfPoints(); ++p)
      {
        EXPECT_EQ(rank->GetTuple1(p), p); // the input's points first, unchanged
      }
    }
  }
}

TEST(HigherOrderSubdivision, StraightPyramidsKeepTheirVolumeAndNodes)
{
  // A straight pyramid's lattice is its own: the volume is exact at every level, and at L = 2 the
  // triquadratic pyramid's nodes are the whole lattice (VTK 9.1 parametrises it differently from
  // vtkQuadraticPyramid, which lacks the base centre).
  vtkNew<vtkUnstructuredGrid> linear;
  vtkNew<vtkPoints> points;
  const double xyz[5][3] = { { 0, 0, 0 }, { 2, 0, 0 }, { 2, 1, 0 }, { 0, 1, 0 }, { 0.7, 0.4, 1.5 } };
  for (const auto& p : xyz)
  {
    points->InsertNextPoint(p);
  }
  linear->SetPoints(points);
  const vtkIdType ids[5] = { 0, 1, 2, 3, 4 };
  linear->InsertNextCell(VTK_PYRAMID, 5, ids);
  for (int type : { VTK_QUADRATIC_PYRAMID, VTK_TRIQUADRATIC_PYRAMID })
  {
    SCOPED_TRACE(type);
    vtkSmartPointer<vtkUnstructuredGrid> pyramid =
      uvtest::Elevate(linear, { { VTK_PYRAMID, type } }, [](double*) {});
    for (int level : { 1, 2, 3, 5 })
    {
      vtkSmartPointer<vtkUnstructuredGrid> out = Subdivide(pyramid, level);
      EXPECT_NEAR(LinearVolume(out), 1.0, 1e-12) << "level " << level;
      if (level == 2)
      {
        EXPECT_EQ(out->GetNumberOfPoints(), pyramid->GetNumberOfPoints() + (type == VTK_QUADRATIC_PYRAMID ? 1 : 0));
      }
    }
  }
}

TEST(HigherOrderSubdivision, LagrangeTetMatchesTheQuadraticTet)
{
  vtkSmartPointer<vtkUnstructuredGrid> quadratic = CurvedQuadraticTet();
  vtkNew<vtkUnstructuredGrid> lagrange;
  lagrange->SetPoints(quadratic->GetPoints());
  lagrange->GetPointData()->ShallowCopy(quadratic->GetPointData());
  const vtkIdType ids[10] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9 };
  lagrange->InsertNextCell(VTK_LAGRANGE_TETRAHEDRON, 10, ids);
  vtkSmartPointer<vtkUnstructuredGrid> a = Subdivide(quadratic, 3), b = Subdivide(lagrange, 3);
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  ASSERT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells());
  for (vtkIdType p = 0; p < a->GetNumberOfPoints(); ++p)
  {
    for (int d = 0; d < 3; ++d)
    {
      EXPECT_NEAR(a->GetPoint(p)[d], b->GetPoint(p)[d], 1e-12);
    }
  }
}

TEST(HigherOrderSubdivision, AutomaticLevelMeetsTheTolerances)
{
  vtkSmartPointer<vtkUnstructuredGrid> tet = CurvedQuadraticTet();
  vtkNew<vtkHigherOrderSubdivision> filter;
  uvtest::EventCounter* events = uvtest::WatchEvents(filter);
  filter->SetInputData(tet);
  filter->SetFieldTolerance(0.01);
  filter->SetChordTolerance(0.01);
  filter->SetMaximumLevel(8);
  filter->Update();
  const int level = filter->GetChosenLevel();
  EXPECT_EQ(events->Warnings, 0);
  EXPECT_LE(filter->GetFieldError(), 0.01);
  EXPECT_LE(filter->GetChordError(), 0.01);
  ASSERT_GT(level, 1);
  filter->SetLevel(level - 1); // the level below misses a tolerance
  filter->Update();
  EXPECT_TRUE(filter->GetFieldError() > 0.01 || filter->GetChordError() > 0.01);
  // Unreachable tolerances: the maximum level, with one warning.
  filter->SetLevel(0);
  filter->SetFieldTolerance(1e-9);
  filter->SetMaximumLevel(3);
  filter->Update();
  EXPECT_EQ(filter->GetChosenLevel(), 3);
  EXPECT_EQ(events->Warnings, 1);
  EXPECT_NE(events->LastMessage.find("maximum level 3"), std::string::npos) << events->LastMessage;
  // Only the named array counts: a wild second array is ignored.
  vtkNew<vtkDoubleArray> wild;
  wild->SetName("wild");
  for (vtkIdType p = 0; p < tet->GetNumberOfPoints(); ++p)
  {
    wild->InsertNextValue(p % 2 ? 1.0 : -1.0);
  }
  tet->GetPointData()->AddArray(wild);
  filter->SetFieldTolerance(0.01);
  filter->SetMaximumLevel(8);
  filter->SetFieldArrayName("f");
  filter->Update();
  EXPECT_EQ(filter->GetChosenLevel(), level);
  filter->SetFieldArrayName(nullptr);
  filter->Update();
  EXPECT_GT(filter->GetChosenLevel(), level);
}

TEST(HigherOrderSubdivision, EmptyLowerDimensionalAndUnsupportedInput)
{
  vtkNew<vtkUnstructuredGrid> empty;
  uvtest::EventCounter* events = nullptr;
  vtkSmartPointer<vtkHigherOrderSubdivision> filter;
  vtkSmartPointer<vtkUnstructuredGrid> out = Subdivide(empty, 0, &events, &filter);
  EXPECT_EQ(out->GetNumberOfCells(), 0);
  EXPECT_EQ(events->Errors + events->Warnings, 0);
  EXPECT_EQ(filter->GetChosenLevel(), 0);

  // Only surfaces: a quadratic triangle and a quad, dropped with one warning.
  vtkNew<vtkUnstructuredGrid> surfaces;
  vtkNew<vtkPoints> points;
  for (int p = 0; p < 6; ++p)
  {
    points->InsertNextPoint(p % 3, p / 3, 0.0);
  }
  surfaces->SetPoints(points);
  const vtkIdType triangle[6] = { 0, 1, 3, 4, 2, 5 }, quad[4] = { 0, 1, 4, 3 };
  surfaces->InsertNextCell(VTK_QUADRATIC_TRIANGLE, 6, triangle);
  surfaces->InsertNextCell(VTK_QUAD, 4, quad);
  out = Subdivide(surfaces, 0, &events);
  EXPECT_EQ(out->GetNumberOfCells(), 0);
  EXPECT_EQ(events->Warnings, 1);
  EXPECT_NE(events->LastMessage.find("Dropped 2 cells"), std::string::npos) << events->LastMessage;

  // Linear cells only: passed through, level 0.
  vtkSmartPointer<vtkUnstructuredGrid> mixed = uvtest::MixedMesh();
  out = Subdivide(mixed, 0, &events, &filter);
  EXPECT_EQ(filter->GetChosenLevel(), 0);
  EXPECT_EQ(out->GetNumberOfCells(), 4);
  EXPECT_EQ(out->GetNumberOfPoints(), mixed->GetNumberOfPoints());

  // No VTK 9.1 class interpolates a Lagrange pyramid.
  vtkNew<vtkUnstructuredGrid> lagrange;
  lagrange->SetPoints(points);
  const vtkIdType pyramid[5] = { 0, 1, 4, 3, 5 };
  lagrange->InsertNextCell(VTK_LAGRANGE_PYRAMID, 5, pyramid);
  out = Subdivide(lagrange, 0, &events);
  EXPECT_EQ(events->Errors, 1);
  EXPECT_EQ(out->GetNumberOfCells(), 0);
}

TEST(HigherOrderSubdivision, SharedHigherOrderMeshes)
{
  const char* files[] = { "quadratic/CylinderQuadratic.vtk", "quadratic/QuadraticTetra.vtu",
    "quadratic/TriQuadraticHexahedron.vtu", "mfem_small/fichera-mixed-p2.vtk" };
  int found = 0;
  for (const char* file : files)
  {
    const std::string path = uvtest::SharedData(file);
    if (path.empty())
    {
      continue;
    }
    ++found;
    SCOPED_TRACE(file);
    vtkSmartPointer<vtkUnstructuredGrid> mesh = Load(path);
    ASSERT_GT(mesh->GetNumberOfCells(), 0);
    const double volume = IsoparametricVolume(mesh);
    double previousGap = VTK_DOUBLE_MAX;
    for (int level : { 1, 2, 4 })
    {
      SCOPED_TRACE(level);
      vtkSmartPointer<vtkUnstructuredGrid> out = Subdivide(mesh, level);
      EXPECT_EQ(out->GetNumberOfCells(), level * level * level * mesh->GetNumberOfCells());
      ExpectDistinctPoints(out);
      ExpectConforming(mesh, out, level);
      const double gap = std::abs(LinearVolume(out) - volume) / volume;
      EXPECT_LE(gap, previousGap * 1.0001 + 1e-12);
      previousGap = gap;
      if (mesh->GetCellData()->GetArray("material"))
      {
        EXPECT_NE(out->GetCellData()->GetArray("material"), nullptr);
      }
    }
    EXPECT_LT(previousGap, 2e-3);
  }
  if (found == 0)
  {
    GTEST_SKIP() << "../shared/data is absent";
  }
}
