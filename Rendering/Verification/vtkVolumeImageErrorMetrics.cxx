#include "vtkVolumeImageErrorMetrics.h"

#include "uvImageErrorMetrics.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <vector>

vtkStandardNewMacro(vtkVolumeImageErrorMetrics);

namespace
{
/// Pixel values as doubles in [0, 1], `stride` per pixel.
std::vector<double> NormalizedValues(vtkDataArray* array)
{
  const double scale = array->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
  std::vector<double> values(static_cast<std::size_t>(array->GetNumberOfValues()));
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < array->GetNumberOfComponents(); ++c)
    {
      values[i * array->GetNumberOfComponents() + c] = scale * array->GetComponent(i, c);
    }
  }
  return values;
}
} // namespace

vtkVolumeImageErrorMetrics::vtkVolumeImageErrorMetrics()
{
  this->ErrorImage = vtkImageData::New();
}

vtkVolumeImageErrorMetrics::~vtkVolumeImageErrorMetrics()
{
  this->ErrorImage->Delete();
}

bool vtkVolumeImageErrorMetrics::Compare(vtkImageData* candidate, vtkImageData* reference)
{
  vtkDataArray* a = candidate ? candidate->GetPointData()->GetScalars() : nullptr;
  vtkDataArray* b = reference ? reference->GetPointData()->GetScalars() : nullptr;
  if (!a || !b)
  {
    vtkErrorMacro("Both images need point scalars.");
    return false;
  }
  int dimsA[3], dimsB[3];
  candidate->GetDimensions(dimsA);
  reference->GetDimensions(dimsB);
  if (dimsA[0] != dimsB[0] || dimsA[1] != dimsB[1] || dimsA[2] != dimsB[2] ||
    a->GetNumberOfComponents() != b->GetNumberOfComponents() ||
    a->GetNumberOfComponents() < this->Channels)
  {
    vtkErrorMacro("Images differ in size or components (" << dimsA[0] << "x" << dimsA[1] << "x"
      << a->GetNumberOfComponents() << " vs " << dimsB[0] << "x" << dimsB[1] << "x"
      << b->GetNumberOfComponents() << "), or have fewer than " << this->Channels << " channels.");
    return false;
  }
  const std::vector<double> x = NormalizedValues(a), y = NormalizedValues(b);
  const uv::ErrorMetrics metrics = uv::CompareImages(x.data(), y.data(),
    static_cast<std::size_t>(a->GetNumberOfTuples()), a->GetNumberOfComponents(), this->Channels,
    this->CoverageThreshold);
  this->RMSE = metrics.All.RMSE;
  this->PSNR = metrics.All.PSNR;
  this->MaximumError = metrics.All.Maximum;
  this->Percentile99Error = metrics.All.Percentile99;
  this->CoveredRMSE = metrics.Covered.RMSE;
  this->CoveredPSNR = metrics.Covered.PSNR;
  this->CoveredMaximumError = metrics.Covered.Maximum;
  this->CoveredPercentile99Error = metrics.Covered.Percentile99;
  this->NumberOfCoveredPixels = static_cast<vtkIdType>(metrics.Covered.Pixels);

  this->ErrorImage->Initialize();
  this->ErrorImage->SetDimensions(dimsA);
  vtkNew<vtkUnsignedCharArray> heat;
  heat->SetName("Error");
  heat->SetNumberOfComponents(3);
  heat->SetNumberOfTuples(a->GetNumberOfTuples());
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    uv::HeatColor(metrics.PixelError[i], this->HeatMapScale, heat->GetPointer(3 * i));
  }
  this->ErrorImage->GetPointData()->SetScalars(heat);
  this->Modified();
  return true;
}

void vtkVolumeImageErrorMetrics::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Channels: " << this->Channels << "\n";
  os << indent << "RMSE: " << this->RMSE << " (covered " << this->CoveredRMSE << ")\n";
  os << indent << "PSNR: " << this->PSNR << " (covered " << this->CoveredPSNR << ")\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "Percentile99Error: " << this->Percentile99Error << "\n";
}
