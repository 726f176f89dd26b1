// vtkUnstructuredVolumeReferenceRenderer against closed forms and against itself.
#include "vtkuvNormalisedTransferFunction.h"
#include "uvTestMeshChecks.h"
#include "vtkAnalyticMeshSource.h"
#include "vtkHexahedraToTetrahedra.h"
#include "vtkUnstructuredVolumeReferenceRenderer.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include <algorithm>
#include <cstdio>
#include <cmath>

namespace
{
vtkSmartPointer<vtkVolumeProperty> Property(
  const std::vector<std::array<double, 2>>& opacity, double unitDistance = 1.0)
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0.1, 0.3, 0.9);
  color->AddRGBPoint(1.0, 0.9, 0.5, 0.1);
  vtkNew<vtkPiecewiseFunction> alpha;
  for (const auto& node : opacity)
  {
    alpha->AddPoint(node[0], node[1]);
  }
  property->SetColor(color);
  property->SetScalarOpacity(alpha);
  property->SetScalarOpacityUnitDistance(unitDistance);
  return property;
}

/// Hexahedral boxes [x0, x0+1] x [0,1] x [0,1] for each x0, scalar = x / 3 at the points.
vtkSmartPointer<vtkUnstructuredGrid> Boxes(const std::vector<double>& starts)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> scalar;
  scalar->SetName("s");
  for (double x0 : starts)
  {
    vtkIdType ids[8];
    for (int k = 0; k < 8; ++k)
    {
      const int cx = (k == 1 || k == 2 || k == 5 || k == 6), cy = (k == 2 || k == 3 || k == 6 || k == 7),
                cz = k >= 4;
      ids[k] = points->InsertNextPoint(x0 + cx, cy, cz);
      scalar->InsertNextValue((x0 + cx) / 3.0);
    }
    grid->InsertNextCell(VTK_HEXAHEDRON, 8, ids);
  }
  grid->SetPoints(points);
  grid->GetPointData()->SetScalars(scalar);
  return grid;
}

vtkSmartPointer<vtkImageData> Render(vtkDataSet* mesh, vtkVolumeProperty* property, vtkCamera* camera,
  int size, double tolerance = 1e-7, uvtest::EventCounter** events = nullptr)
{
  auto renderer = vtkSmartPointer<vtkUnstructuredVolumeReferenceRenderer>::New();
  uvtest::EventCounter* watched = uvtest::WatchEvents(renderer);
  if (events)
  {
    *events = watched;
  }
  renderer->SetInputData(mesh);
  renderer->SetVolumeProperty(property);
  renderer->SetCamera(camera);
  renderer->SetImageSize(size, size);
  renderer->SetTolerance(tolerance);
  renderer->Render();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(renderer->GetOutput());
  return image;
}

vtkSmartPointer<vtkCamera> ParallelCamera(const double focal[3], const double direction[3], double scale)
{
  auto camera = vtkSmartPointer<vtkCamera>::New();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(focal[0], focal[1], focal[2]);
  camera->SetPosition(focal[0] - 10 * direction[0], focal[1] - 10 * direction[1], focal[2] - 10 * direction[2]);
  camera->SetViewUp(direction[2] != 0 ? 0 : 0, direction[2] != 0 ? 1 : 0, direction[2] != 0 ? 0 : 1);
  camera->SetParallelScale(scale);
  camera->SetClippingRange(1.0, 30.0);
  return camera;
}

double MaxDifference(vtkImageData* a, vtkImageData* b)
{
  vtkDataArray* x = a->GetPointData()->GetScalars();
  vtkDataArray* y = b->GetPointData()->GetScalars();
  double worst = 0.0;
  for (vtkIdType i = 0; i < x->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      worst = std::max(worst, std::abs(x->GetComponent(i, c) - y->GetComponent(i, c)));
    }
  }
  return worst;
}
} // namespace

TEST(ReferenceRenderer, UnitCubeWithConstantOpacityIsClosedForm)
{
  // Parallel rays along z through a unit cube: every covered pixel sees length 1.
  const double alpha = 0.4;
  vtkSmartPointer<vtkVolumeProperty> property = Property({ { 0.0, alpha }, { 1.0, alpha } });
  const double focal[3] = { 0.5, 0.5, 0.5 }, along[3] = { 0, 0, 1 };
  // A scale that puts no pixel centre on the cube's faces (0.8 would, at 40 pixels).
  const double scale = 0.81;
  vtkSmartPointer<vtkCamera> camera = ParallelCamera(focal, along, scale);
  vtkSmartPointer<vtkUnstructuredGrid> cube = Boxes({ 0.0 });
  vtkSmartPointer<vtkImageData> image = Render(cube, property, camera, 40);
  vtkDataArray* rgba = image->GetPointData()->GetScalars();
  int covered = 0;
  for (vtkIdType i = 0; i < rgba->GetNumberOfTuples(); ++i)
  {
    const double a = rgba->GetComponent(i, 3);
    if (a > 0.0)
    {
      ++covered;
      ASSERT_NEAR(a, alpha, 1e-7) << "pixel " << i; // 1 - exp(-tau * 1) with tau = -ln(1 - alpha)
    }
  }
  // Pixel centres at -scale + (i + 0.5) * 2 scale / 40 inside |c| < 0.5, in both directions.
  int across = 0;
  for (int i = 0; i < 40; ++i)
  {
    across += std::abs(-scale + (i + 0.5) * 2.0 * scale / 40) < 0.5 ? 1 : 0;
  }
  EXPECT_EQ(covered, across * across);

  // Its 6-tet split gives the same image: no cracks along the new faces.
  vtkNew<vtkHexahedraToTetrahedra> split;
  split->SetInputData(cube);
  split->Update();
  EXPECT_LT(MaxDifference(image, Render(split->GetOutput(), property, camera, 40)), 1e-6);
}

TEST(ReferenceRenderer, RaysLeaveAndReEnterAcrossAHole)
{
  // Two unit boxes along x with a gap: rays along x cross 2 units of matter in two pieces.
  const double alpha = 0.3;
  vtkSmartPointer<vtkVolumeProperty> property = Property({ { 0.0, alpha }, { 2.0, alpha } });
  const double focal[3] = { 1.5, 0.5, 0.5 }, along[3] = { 1, 0, 0 };
  vtkSmartPointer<vtkImageData> image = Render(Boxes({ 0.0, 2.0 }), property, ParallelCamera(focal, along, 0.8), 20);
  vtkDataArray* rgba = image->GetPointData()->GetScalars();
  const double expected = 1.0 - (1.0 - alpha) * (1.0 - alpha);
  const double centre = rgba->GetComponent(10 * 20 + 10, 3);
  EXPECT_NEAR(centre, expected, 1e-7);
}

TEST(ReferenceRenderer, HexahedraAndTheirTetSplitAgreeOnLinearFields)
{
  // The trilinear field of a linear function is that linear function; so is the tets' field.
  vtkSmartPointer<vtkVolumeProperty> property =
    Property({ { 0.0, 0.0 }, { 0.5, 0.3 }, { 0.6, 0.05 }, { 1.0, 0.8 } }, 0.5);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(3.0, -4.0, 2.5);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 0, 1);
  camera->SetViewAngle(30);
  camera->SetClippingRange(1.0, 20.0);
  for (int distortion : { vtkAnalyticMeshSource::NO_DISTORTION, vtkAnalyticMeshSource::ROTATE_45 })
  {
    vtkNew<vtkAnalyticMeshSource> hexahedra;
    hexahedra->SetResolution(3, 3, 3);
    hexahedra->SetDistortion(distortion);
    hexahedra->SetField(vtkAnalyticMeshSource::LINEAR);
    vtkNew<vtkAnalyticMeshSource> tets;
    tets->SetResolution(3, 3, 3);
    tets->SetDistortion(distortion);
    tets->SetField(vtkAnalyticMeshSource::LINEAR);
    tets->SetCellKind(vtkAnalyticMeshSource::SIX_TETRAHEDRA);
    hexahedra->Update();
    tets->Update();
    vtkSmartPointer<vtkImageData> a = Render(hexahedra->GetOutput(), property, camera, 32);
    vtkSmartPointer<vtkImageData> b = Render(tets->GetOutput(), property, camera, 32);
    EXPECT_LT(MaxDifference(a, b), 1e-6);
    EXPECT_GT(a->GetPointData()->GetScalars()->GetRange(3)[1], 0.3); // something was drawn
  }
}

TEST(ReferenceRenderer, WedgesAndPyramidsMatchTheirTetSplitOnLinearFields)
{
  // A hexahedron with a pyramid, a wedge and a tet glued on; planar faces, a linear field: the
  // isoparametric cells and the tets of their split describe the same field on the same volume.
  vtkSmartPointer<vtkUnstructuredGrid> mixed = uvtest::MixedMesh();
  vtkNew<vtkDoubleArray> linear;
  linear->SetName("linear");
  for (vtkIdType i = 0; i < mixed->GetNumberOfPoints(); ++i)
  {
    const double* x = mixed->GetPoint(i);
    linear->InsertNextValue(0.2 + 0.25 * x[0] + 0.1 * x[1] + 0.15 * x[2]);
  }
  mixed->GetPointData()->SetScalars(linear);
  vtkNew<vtkHexahedraToTetrahedra> split;
  split->SetInputData(mixed);
  split->Update();
  vtkSmartPointer<vtkVolumeProperty> property =
    Property({ { 0.0, 0.0 }, { 0.4, 0.5 }, { 0.5, 0.1 }, { 1.0, 0.7 } }, 0.5);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(4.0, -3.0, 3.5);
  camera->SetFocalPoint(0.8, 0.3, 0.8);
  camera->SetViewUp(0, 0, 1);
  camera->SetClippingRange(1.0, 20.0);
  uvtest::EventCounter* events = nullptr;
  vtkSmartPointer<vtkImageData> isoparametric = Render(mixed, property, camera, 32, 1e-7, &events);
  EXPECT_EQ(events->Errors, 0);
  vtkSmartPointer<vtkImageData> tets = Render(split->GetOutput(), property, camera, 32);
  EXPECT_LT(MaxDifference(isoparametric, tets), 1e-6);
  EXPECT_GT(isoparametric->GetPointData()->GetScalars()->GetRange(3)[1], 0.3);
}

TEST(ReferenceRenderer, OverlappingCellsSuperpose)
{
  // Two boxes overlapping over half their length along the rays, scalar 0 in one and 1 in the
  // other (different colours): where both are, their extinctions and emissions add, whatever
  // their order. Closed form of the three constant pieces.
  const double alpha = 0.5, tau = -std::log(1.0 - alpha);
  vtkSmartPointer<vtkVolumeProperty> property = Property({ { 0.0, alpha }, { 1.0, alpha } });
  vtkSmartPointer<vtkUnstructuredGrid> boxes = Boxes({ 0.0, 0.5 });
  vtkDataArray* scalar = boxes->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < 16; ++i)
  {
    scalar->SetComponent(i, 0, i < 8 ? 0.0 : 1.0);
  }
  const double focal[3] = { 0.75, 0.5, 0.5 }, along[3] = { 1, 0, 0 };
  vtkSmartPointer<vtkImageData> image = Render(boxes, property, ParallelCamera(focal, along, 0.8), 20);
  const glm::dvec3 first(0.1, 0.3, 0.9), second(0.9, 0.5, 0.1); // Property()'s colours at 0 and 1
  glm::dvec3 color(0.0);
  double transmittance = 1.0;
  const auto piece = [&](double depth, const glm::dvec3& emission) {
    color += transmittance * emission / depth * (1.0 - std::exp(-depth));
    transmittance *= std::exp(-depth);
  };
  piece(0.5 * tau, 0.5 * tau * first);
  piece(tau, 0.5 * tau * (first + second));
  piece(0.5 * tau, 0.5 * tau * second);
  vtkDataArray* rgba = image->GetPointData()->GetScalars();
  const vtkIdType centre = 10 * 20 + 10;
  EXPECT_NEAR(rgba->GetComponent(centre, 3), 1.0 - transmittance, 1e-7);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(rgba->GetComponent(centre, c), color[c], 1e-7) << "channel " << c;
  }
}

TEST(ReferenceRenderer, OffsetsChangeNothing)
{
  // The same twisted mesh and camera moved by 1e6 and 1e9: everything is recentred in double, so
  // the images agree (before: 1e6 lost pixels in grazing views, 1e9 did not finish).
  vtkNew<vtkAnalyticMeshSource> source;
  source->SetResolution(4, 4, 4);
  source->SetDistortion(vtkAnalyticMeshSource::TWIST);
  source->Update();
  vtkSmartPointer<vtkVolumeProperty> property =
    Property({ { 0.0, 0.0 }, { 0.45, 0.0 }, { 0.5, 0.9 }, { 0.55, 0.0 }, { 1.0, 0.3 } }, 0.3);
  const auto camera = [](double offset, bool grazing) {
    auto view = vtkSmartPointer<vtkCamera>::New();
    view->SetPosition(offset + (grazing ? 4.0 : 2.5), offset + (grazing ? 0.02 : 3.0), offset + (grazing ? 0.01 : 4.0));
    view->SetFocalPoint(offset, offset, offset);
    view->SetClippingRange(0.5, 20.0);
    return view;
  };
  for (bool grazing : { false, true })
  {
    vtkSmartPointer<vtkImageData> origin = Render(source->GetOutput(), property, camera(0.0, grazing), 24);
    for (double offset : { 1e6, 1e9 })
    {
      vtkNew<vtkUnstructuredGrid> moved;
      moved->DeepCopy(source->GetOutput());
      vtkPoints* points = moved->GetPoints();
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        double x[3];
        points->GetPoint(i, x);
        points->SetPoint(i, x[0] + offset, x[1] + offset, x[2] + offset);
      }
      vtkSmartPointer<vtkImageData> image = Render(moved, property, camera(offset, grazing), 24);
      EXPECT_LT(MaxDifference(origin, image), offset > 1e7 ? 1e-4 : 1e-6)
        << "offset " << offset << (grazing ? ", grazing" : "");
    }
  }
}

TEST(ReferenceRenderer, ScalarOffsetsChangeNothing)
{
  // The same field as 64-bit integers near 2^62 (steps of 1024, which doubles hold exactly there)
  // and as small doubles, with the transfer function moved along: the reference renders both the
  // same (before, interpolating values near 4.6e18 in double lost a thousandth of the range).
  vtkNew<vtkAnalyticMeshSource> source;
  source->SetResolution(4, 4, 4);
  source->SetDistortion(vtkAnalyticMeshSource::TWIST);
  source->Update();
  vtkDataArray* field = source->GetOutput()->GetPointData()->GetScalars();
  const double base = std::ldexp(1.0, 62);
  const auto steps = [&](vtkIdType i) { return 1024.0 * std::round(1024.0 * field->GetComponent(i, 0)); };
  vtkNew<vtkTypeInt64Array> far;
  vtkNew<vtkDoubleArray> near;
  for (vtkIdType i = 0; i < field->GetNumberOfTuples(); ++i)
  {
    far->InsertNextValue(static_cast<vtkTypeInt64>(base) + static_cast<vtkTypeInt64>(steps(i)));
    near->InsertNextValue(steps(i));
  }
  const auto mesh = [&](vtkDataArray* values) {
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    grid->ShallowCopy(source->GetOutput());
    grid->GetPointData()->SetScalars(values);
    return grid;
  };
  const auto property = [](double offset) {
    auto moved = Property({}, 0.4);
    vtkNew<vtkPiecewiseFunction> opacity;
    vtkNew<vtkColorTransferFunction> color;
    for (double u : { 0.0, 0.375, 0.625, 1.0 }) // nodes on multiples of 1024 too
    {
      opacity->AddPoint(offset + u * 1024.0 * 1024.0, u == 0.625 ? 0.9 : 0.2 * u);
      color->AddRGBPoint(offset + u * 1024.0 * 1024.0, u, 0.5, 1.0 - u);
    }
    moved->SetScalarOpacity(opacity);
    moved->SetColor(color);
    return moved;
  };
  vtkNew<vtkCamera> camera;
  camera->SetPosition(2.5, 3.0, 4.0);
  camera->SetClippingRange(0.5, 20.0);
  vtkSmartPointer<vtkImageData> expected = Render(mesh(near), property(0.0), camera, 24);
  vtkSmartPointer<vtkImageData> image = Render(mesh(far), property(base), camera, 24);
  EXPECT_GT(expected->GetPointData()->GetScalars()->GetRange(3)[1], 0.5);
  EXPECT_LT(MaxDifference(expected, image), 1e-6);
}

TEST(ReferenceRenderer, HalvingTheToleranceChangesNoPixelByMoreThan1e6)
{
  vtkNew<vtkAnalyticMeshSource> mesh;
  mesh->SetResolution(4, 4, 4);
  mesh->SetDistortion(vtkAnalyticMeshSource::TWIST);
  mesh->Update();
  vtkSmartPointer<vtkVolumeProperty> property =
    Property({ { 0.0, 0.0 }, { 0.45, 0.0 }, { 0.5, 0.9 }, { 0.55, 0.0 }, { 1.0, 0.3 } }, 0.3);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(2.5, 3.0, 4.0);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetClippingRange(0.5, 20.0);
  vtkSmartPointer<vtkImageData> coarse = Render(mesh->GetOutput(), property, camera, 24, 1e-7);
  vtkSmartPointer<vtkImageData> finer = Render(mesh->GetOutput(), property, camera, 24, 5e-8);
  EXPECT_LT(MaxDifference(coarse, finer), 1e-6);
}

TEST(ReferenceRenderer, BadInput)
{
  vtkSmartPointer<vtkVolumeProperty> property = Property({ { 0.0, 0.5 }, { 1.0, 0.5 } });
  vtkNew<vtkCamera> camera;
  uvtest::EventCounter* events = nullptr;
  vtkNew<vtkUnstructuredGrid> empty;
  vtkSmartPointer<vtkImageData> image = Render(empty, property, camera, 8, 1e-7, &events);
  EXPECT_EQ(events->Errors, 0);
  EXPECT_EQ(image->GetPointData()->GetScalars()->GetRange(3)[1], 0.0);

  vtkSmartPointer<vtkUnstructuredGrid> cube = Boxes({ 0.0 });
  cube->GetPointData()->GetScalars()->SetName("other");
  auto renderer = vtkSmartPointer<vtkUnstructuredVolumeReferenceRenderer>::New();
  uvtest::EventCounter missing(renderer);
  renderer->SetInputData(cube);
  renderer->SetScalarArrayName("s");
  renderer->SetVolumeProperty(property);
  renderer->SetCamera(camera);
  EXPECT_FALSE(renderer->Render());
  EXPECT_EQ(missing.Errors, 1);

  // Quadratic cells render (test_higher_order.py checks how well), and a Lagrange tetrahedron of
  // order 2 on the same ten nodes is the same cell. A Lagrange pyramid, which no VTK 9.1 class
  // interpolates, is an error naming it, as is a rational Bezier cell.
  const auto quadratic = Render(uvtest::QuadraticTetraMesh(), property, camera, 8, 1e-7, &events);
  EXPECT_EQ(events->Errors, 0);
  const auto lagrange = Render(uvtest::QuadraticTetraMesh(VTK_LAGRANGE_TETRAHEDRON), property, camera, 8, 1e-7, &events);
  EXPECT_EQ(events->Errors, 0);
  EXPECT_LT(MaxDifference(quadratic, lagrange), 1e-6);
  Render(uvtest::QuadraticTetraMesh(VTK_LAGRANGE_PYRAMID), property, camera, 8, 1e-7, &events);
  EXPECT_EQ(events->Errors, 1);
  EXPECT_NE(events->LastMessage.find("vtkLagrangePyramid"), std::string::npos) << events->LastMessage;
  auto bezier = uvtest::QuadraticTetraMesh(VTK_BEZIER_TETRAHEDRON);
  vtkNew<vtkDoubleArray> rationalWeights;
  rationalWeights->SetNumberOfTuples(bezier->GetNumberOfPoints());
  rationalWeights->Fill(1.0);
  bezier->GetPointData()->SetRationalWeights(rationalWeights);
  Render(bezier, property, camera, 8, 1e-7, &events);
  EXPECT_EQ(events->Errors, 1);
  EXPECT_NE(events->LastMessage.find("Rational Bezier"), std::string::npos) << events->LastMessage;
}

TEST(ReferenceRenderer, CurvedTransferFunctionsAreFollowedWithNodesWhereTheyBend)
{
  // ParaView's default colour map interpolates in the Diverging space (not linear in RGB between
  // its nodes). The model halves intervals only where the curve bends: as close to VTK's colours as
  // the full 32 pieces per interval, with far fewer nodes. In RGB no node is added.
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkColorTransferFunction> colors;
  colors->AddRGBPoint(0.0, 0.23, 0.30, 0.75);
  colors->AddRGBPoint(0.5, 0.87, 0.87, 0.87);
  colors->AddRGBPoint(1.0, 0.71, 0.02, 0.15);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(0.3, 0.1);
  opacity->AddPoint(1.0, 0.4);
  property->SetColor(colors);
  property->SetScalarOpacity(opacity);
  EXPECT_EQ(vtkuv::TransferFunctionNodes(property).size(), 4u); // RGB: the nodes' union alone

  colors->SetColorSpaceToDiverging();
  auto colourError = [&](const std::vector<uv::TransferFunction::Node>& nodes) {
    const uv::TransferFunction model(nodes);
    double worst = 0.0;
    for (int i = 0; i <= 2000; ++i)
    {
      const double s = i / 2000.0;
      double rgb[3];
      colors->GetColor(s, rgb);
      const glm::dvec3 followed = model.Color(s);
      worst = std::max({ worst, std::abs(followed.x - rgb[0]), std::abs(followed.y - rgb[1]), std::abs(followed.z - rgb[2]) });
    }
    return worst;
  };
  const auto uniform = vtkuv::TransferFunctionNodes(property, 32, 0.0); // every interval in 32
  const auto adaptive = vtkuv::TransferFunctionNodes(property);         // tolerance 2e-3
  const auto finer = vtkuv::TransferFunctionNodes(property, 32, 1e-4);
  std::printf("Diverging colour map: uniform %zu nodes, error %.2e; adaptive %zu nodes, error %.2e; "
              "tolerance 1e-4: %zu nodes\n", uniform.size(), colourError(uniform), adaptive.size(),
    colourError(adaptive), finer.size());
  EXPECT_EQ(uniform.size(), 3u * 32u + 1u);
  EXPECT_LT(adaptive.size(), uniform.size() / 2);
  EXPECT_LT(colourError(adaptive), colourError(uniform) + 2e-3);
  EXPECT_GT(finer.size(), adaptive.size());
}
