#include "vtkUnstructuredVolumeReferenceRenderer.h"

#include "uvChebyshevSeries.h"
#include "uvLinearCellSplit.h"
#include "uvOpticalModel.h"
#include "uvRayCellGeometry.h"
#include "uvTransferFunctionFromVolumeProperty.h"

#include "vtkCamera.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkGenericCell.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
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
  int Corners() const { return this->Shape ? this->Shape->Corners : 4; }
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

struct Segment
{
  uv::Interval Span;
  std::int64_t Cell;
};
} // namespace

vtkUnstructuredVolumeReferenceRenderer::vtkUnstructuredVolumeReferenceRenderer()
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
}

void vtkUnstructuredVolumeReferenceRenderer::SetInputData(vtkDataSet* input)
{
  vtkSetObjectBodyMacro(Input, vtkDataSet, input);
}

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
  this->Output->Initialize();
  this->Output->SetDimensions(width, height, 1);
  vtkNew<vtkFloatArray> rgba;
  rgba->SetName("RGBA");
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  rgba->Fill(0.0);
  this->Output->GetPointData()->SetScalars(rgba);
  if (!this->Input || this->Input->GetNumberOfCells() == 0)
  {
    return true; // nothing to render: a transparent image
  }

  vtkDataArray* scalars = this->ScalarArrayName
    ? this->Input->GetPointData()->GetArray(this->ScalarArrayName)
    : this->Input->GetPointData()->GetScalars();
  if (!scalars || scalars->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro("No single-component point scalar array "
      << (this->ScalarArrayName ? this->ScalarArrayName : "(active scalars)") << " on the input.");
    return false;
  }
  const std::vector<uv::TransferFunction::Node> nodes = uv::TransferFunctionNodes(this->VolumeProperty);
  if (nodes.empty())
  {
    vtkErrorMacro("The volume property has no scalar opacity function.");
    return false;
  }
  const uv::TransferFunction transfer(nodes);
  if (transfer.IsInvisible())
  {
    return true;
  }

  // Points, scalars and cells in double precision.
  const vtkIdType numPoints = this->Input->GetNumberOfPoints();
  std::vector<glm::dvec3> points(numPoints);
  std::vector<double> values(numPoints);
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    this->Input->GetPoint(i, &points[i].x);
    values[i] = scalars->GetComponent(i, 0);
  }
  std::vector<Cell> cells;
  std::vector<uv::BoundingVolumeHierarchy::Box> boxes;
  vtkNew<vtkIdList> ids;
  vtkNew<vtkGenericCell> probe;
  vtkIdType ignored = 0, nonFinite = 0;
  for (vtkIdType c = 0; c < this->Input->GetNumberOfCells(); ++c)
  {
    const int type = this->Input->GetCellType(c);
    if (type != VTK_TETRA && !ShapeOf(type))
    {
      probe->SetCellType(type);
      if (type == VTK_EMPTY_CELL || probe->GetCellDimension() < 3)
      {
        ++ignored;
        continue;
      }
      vtkErrorMacro("The reference renderer takes linear tetrahedra, hexahedra, voxels, wedges and "
                    "pyramids; cell "
        << c << " is a " << vtkCellTypes::GetClassNameFromTypeId(type) << ".");
      return false;
    }
    this->Input->GetCellPoints(c, ids);
    Cell cell{ ShapeOf(type), {} };
    const int corners = cell.Corners();
    uv::BoundingVolumeHierarchy::Box box;
    bool finite = true;
    for (int k = 0; k < corners; ++k)
    {
      const vtkIdType id = ids->GetId(type == VTK_VOXEL ? uv::VoxelToHexahedronOrder[k] : k);
      cell.Ids[k] = id;
      box.Add({ points[id], points[id] });
      finite = finite && std::isfinite(values[id]);
    }
    if (!finite)
    {
      ++nonFinite;
      continue;
    }
    cells.push_back(cell);
    boxes.push_back(box);
  }
  if (ignored > 0)
  {
    vtkWarningMacro("Ignored " << ignored << " cells that are not 3D.");
  }
  if (nonFinite > 0)
  {
    vtkWarningMacro("Left out " << nonFinite << " cells with non-finite scalars.");
  }
  const uv::BoundingVolumeHierarchy hierarchy(std::move(boxes));

  // Pixel centres unprojected through the camera's composite projection (both projections).
  const double aspect = static_cast<double>(width) / height;
  vtkNew<vtkMatrix4x4> unproject;
  unproject->DeepCopy(this->Camera->GetCompositeProjectionTransformMatrix(aspect, -1, 1));
  unproject->Invert();
  auto unprojectPoint = [&](double x, double y, double z) {
    double in[4] = { x, y, z, 1.0 }, out[4];
    unproject->MultiplyPoint(in, out);
    return glm::dvec3(out[0], out[1], out[2]) / out[3];
  };

  float* pixels = rgba->GetPointer(0);
  const double tolerance = this->Tolerance;
  vtkSMPThreadLocal<std::vector<Segment>> threadSegments;
  vtkSMPThreadLocal<std::vector<uv::Interval>> threadParts;
  vtkSMPThreadLocal<std::vector<double>> threadScratch;
  vtkSMPTools::For(0, static_cast<vtkIdType>(width) * height, [&](vtkIdType begin, vtkIdType end) {
    std::vector<Segment>& segments = threadSegments.Local();
    std::vector<uv::Interval>& parts = threadParts.Local();
    std::vector<double>& scratch = threadScratch.Local();
    for (vtkIdType pixel = begin; pixel < end; ++pixel)
    {
      const double x = 2.0 * ((pixel % width) + 0.5) / width - 1.0;
      const double y = 2.0 * ((pixel / width) + 0.5) / height - 1.0;
      const glm::dvec3 nearPoint = unprojectPoint(x, y, -1.0);
      const uv::Ray ray{ nearPoint, glm::normalize(unprojectPoint(x, y, 1.0) - nearPoint) };
      segments.clear();
      hierarchy.Traverse(ray, [&](std::int64_t index) {
        const Cell& cell = cells[index];
        glm::dvec3 p[8];
        for (int k = 0; k < cell.Corners(); ++k)
        {
          p[k] = points[cell.Ids[k]];
        }
        parts.clear();
        if (cell.Shape)
        {
          uv::IntersectIsoparametric(*cell.Shape, ray, p, cell.Ids, parts, scratch);
        }
        else
        {
          uv::Interval span;
          if (uv::IntersectTetrahedron(ray, p, cell.Ids, span))
          {
            parts.push_back(span);
          }
        }
        for (uv::Interval part : parts)
        {
          part.Enter = std::max(part.Enter, 0.0);
          if (part.Exit > part.Enter)
          {
            segments.push_back({ part, index });
          }
        }
      });
      std::sort(segments.begin(), segments.end(),
        [](const Segment& a, const Segment& b) { return a.Span.Enter < b.Span.Enter; });

      uv::RayAccumulator accumulator;
      for (const Segment& segment : segments)
      {
        if (accumulator.Transmittance < 1e-12)
        {
          break; // what lies behind cannot change any channel by more than 1e-12
        }
        const Cell& cell = cells[segment.Cell];
        glm::dvec3 p[8];
        double f[8];
        for (int k = 0; k < cell.Corners(); ++k)
        {
          p[k] = points[cell.Ids[k]];
          f[k] = values[cell.Ids[k]];
        }
        const double t0 = segment.Span.Enter, t1 = segment.Span.Exit;
        if (!cell.Shape)
        {
          const double s0 = uv::TetrahedronScalar(p, f, ray.Origin + t0 * ray.Direction);
          const double s1 = uv::TetrahedronScalar(p, f, ray.Origin + t1 * ray.Direction);
          const auto linear = [&](double t) { return s0 + (s1 - s0) * (t - t0) / (t1 - t0); };
          uv::IntegrateSegment(transfer, linear, t0, t1, tolerance, accumulator);
          continue;
        }
        const uv::IsoparametricShape& shape = *cell.Shape;
        glm::dvec3 xi0 = shape.Centre, xi1 = shape.Centre;
        uv::InverseIsoparametric(shape, p, ray.Origin + t0 * ray.Direction, xi0);
        uv::InverseIsoparametric(shape, p, ray.Origin + t1 * ray.Direction, xi1);
        const auto isoparametric = [&](double t) {
          glm::dvec3 xi = xi0 + (xi1 - xi0) * ((t - t0) / (t1 - t0));
          uv::InverseIsoparametric(shape, p, ray.Origin + t * ray.Direction, xi);
          return uv::IsoparametricScalar(shape, f, xi);
        };
        // s(t) is smooth inside the cell: a certified Chebyshev fit (17 inverse solves) stands in
        // for the hundreds of solves the quadrature would make; unresolved fits use s(t) itself.
        double magnitude = 1.0;
        for (int k = 0; k < shape.Corners; ++k)
        {
          magnitude = std::max(magnitude, 1.0 + std::abs(f[k]));
        }
        uv::ChebyshevSeries series;
        if (series.Fit(isoparametric, t0, t1, 1e-12 * magnitude))
        {
          uv::IntegrateSegment(transfer, series, t0, t1, tolerance, accumulator);
        }
        else
        {
          uv::IntegrateSegment(transfer, isoparametric, t0, t1, tolerance, accumulator);
        }
      }
      float* out = pixels + 4 * pixel;
      out[0] = static_cast<float>(accumulator.Color.x);
      out[1] = static_cast<float>(accumulator.Color.y);
      out[2] = static_cast<float>(accumulator.Color.z);
      out[3] = static_cast<float>(accumulator.Opacity());
    }
  });
  rgba->Modified();
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
}
