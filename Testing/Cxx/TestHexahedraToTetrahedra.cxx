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
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRectilinearGrid.h"
#include "vtkStructuredGrid.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkXMLStructuredGridReader.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <gtest/gtest.h>

#include <numeric>

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

  vtkSmartPointer<vtkUnstructuredGrid> quadratic = uvtest::QuadraticTetraMesh();
  out = Split(quadratic, vtkHexahedraToTetrahedra::SIX_TETRAHEDRA, &events);
  EXPECT_EQ(events->Errors, 1);
  EXPECT_NE(events->LastMessage.find("vtkQuadraticTetra"), std::string::npos) << events->LastMessage;
  EXPECT_EQ(out->GetNumberOfCells(), 0);
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
