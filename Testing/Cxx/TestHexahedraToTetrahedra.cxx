// vtkHexahedraToTetrahedra on structured, unstructured, mixed and real meshes.
#include "uvTestMeshChecks.h"
#include "vtkAnalyticMeshSource.h"
#include "vtkHexahedraToTetrahedra.h"

#include "vtkAppendFilter.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellTypes.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkDoubleArray.h"
#include "vtkExodusIIReader.h"
#include "vtkGenericCell.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRectilinearGrid.h"
#include "vtkStructuredGrid.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredVolumeCompatibility.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkXMLStructuredGridReader.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>

namespace
{
vtkSmartPointer<vtkUnstructuredGrid> Split(vtkDataSet* input, int mode = vtkHexahedraToTetrahedra::SIX_TETRAHEDRA,
  uvtest::EventCounter** counter = nullptr)
{
  auto filter = vtkSmartPointer<vtkHexahedraToTetrahedra>::New();
  uvtest::EventCounter* watched = uvtest::WatchEvents(filter);
  if (counter)
  {
    *counter = watched;
  }
  filter->SetSplitMode(mode);
  filter->SetInputData(input);
  filter->Update();
  return filter->GetOutput();
}

/// True when two corners of the input cell coincide (a collapsed edge, as real grids have).
bool HasCoincidentCorners(vtkDataSet* input, vtkIdType cell)
{
  vtkNew<vtkIdList> ids;
  input->GetCellPoints(cell, ids);
  for (vtkIdType a = 0; a < ids->GetNumberOfIds(); ++a)
  {
    for (vtkIdType b = a + 1; b < ids->GetNumberOfIds(); ++b)
    {
      double p[3], q[3];
      input->GetPoint(ids->GetId(a), p);
      input->GetPoint(ids->GetId(b), q);
      if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2])
      {
        return true;
      }
    }
  }
  return false;
}

/// Conforming, positive, the expected boundary, and the expected volume (when given). A flat tet is
/// accepted only where its input cell has coincident corners.
void ExpectValidSplit(vtkDataSet* input, vtkUnstructuredGrid* tets, double expectedVolume = -1.0,
  double relativeTolerance = 1e-12)
{
  ASSERT_GT(tets->GetNumberOfCells(), 0);
  EXPECT_EQ(tets->GetCellType(0), VTK_TETRA);
  const uvtest::FaceCensus census = uvtest::CountFaces(tets);
  EXPECT_EQ(census.Overshared, 0);
  EXPECT_EQ(census.Boundary, uvtest::ExpectedBoundaryTriangles(input))
    << "boundary triangles differ from the input's split boundary: a crack or T-junction inside";
  EXPECT_EQ(4 * tets->GetNumberOfCells(), 2 * census.Interior + census.Boundary);
  const std::vector<double> volumes = uvtest::TetVolumes(tets);
  const double smallest = *std::min_element(volumes.begin(), volumes.end());
  EXPECT_GE(smallest, 0.0) << "a tet is inverted";
  vtkDataArray* original = tets->GetCellData()->GetArray("vtkOriginalCellIds");
  int flatFromValidCells = 0;
  for (std::size_t t = 0; t < volumes.size(); ++t)
  {
    if (volumes[t] <= 0.0 &&
      !HasCoincidentCorners(input, static_cast<vtkIdType>(original->GetTuple1(static_cast<vtkIdType>(t)))))
    {
      ++flatFromValidCells;
    }
  }
  EXPECT_EQ(flatFromValidCells, 0) << "flat tets from cells without coincident corners";
  if (expectedVolume > 0.0)
  {
    const double total = std::accumulate(volumes.begin(), volumes.end(), 0.0);
    EXPECT_NEAR(total, expectedVolume, relativeTolerance * expectedVolume);
  }
}

vtkSmartPointer<vtkImageData> Image(int nx, int ny, int nz)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(3, 3 + nx, -2, -2 + ny, 5, 5 + nz); // a non-zero origin extent on purpose
  image->SetSpacing(0.5, 0.25, 2.0);
  image->SetOrigin(1.0, -3.0, 7.0);
  vtkNew<vtkDoubleArray> values;
  values->SetName("values");
  values->SetNumberOfValues(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    values->SetValue(i, 0.5 * i);
  }
  image->GetPointData()->SetScalars(values);
  vtkNew<vtkIntArray> cellIds;
  cellIds->SetName("cellLabel");
  cellIds->SetNumberOfValues(image->GetNumberOfCells());
  for (vtkIdType c = 0; c < image->GetNumberOfCells(); ++c)
  {
    cellIds->SetValue(c, static_cast<int>(3 * c + 1));
  }
  image->GetCellData()->AddArray(cellIds);
  return image;
}

vtkSmartPointer<vtkUnstructuredGrid> Analytic(int resolution, int distortion, int cellKind)
{
  vtkNew<vtkAnalyticMeshSource> source;
  source->SetResolution(resolution, resolution + 1, resolution + 2);
  source->SetDistortion(distortion);
  source->SetCellKind(cellKind);
  source->Update();
  return source->GetOutput();
}

/// Each input cell's volume by the divergence theorem over its own faces (vtkCell::GetFace), summed:
/// independent of the split. Valid for cells with planar faces.
double FaceVolume(vtkDataSet* mesh)
{
  double total = 0.0;
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCell(c, cell);
    double six = 0.0;
    for (int f = 0; f < cell->GetNumberOfFaces(); ++f)
    {
      vtkIdList* ids = cell->GetFace(f)->GetPointIds();
      double p[3][3];
      mesh->GetPoint(ids->GetId(0), p[0]);
      for (vtkIdType i = 1; i + 1 < ids->GetNumberOfIds(); ++i)
      {
        mesh->GetPoint(ids->GetId(i), p[1]);
        mesh->GetPoint(ids->GetId(i + 1), p[2]);
        six += p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
          p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) + p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
      }
    }
    total += std::abs(six) / 6.0;
  }
  return total;
}

/// `mesh` with the cells picked by `convert` rewritten as VTK_POLYHEDRON from their faces
/// (vtkCell::GetFace), every other face reversed when `flipFaces` (the split must not care); points,
/// point data and cell data shared.
template <typename Pick>
vtkSmartPointer<vtkUnstructuredGrid> AsPolyhedra(vtkUnstructuredGrid* mesh, Pick convert, bool flipFaces = false)
{
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->SetPoints(mesh->GetPoints());
  vtkNew<vtkGenericCell> cell;
  vtkNew<vtkIdList> stream;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCell(c, cell);
    if (!convert(c))
    {
      out->InsertNextCell(cell->GetCellType(), cell->GetPointIds());
      continue;
    }
    stream->Reset();
    stream->InsertNextId(cell->GetNumberOfFaces());
    for (int f = 0; f < cell->GetNumberOfFaces(); ++f)
    {
      vtkIdList* ids = cell->GetFace(f)->GetPointIds();
      stream->InsertNextId(ids->GetNumberOfIds());
      for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
      {
        const vtkIdType at = flipFaces && f % 2 ? ids->GetNumberOfIds() - 1 - i : i;
        stream->InsertNextId(ids->GetId(at));
      }
    }
    out->InsertNextCell(VTK_POLYHEDRON, stream);
  }
  out->GetPointData()->ShallowCopy(mesh->GetPointData());
  out->GetCellData()->ShallowCopy(mesh->GetCellData());
  return out;
}

/// Each tet as its sorted point ids -> its vtkOriginalCellIds entry.
std::map<std::vector<vtkIdType>, vtkIdType> TetKeys(vtkUnstructuredGrid* tets)
{
  std::map<std::vector<vtkIdType>, vtkIdType> keys;
  vtkDataArray* original = tets->GetCellData()->GetArray("vtkOriginalCellIds");
  vtkNew<vtkIdList> ids;
  for (vtkIdType t = 0; t < tets->GetNumberOfCells(); ++t)
  {
    tets->GetCellPoints(t, ids);
    std::vector<vtkIdType> key(ids->GetPointer(0), ids->GetPointer(0) + 4);
    std::sort(key.begin(), key.end());
    keys[key] = static_cast<vtkIdType>(original->GetTuple1(t));
  }
  return keys;
}

/// Same points, point data, tets (as id sets, with their input cells) and cell data.
void ExpectSameTets(vtkUnstructuredGrid* expected, vtkUnstructuredGrid* actual)
{
  ASSERT_EQ(actual->GetNumberOfPoints(), expected->GetNumberOfPoints());
  ASSERT_EQ(actual->GetNumberOfCells(), expected->GetNumberOfCells());
  EXPECT_EQ(TetKeys(actual), TetKeys(expected));
  for (vtkIdType i = 0; i < expected->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    expected->GetPoint(i, p);
    actual->GetPoint(i, q);
    ASSERT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) << "point " << i;
  }
  vtkPointData* expectedData = expected->GetPointData();
  ASSERT_EQ(actual->GetPointData()->GetNumberOfArrays(), expectedData->GetNumberOfArrays());
  for (int a = 0; a < expectedData->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* e = expectedData->GetArray(a);
    vtkDataArray* g = actual->GetPointData()->GetArray(e->GetName());
    ASSERT_TRUE(g && g->GetNumberOfTuples() == e->GetNumberOfTuples()) << e->GetName();
    for (vtkIdType i = 0; i < e->GetNumberOfTuples(); ++i)
    {
      ASSERT_EQ(g->GetTuple1(i), e->GetTuple1(i));
    }
  }
}

/// A column of `levels` regular n-gonal prisms (unit circumradius, unit height) sharing their
/// n-gons, point ids shuffled so each cell's smallest vertex falls anywhere, with a point scalar.
vtkSmartPointer<vtkUnstructuredGrid> PrismColumn(int n, int levels, unsigned seed)
{
  const int numPoints = n * (levels + 1);
  std::vector<vtkIdType> id(numPoints);
  std::iota(id.begin(), id.end(), 0);
  std::mt19937 random(seed);
  std::shuffle(id.begin(), id.end(), random);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numPoints);
  vtkNew<vtkDoubleArray> values;
  values->SetName("values");
  values->SetNumberOfValues(numPoints);
  for (int level = 0; level <= levels; ++level)
  {
    for (int i = 0; i < n; ++i)
    {
      const double angle = 2.0 * std::acos(-1.0) * i / n;
      const vtkIdType at = id[level * n + i];
      points->SetPoint(at, std::cos(angle), std::sin(angle), level);
      values->SetValue(at, std::cos(angle) + 2.0 * level);
    }
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->GetPointData()->SetScalars(values);
  for (int level = 0; level < levels; ++level)
  {
    std::vector<vtkIdType> corners;
    for (int i = 0; i < 2 * n; ++i)
    {
      corners.push_back(id[level * n + i]);
    }
    grid->InsertNextCell(n == 5 ? VTK_PENTAGONAL_PRISM : VTK_HEXAGONAL_PRISM, 2 * n, corners.data());
  }
  return grid;
}

double RegularPolygonArea(int n)
{
  return 0.5 * n * std::sin(2.0 * std::acos(-1.0) / n);
}

/// An L-shaped polyhedron (outline (0,0) (3,0) (3,w) (w,w) (w,3) (0,3), z in [0, 1]; top and bottom
/// each two convex quads) and a hexahedron on its x = 3 face, with point and cell arrays.
vtkSmartPointer<vtkUnstructuredGrid> LShapeAndHexahedron(double w)
{
  const double outline[6][2] = { { 0, 0 }, { 3, 0 }, { 3, w }, { w, w }, { w, 3 }, { 0, 3 } };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> values;
  values->SetName("values");
  vtkNew<vtkIntArray> labels;
  labels->SetName("pointLabel");
  for (double z : { 0.0, 1.0 })
  {
    for (const auto& xy : outline)
    {
      points->InsertNextPoint(xy[0], xy[1], z);
    }
  }
  points->InsertNextPoint(4, 0, 0); // 12..15: the hexahedron's far face at x = 4
  points->InsertNextPoint(4, w, 0);
  points->InsertNextPoint(4, w, 1);
  points->InsertNextPoint(4, 0, 1);
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    values->InsertNextValue(p[0] + 10.0 * p[1] + 100.0 * p[2]);
    labels->InsertNextValue(static_cast<int>(i));
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->GetPointData()->SetScalars(values);
  grid->GetPointData()->AddArray(labels);
  std::vector<std::vector<vtkIdType>> faces = { { 0, 3, 2, 1 }, { 0, 5, 4, 3 }, { 6, 7, 8, 9 }, { 6, 9, 10, 11 } };
  for (vtkIdType i = 0; i < 6; ++i)
  {
    faces.push_back({ i, (i + 1) % 6, 6 + (i + 1) % 6, 6 + i });
  }
  vtkNew<vtkIdList> stream;
  stream->InsertNextId(static_cast<vtkIdType>(faces.size()));
  for (const auto& face : faces)
  {
    stream->InsertNextId(static_cast<vtkIdType>(face.size()));
    for (vtkIdType id : face)
    {
      stream->InsertNextId(id);
    }
  }
  grid->InsertNextCell(VTK_POLYHEDRON, stream);
  const vtkIdType hexahedron[8] = { 1, 12, 13, 2, 7, 15, 14, 8 };
  grid->InsertNextCell(VTK_HEXAHEDRON, 8, hexahedron);
  vtkNew<vtkIntArray> cellLabel;
  cellLabel->SetName("cellLabel");
  cellLabel->InsertNextValue(70);
  cellLabel->InsertNextValue(71);
  grid->GetCellData()->AddArray(cellLabel);
  return grid;
}

} // namespace

TEST(HexahedraToTetrahedra, ImageDataSixAndFive)
{
  vtkSmartPointer<vtkImageData> image = Image(4, 5, 3);
  const double volume = (4 * 0.5) * (5 * 0.25) * (3 * 2.0);
  for (int mode : { vtkHexahedraToTetrahedra::SIX_TETRAHEDRA, vtkHexahedraToTetrahedra::FIVE_TETRAHEDRA })
  {
    uvtest::EventCounter* events = nullptr;
    vtkSmartPointer<vtkUnstructuredGrid> tets = Split(image, mode, &events);
    const int perCell = mode == vtkHexahedraToTetrahedra::FIVE_TETRAHEDRA ? 5 : 6;
    EXPECT_EQ(tets->GetNumberOfCells(), perCell * image->GetNumberOfCells());
    EXPECT_EQ(events->Errors + events->Warnings, 0);
    ExpectValidSplit(image, tets, volume);
    // Point data passes through, cell data goes to every child.
    EXPECT_EQ(tets->GetPointData()->GetScalars()->GetTuple1(17), 0.5 * 17);
    auto original = vtkIdTypeArray::SafeDownCast(tets->GetCellData()->GetArray("vtkOriginalCellIds"));
    auto label = tets->GetCellData()->GetArray("cellLabel");
    ASSERT_TRUE(original && label);
    for (vtkIdType t = 0; t < tets->GetNumberOfCells(); ++t)
    {
      ASSERT_EQ(original->GetValue(t), t / perCell);
      ASSERT_EQ(label->GetTuple1(t), 3 * (t / perCell) + 1);
    }
  }
}

TEST(HexahedraToTetrahedra, MirroredImageData)
{
  // Negative spacing mirrors every voxel; one sign test must flip them all.
  vtkSmartPointer<vtkImageData> image = Image(3, 4, 2);
  image->SetSpacing(-0.5, 0.25, -2.0);
  for (int mode : { vtkHexahedraToTetrahedra::SIX_TETRAHEDRA, vtkHexahedraToTetrahedra::FIVE_TETRAHEDRA })
  {
    ExpectValidSplit(image, Split(image, mode), (3 * 0.5) * (4 * 0.25) * (2 * 2.0));
  }
  image->SetSpacing(-0.5, 0.25, 2.0);
  ExpectValidSplit(image, Split(image), (3 * 0.5) * (4 * 0.25) * (2 * 2.0));
}

TEST(HexahedraToTetrahedra, RectilinearAndLeftHandedStructuredGrids)
{
  vtkNew<vtkRectilinearGrid> rectilinear;
  rectilinear->SetDimensions(4, 3, 5);
  const double xs[4] = { 0, 0.1, 0.5, 2 }, ys[3] = { -1, 0, 3 }, zs[5] = { 0, 1, 2, 3.5, 4 };
  vtkNew<vtkDoubleArray> x, y, z;
  for (double v : xs) x->InsertNextValue(v);
  for (double v : ys) y->InsertNextValue(v);
  for (double v : zs) z->InsertNextValue(v);
  rectilinear->SetXCoordinates(x);
  rectilinear->SetYCoordinates(y);
  rectilinear->SetZCoordinates(z);
  ExpectValidSplit(rectilinear, Split(rectilinear, vtkHexahedraToTetrahedra::FIVE_TETRAHEDRA), 2.0 * 4.0 * 4.0);
  ExpectValidSplit(rectilinear, Split(rectilinear), 2.0 * 4.0 * 4.0);

  // A structured grid whose i axis runs along -x: every hexahedron is mirrored (left-handed).
  vtkNew<vtkStructuredGrid> mirrored;
  mirrored->SetDimensions(3, 3, 3);
  vtkNew<vtkPoints> points;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        points->InsertNextPoint(-i, j, k);
  mirrored->SetPoints(points);
  for (int mode : { vtkHexahedraToTetrahedra::SIX_TETRAHEDRA, vtkHexahedraToTetrahedra::FIVE_TETRAHEDRA })
  {
    ExpectValidSplit(mirrored, Split(mirrored, mode), 8.0);
  }
}

TEST(HexahedraToTetrahedra, UnstructuredGeneratedMeshes)
{
  // Planar faces (no distortion, a 45 degree rotation): the volume is exact.
  for (int distortion : { vtkAnalyticMeshSource::NO_DISTORTION, vtkAnalyticMeshSource::ROTATE_45 })
  {
    vtkSmartPointer<vtkUnstructuredGrid> hexes = Analytic(5, distortion, vtkAnalyticMeshSource::HEXAHEDRA);
    vtkSmartPointer<vtkUnstructuredGrid> tets = Split(hexes);
    EXPECT_EQ(tets->GetNumberOfCells(), 6 * hexes->GetNumberOfCells());
    ExpectValidSplit(hexes, tets, 8.0);
  }
  // Curved faces (twist, jitter): conformity and orientation; the volume depends on the diagonals.
  for (int distortion : { vtkAnalyticMeshSource::TWIST, vtkAnalyticMeshSource::JITTER })
  {
    vtkSmartPointer<vtkUnstructuredGrid> hexes = Analytic(6, distortion, vtkAnalyticMeshSource::HEXAHEDRA);
    ExpectValidSplit(hexes, Split(hexes));
  }
  // Five on an unstructured input: a warning, then six.
  uvtest::EventCounter* events = nullptr;
  vtkSmartPointer<vtkUnstructuredGrid> hexes = Analytic(3, 0, vtkAnalyticMeshSource::HEXAHEDRA);
  vtkSmartPointer<vtkUnstructuredGrid> tets = Split(hexes, vtkHexahedraToTetrahedra::FIVE_TETRAHEDRA, &events);
  EXPECT_EQ(events->Warnings, 1);
  EXPECT_EQ(tets->GetNumberOfCells(), 6 * hexes->GetNumberOfCells());
}

TEST(HexahedraToTetrahedra, MixedCellsConformAndLowerDimensionalCellsAreDropped)
{
  vtkSmartPointer<vtkUnstructuredGrid> mixed = uvtest::MixedMesh();
  uvtest::EventCounter* events = nullptr;
  vtkSmartPointer<vtkUnstructuredGrid> tets = Split(mixed, vtkHexahedraToTetrahedra::SIX_TETRAHEDRA, &events);
  EXPECT_EQ(events->Errors, 0);
  EXPECT_EQ(events->Warnings, 1);
  EXPECT_NE(events->LastMessage.find("Dropped 2 cells"), std::string::npos) << events->LastMessage;
  EXPECT_EQ(tets->GetNumberOfCells(), 6 + 2 + 3 + 1);
  // hexahedron 1 + pyramid 1/3 + wedge 1/2 + tet (4,5,8,11) 1.25/6.
  ExpectValidSplit(mixed, tets, 1.0 + 1.0 / 3.0 + 0.5 + 1.25 / 6.0);
  auto label = tets->GetCellData()->GetArray("label");
  auto original = tets->GetCellData()->GetArray("vtkOriginalCellIds");
  for (vtkIdType t = 0; t < tets->GetNumberOfCells(); ++t)
  {
    EXPECT_EQ(label->GetTuple1(t), 10 + original->GetTuple1(t));
  }
  // The tet passes through with its own point order.
  const vtkIdType last = tets->GetNumberOfCells() - 1;
  vtkNew<vtkIdList> ids;
  tets->GetCellPoints(last, ids);
  EXPECT_EQ(ids->GetId(0), 4);
  EXPECT_EQ(ids->GetId(3), 11);
}

TEST(HexahedraToTetrahedra, EmptyAndUnsupportedInput)
{
  vtkNew<vtkUnstructuredGrid> empty;
  uvtest::EventCounter* events = nullptr;
  vtkSmartPointer<vtkUnstructuredGrid> out = Split(empty, vtkHexahedraToTetrahedra::SIX_TETRAHEDRA, &events);
  EXPECT_EQ(out->GetNumberOfCells(), 0);
  EXPECT_EQ(events->Errors + events->Warnings, 0);

  // No VTK 9.1 class interpolates a Lagrange pyramid: an error alone, and beside a quadratic tet the
  // subdivision's error, reported as ours.
  vtkNew<vtkUnstructuredGrid> lagrange;
  lagrange->SetPoints(uvtest::MixedMesh()->GetPoints());
  const vtkIdType pyramid[5] = { 4, 5, 6, 7, 8 };
  lagrange->InsertNextCell(VTK_LAGRANGE_PYRAMID, 5, pyramid);
  for (bool withQuadraticTet : { false, true })
  {
    if (withQuadraticTet)
    {
      const vtkIdType tet[10] = { 0, 1, 3, 4, 1, 2, 3, 5, 6, 7 }; // any nodes: the error comes first
      lagrange->InsertNextCell(VTK_QUADRATIC_TETRA, 10, tet);
    }
    out = Split(lagrange, vtkHexahedraToTetrahedra::SIX_TETRAHEDRA, &events);
    EXPECT_EQ(events->Errors, 1);
    EXPECT_NE(events->LastMessage.find("vtkLagrangePyramid"), std::string::npos) << events->LastMessage;
    EXPECT_EQ(events->LastMessage.find("vtkHigherOrderSubdivision ("), std::string::npos) << events->LastMessage;
    EXPECT_EQ(out->GetNumberOfCells(), 0);
  }
}

TEST(HexahedraToTetrahedra, HigherOrderCellsAreSubdividedFirst)
{
  // The mixed mesh made quadratic and curved; its quad and line are dropped with one warning.
  vtkSmartPointer<vtkUnstructuredGrid> quadratic = uvtest::Elevate(uvtest::MixedMesh(),
    { { VTK_HEXAHEDRON, VTK_TRIQUADRATIC_HEXAHEDRON }, { VTK_WEDGE, VTK_BIQUADRATIC_QUADRATIC_WEDGE },
      { VTK_PYRAMID, VTK_TRIQUADRATIC_PYRAMID }, { VTK_TETRA, VTK_QUADRATIC_TETRA } },
    [](double* x) { x[2] += 0.1 * std::sin(x[0] + x[1]); });
  for (int level : { 1, 3 })
  {
    SCOPED_TRACE(level);
    vtkNew<vtkHexahedraToTetrahedra> filter;
    uvtest::EventCounter* events = uvtest::WatchEvents(filter);
    filter->SetLevel(level);
    filter->SetInputData(quadratic);
    filter->Update();
    vtkUnstructuredGrid* tets = filter->GetOutput();
    EXPECT_EQ(events->Errors, 0);
    EXPECT_EQ(events->Warnings, 1);
    EXPECT_NE(events->LastMessage.find("Dropped 2 cells"), std::string::npos) << events->LastMessage;
    const uvtest::FaceCensus census = uvtest::CountFaces(tets);
    EXPECT_EQ(census.Overshared, 0);
    EXPECT_EQ(census.Boundary, uvtest::ExpectedSubdividedBoundaryTriangles(quadratic, level));
    const std::vector<double> volumes = uvtest::TetVolumes(tets);
    EXPECT_GT(*std::min_element(volumes.begin(), volumes.end()), 0.0);
    // vtkOriginalCellIds names the quadratic input's cells, whose data each tet carries.
    vtkDataArray* original = tets->GetCellData()->GetArray("vtkOriginalCellIds");
    vtkDataArray* label = tets->GetCellData()->GetArray("label");
    ASSERT_TRUE(original && label);
    std::set<vtkIdType> cells;
    for (vtkIdType t = 0; t < tets->GetNumberOfCells(); ++t)
    {
      cells.insert(static_cast<vtkIdType>(original->GetTuple1(t)));
      EXPECT_EQ(label->GetTuple1(t), 10 + original->GetTuple1(t));
    }
    EXPECT_EQ(cells, (std::set<vtkIdType>{ 0, 1, 2, 3 }));
    // Hexahedra give 6 tets, wedges 3, and the pyramid's sub-pyramids 2 beside its sub-tets.
    vtkIdType subPyramids = 0, subTets = 0;
    for (vtkIdType m = 1; m <= level; ++m)
    {
      subPyramids += m * m + (m - 1) * (m - 1);
      subTets += 2 * m * (m - 1);
    }
    const vtkIdType cube = level * level * level;
    EXPECT_EQ(tets->GetNumberOfCells(), 6 * cube + 3 * cube + cube + 2 * subPyramids + subTets);
  }
  // The automatic level at relaxed tolerances: no warning beyond the dropped cells.
  vtkNew<vtkHexahedraToTetrahedra> relaxed;
  uvtest::EventCounter* events = uvtest::WatchEvents(relaxed);
  relaxed->SetFieldTolerance(0.05);
  relaxed->SetChordTolerance(0.05);
  relaxed->SetMaximumLevel(8);
  relaxed->SetInputData(quadratic);
  relaxed->Update();
  EXPECT_EQ(events->Warnings, 1);
  EXPECT_GT(relaxed->GetOutput()->GetNumberOfCells(), 6 + 3 + 1 + 2);
}

TEST(HexahedraToTetrahedra, SharedHexahedralMeshes)
{
  struct Case
  {
    std::string File;
    vtkSmartPointer<vtkDataSet> Mesh;
  };
  std::vector<Case> cases;
  if (std::string path = uvtest::SharedData("can/can.vtu"); !path.empty())
  {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    cases.push_back({ "can.vtu", reader->GetOutput() });
  }
  if (std::string path = uvtest::SharedData("hexa/hexa.vtk"); !path.empty())
  {
    vtkNew<vtkUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    cases.push_back({ "hexa.vtk", reader->GetOutput() });
  }
  if (std::string path = uvtest::SharedData("bluntfin/bluntfin.vts"); !path.empty())
  {
    vtkNew<vtkXMLStructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    cases.push_back({ "bluntfin.vts", reader->GetOutput() });
  }
  if (std::string path = uvtest::SharedData("disk_out_ref/disk_out_ref.ex2"); !path.empty())
  {
    vtkNew<vtkExodusIIReader> reader;
    reader->SetFileName(path.c_str());
    reader->UpdateInformation();
    reader->SetAllArrayStatus(vtkExodusIIReader::ELEM_BLOCK, 1);
    reader->Update();
    vtkNew<vtkAppendFilter> merge; // vtkAppendFilter of VTK 9.1 takes the blocks one by one
    merge->MergePointsOn();
    vtkSmartPointer<vtkDataObjectTreeIterator> block;
    block.TakeReference(reader->GetOutput()->NewTreeIterator());
    for (block->InitTraversal(); !block->IsDoneWithTraversal(); block->GoToNextItem())
    {
      merge->AddInputData(block->GetCurrentDataObject());
    }
    merge->Update();
    cases.push_back({ "disk_out_ref.ex2", merge->GetOutput() });
  }
  if (cases.empty())
  {
    GTEST_SKIP() << "../shared/data is absent";
  }
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.File);
    vtkSmartPointer<vtkUnstructuredGrid> tets = Split(c.Mesh);
    EXPECT_EQ(tets->GetNumberOfCells(), 6 * c.Mesh->GetNumberOfCells());
    ExpectValidSplit(c.Mesh, tets);
    if (vtkStructuredGrid::SafeDownCast(c.Mesh))
    {
      vtkSmartPointer<vtkUnstructuredGrid> five = Split(c.Mesh, vtkHexahedraToTetrahedra::FIVE_TETRAHEDRA);
      EXPECT_EQ(five->GetNumberOfCells(), 5 * c.Mesh->GetNumberOfCells());
      ExpectValidSplit(c.Mesh, five);
    }
  }
}

TEST(HexahedraToTetrahedra, HexahedraAsPolyhedraGiveTheHexahedronSplit)
{
  for (int distortion : { vtkAnalyticMeshSource::NO_DISTORTION, vtkAnalyticMeshSource::ROTATE_45 })
  {
    vtkSmartPointer<vtkUnstructuredGrid> hexes = Analytic(3, distortion, vtkAnalyticMeshSource::HEXAHEDRA);
    vtkNew<vtkIntArray> label;
    label->SetName("cellLabel");
    for (vtkIdType c = 0; c < hexes->GetNumberOfCells(); ++c)
    {
      label->InsertNextValue(static_cast<int>(5 * c));
    }
    hexes->GetCellData()->AddArray(label);
    for (bool flip : { false, true })
    {
      vtkSmartPointer<vtkUnstructuredGrid> polyhedra =
        AsPolyhedra(hexes, [](vtkIdType) { return true; }, flip);
      ASSERT_EQ(polyhedra->GetCellType(0), VTK_POLYHEDRON);
      uvtest::EventCounter* events = nullptr;
      vtkSmartPointer<vtkUnstructuredGrid> tets = Split(polyhedra, vtkHexahedraToTetrahedra::SIX_TETRAHEDRA, &events);
      EXPECT_EQ(events->Errors + events->Warnings, 0) << events->LastMessage;
      ExpectSameTets(Split(hexes), tets);
      ExpectValidSplit(polyhedra, tets, FaceVolume(hexes));
      EXPECT_NEAR(FaceVolume(hexes), 8.0, 1e-12);
      auto original = tets->GetCellData()->GetArray("vtkOriginalCellIds");
      auto labels = tets->GetCellData()->GetArray("cellLabel");
      for (vtkIdType t = 0; t < tets->GetNumberOfCells(); ++t)
      {
        ASSERT_EQ(labels->GetTuple1(t), 5 * original->GetTuple1(t));
      }
    }
  }
}

TEST(HexahedraToTetrahedra, PrismColumnsConformAcrossCellTypes)
{
  for (int n : { 5, 6 })
  {
    for (unsigned seed = 1; seed <= 20; ++seed)
    {
      SCOPED_TRACE(n);
      vtkSmartPointer<vtkUnstructuredGrid> prisms = PrismColumn(n, 4, seed);
      const double volume = 4.0 * RegularPolygonArea(n);
      vtkSmartPointer<vtkUnstructuredGrid> tets = Split(prisms);
      EXPECT_EQ(tets->GetNumberOfCells(), (n == 5 ? 9 : 12) * 4);
      ExpectValidSplit(prisms, tets, volume);
      EXPECT_NEAR(FaceVolume(prisms), volume, 1e-12);
      // Odd levels as polyhedra: the shared n-gons must still be cut alike, and the tets unchanged.
      vtkSmartPointer<vtkUnstructuredGrid> mixed = AsPolyhedra(prisms, [](vtkIdType c) { return c % 2 == 1; });
      vtkSmartPointer<vtkUnstructuredGrid> mixedTets = Split(mixed);
      ExpectValidSplit(mixed, mixedTets, volume);
      ExpectSameTets(tets, mixedTets);
    }
  }
}

TEST(HexahedraToTetrahedra, NonConvexPolyhedronGetsACentrePoint)
{
  vtkSmartPointer<vtkUnstructuredGrid> mesh = LShapeAndHexahedron(2.0);
  uvtest::EventCounter* events = nullptr;
  vtkSmartPointer<vtkUnstructuredGrid> tets = Split(mesh, vtkHexahedraToTetrahedra::SIX_TETRAHEDRA, &events);
  EXPECT_EQ(events->Errors + events->Warnings, 0) << events->LastMessage;
  EXPECT_EQ(tets->GetNumberOfCells(), 20 + 6);
  ExpectValidSplit(mesh, tets, 8.0 + 2.0);
  EXPECT_NEAR(FaceVolume(mesh), 10.0, 1e-12);
  // One new point after the input's: the mean of the L's 12 vertices, its data the mean too.
  ASSERT_EQ(tets->GetNumberOfPoints(), mesh->GetNumberOfPoints() + 1);
  const vtkIdType centre = mesh->GetNumberOfPoints();
  double p[3];
  tets->GetPoint(centre, p);
  EXPECT_NEAR(p[0], 10.0 / 6.0, 1e-14);
  EXPECT_NEAR(p[1], 10.0 / 6.0, 1e-14);
  EXPECT_NEAR(p[2], 0.5, 1e-14);
  EXPECT_NEAR(tets->GetPointData()->GetScalars()->GetTuple1(centre), p[0] + 10.0 * p[1] + 100.0 * p[2], 1e-12);
  EXPECT_EQ(tets->GetPointData()->GetScalars()->GetName(), std::string("values"));
  EXPECT_EQ(tets->GetPointData()->GetArray("pointLabel")->GetTuple1(centre), 6.0); // mean of 0..11, 5.5, rounded
  for (vtkIdType i = 0; i < centre; ++i)
  {
    ASSERT_EQ(tets->GetPointData()->GetArray("pointLabel")->GetTuple1(i), i);
  }
  // The centre is used by the L's tets only, and cell data follows the input cell.
  auto original = tets->GetCellData()->GetArray("vtkOriginalCellIds");
  auto label = tets->GetCellData()->GetArray("cellLabel");
  vtkNew<vtkIdList> ids;
  for (vtkIdType t = 0; t < tets->GetNumberOfCells(); ++t)
  {
    tets->GetCellPoints(t, ids);
    EXPECT_EQ(ids->IsId(centre) >= 0, original->GetTuple1(t) == 0);
    EXPECT_EQ(label->GetTuple1(t), 70 + original->GetTuple1(t));
  }
}

TEST(HexahedraToTetrahedra, BadPolyhedraAreSkippedWithOneError)
{
  vtkNew<vtkUnstructuredGrid> hexes; // one unit cube
  vtkNew<vtkPoints> corners;
  const double unit[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 },
    { 1, 1, 1 }, { 0, 1, 1 } };
  for (const auto& p : unit)
  {
    corners->InsertNextPoint(p);
  }
  hexes->SetPoints(corners);
  const vtkIdType hexahedron[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  hexes->InsertNextCell(VTK_HEXAHEDRON, 8, hexahedron);
  vtkSmartPointer<vtkUnstructuredGrid> cube = AsPolyhedra(hexes, [](vtkIdType) { return true; });
  // Cell 0: the good cube. Cell 1: the cube with a face missing. Cell 2: a face with a repeated
  // point. Cell 3: a face of two points.
  vtkNew<vtkIdList> cubeStream;
  uvcompat::GetPolyhedronFaceStream(cube, 0, cubeStream);
  const vtkIdType numFaces = cubeStream->GetId(0);
  std::vector<vtkIdType> good(cubeStream->begin() + 1, cubeStream->end());
  ASSERT_EQ(good.size(), static_cast<std::size_t>(5 * numFaces));
  auto insert = [&](std::vector<vtkIdType> faceStream, vtkIdType count) {
    faceStream.insert(faceStream.begin(), count);
    vtkNew<vtkIdList> stream;
    for (vtkIdType id : faceStream)
    {
      stream->InsertNextId(id);
    }
    cube->InsertNextCell(VTK_POLYHEDRON, stream);
  };
  insert(std::vector<vtkIdType>(good.begin(), good.end() - 5), numFaces - 1);
  std::vector<vtkIdType> repeated = good;
  repeated[2] = repeated[1];
  insert(repeated, numFaces);
  std::vector<vtkIdType> twoPoints = { 2, good[1], good[2] };
  twoPoints.insert(twoPoints.end(), good.begin() + 5, good.end());
  insert(twoPoints, numFaces);
  uvtest::EventCounter* events = nullptr;
  vtkSmartPointer<vtkUnstructuredGrid> tets = Split(cube, vtkHexahedraToTetrahedra::SIX_TETRAHEDRA, &events);
  EXPECT_EQ(events->Errors, 1);
  EXPECT_EQ(events->Warnings, 0);
  EXPECT_NE(events->LastMessage.find("Skipped 3 polyhedra"), std::string::npos) << events->LastMessage;
  EXPECT_NE(events->LastMessage.find("cell 1: "), std::string::npos) << events->LastMessage;
  EXPECT_NE(events->LastMessage.find("do not close"), std::string::npos) << events->LastMessage;
  EXPECT_EQ(tets->GetNumberOfCells(), 6);
  EXPECT_EQ(tets->GetNumberOfPoints(), cube->GetNumberOfPoints());

  // A non-planar face, then a polyhedron that is not star-shaped from its centre: each named.
  vtkSmartPointer<vtkUnstructuredGrid> bent = AsPolyhedra(hexes, [](vtkIdType) { return true; });
  vtkNew<vtkPoints> moved;
  moved->DeepCopy(bent->GetPoints());
  double corner[3];
  moved->GetPoint(7, corner);
  moved->SetPoint(7, corner[0] + 0.3, corner[1] + 0.2, corner[2] + 0.1);
  bent->SetPoints(moved);
  tets = Split(bent, vtkHexahedraToTetrahedra::SIX_TETRAHEDRA, &events);
  EXPECT_EQ(events->Errors, 1);
  EXPECT_NE(events->LastMessage.find("cell 0: face"), std::string::npos) << events->LastMessage;
  EXPECT_NE(events->LastMessage.find("is not planar"), std::string::npos) << events->LastMessage;
  EXPECT_EQ(tets->GetNumberOfCells(), 0);

  vtkSmartPointer<vtkUnstructuredGrid> thin = LShapeAndHexahedron(1.0);
  tets = Split(thin, vtkHexahedraToTetrahedra::SIX_TETRAHEDRA, &events);
  EXPECT_EQ(events->Errors, 1);
  EXPECT_NE(events->LastMessage.find("cell 0: the polyhedron is not convex and not star-shaped"),
    std::string::npos)
    << events->LastMessage;
  EXPECT_EQ(tets->GetNumberOfCells(), 6); // the hexahedron only, no centre point
  EXPECT_EQ(tets->GetNumberOfPoints(), thin->GetNumberOfPoints());
}

TEST(HexahedraToTetrahedra, SharedPrismFiles)
{
  int found = 0;
  for (const char* file : { "cells/PentagonalPrism.vtu", "cells/HexagonalPrism.vtu" })
  {
    const std::string path = uvtest::SharedData(file);
    if (path.empty())
    {
      continue;
    }
    ++found;
    SCOPED_TRACE(file);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkUnstructuredGrid* prism = reader->GetOutput();
    ASSERT_EQ(prism->GetNumberOfCells(), 1);
    const bool pentagonal = prism->GetCellType(0) == VTK_PENTAGONAL_PRISM;
    ASSERT_TRUE(pentagonal || prism->GetCellType(0) == VTK_HEXAGONAL_PRISM);
    uvtest::EventCounter* events = nullptr;
    vtkSmartPointer<vtkUnstructuredGrid> tets = Split(prism, vtkHexahedraToTetrahedra::SIX_TETRAHEDRA, &events);
    EXPECT_EQ(events->Errors + events->Warnings, 0) << events->LastMessage;
    EXPECT_EQ(tets->GetNumberOfCells(), pentagonal ? 9 : 12);
    const double volume = FaceVolume(prism);
    EXPECT_GT(volume, 0.5);
    ExpectValidSplit(prism, tets, volume);
    vtkSmartPointer<vtkUnstructuredGrid> polyhedron = AsPolyhedra(prism, [](vtkIdType) { return true; }, true);
    ExpectSameTets(tets, Split(polyhedron));
  }
  if (found == 0)
  {
    GTEST_SKIP() << "../shared/data is absent";
  }
}
