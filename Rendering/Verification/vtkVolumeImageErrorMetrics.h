/**
 * @class   vtkVolumeImageErrorMetrics
 * @brief   Error of a rendered image against the reference renderer's: RMSE, PSNR, max, 99th percentile.
 *
 * Both images are vtkImageData of the same dimensions whose scalars are premultiplied RGBA (or RGB)
 * in [0, 1] (float) or [0, 255] (unsigned char, scaled by 1/255). Metrics are computed over all pixels
 * and over the pixels the volume covers (either image's opacity above CoverageThreshold); Channels
 * chooses 4 (RGBA) or 3 (RGB, for renderers whose alpha is not meaningful). GetErrorImage() is a heat
 * map (black, red, yellow, white) of each pixel's largest channel error over [0, HeatMapScale].
 */
#ifndef vtkVolumeImageErrorMetrics_h
#define vtkVolumeImageErrorMetrics_h

#include "vtkObject.h"
#include "vtkUnstructuredVolumeModule.h" // for export macro

class vtkImageData;

class VTKUNSTRUCTUREDVOLUME_EXPORT vtkVolumeImageErrorMetrics : public vtkObject
{
public:
  static vtkVolumeImageErrorMetrics* New();
  vtkTypeMacro(vtkVolumeImageErrorMetrics, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetClampMacro(Channels, int, 3, 4);
  vtkGetMacro(Channels, int);
  vtkSetMacro(CoverageThreshold, double);
  vtkGetMacro(CoverageThreshold, double);
  vtkSetMacro(HeatMapScale, double);
  vtkGetMacro(HeatMapScale, double);

  /// Compares; false (with an error) when the images do not match in size or layout.
  bool Compare(vtkImageData* candidate, vtkImageData* reference);

  ///@{
  /// Over all pixels.
  vtkGetMacro(RMSE, double);
  vtkGetMacro(PSNR, double);
  vtkGetMacro(MaximumError, double);
  vtkGetMacro(Percentile99Error, double);
  ///@}
  ///@{
  /// Over the covered pixels.
  vtkGetMacro(CoveredRMSE, double);
  vtkGetMacro(CoveredPSNR, double);
  vtkGetMacro(CoveredMaximumError, double);
  vtkGetMacro(CoveredPercentile99Error, double);
  vtkGetMacro(NumberOfCoveredPixels, vtkIdType);
  ///@}

  /// The heat map of the last comparison (RGB, unsigned char).
  vtkImageData* GetErrorImage() { return this->ErrorImage; }

protected:
  vtkVolumeImageErrorMetrics();
  ~vtkVolumeImageErrorMetrics() override;

  int Channels = 4;
  double CoverageThreshold = 1e-3;
  double HeatMapScale = 0.1;
  double RMSE = 0, PSNR = 0, MaximumError = 0, Percentile99Error = 0;
  double CoveredRMSE = 0, CoveredPSNR = 0, CoveredMaximumError = 0, CoveredPercentile99Error = 0;
  vtkIdType NumberOfCoveredPixels = 0;
  vtkImageData* ErrorImage = nullptr;

private:
  vtkVolumeImageErrorMetrics(const vtkVolumeImageErrorMetrics&) = delete;
  void operator=(const vtkVolumeImageErrorMetrics&) = delete;
};

#endif
