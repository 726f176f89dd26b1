// Error of an image against a reference, free of VTK: RMSE, PSNR, maximum and 99th-percentile absolute
// error over premultiplied RGBA in [0, 1], over all pixels and over the pixels the volume covers.
#ifndef uvImageErrorMetrics_h
#define uvImageErrorMetrics_h

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace uv
{

struct ErrorSummary
{
  double RMSE = 0.0;
  double PSNR = std::numeric_limits<double>::infinity(); // 20 log10(1 / RMSE)
  double Maximum = 0.0;                                 // largest absolute channel error
  double Percentile99 = 0.0;                            // of the per-pixel largest channel error
  std::size_t Pixels = 0;
};

struct ErrorMetrics
{
  ErrorSummary All;
  ErrorSummary Covered; // pixels where either image has opacity above the coverage threshold
  std::vector<double> PixelError; // largest absolute channel error of each pixel
};

/// Both images hold `pixels` tuples of `stride` floats (RGBA = 4); the first `channels` of them are
/// compared (4 for RGBA, 3 when the candidate has no meaningful alpha). Coverage uses channel 3 when
/// `stride` >= 4.
template <typename T, typename U>
ErrorMetrics CompareImages(const T* candidate, const U* reference, std::size_t pixels, int stride,
  int channels, double coverageThreshold = 1e-3)
{
  ErrorMetrics metrics;
  metrics.PixelError.resize(pixels);
  std::vector<double> allErrors, coveredErrors;
  double sumAll = 0.0, sumCovered = 0.0;
  for (std::size_t i = 0; i < pixels; ++i)
  {
    double worst = 0.0, squares = 0.0;
    for (int c = 0; c < channels; ++c)
    {
      const double d = static_cast<double>(candidate[stride * i + c]) - static_cast<double>(reference[stride * i + c]);
      worst = std::max(worst, std::abs(d));
      squares += d * d;
    }
    metrics.PixelError[i] = worst;
    sumAll += squares;
    allErrors.push_back(worst);
    const bool covered = stride >= 4 &&
      std::max(static_cast<double>(candidate[stride * i + 3]), static_cast<double>(reference[stride * i + 3])) >
        coverageThreshold;
    if (covered)
    {
      sumCovered += squares;
      coveredErrors.push_back(worst);
    }
  }
  auto summarize = [channels](double sum, std::vector<double>& errors) {
    ErrorSummary summary;
    summary.Pixels = errors.size();
    if (errors.empty())
    {
      return summary;
    }
    summary.RMSE = std::sqrt(sum / (static_cast<double>(errors.size()) * channels));
    summary.PSNR = summary.RMSE > 0.0 ? 20.0 * std::log10(1.0 / summary.RMSE)
                                      : std::numeric_limits<double>::infinity();
    summary.Maximum = *std::max_element(errors.begin(), errors.end());
    const std::size_t rank =
      std::min(errors.size() - 1, static_cast<std::size_t>(std::ceil(0.99 * errors.size())) - 1);
    std::nth_element(errors.begin(), errors.begin() + rank, errors.end());
    summary.Percentile99 = errors[rank];
    return summary;
  };
  metrics.All = summarize(sumAll, allErrors);
  metrics.Covered = summarize(sumCovered, coveredErrors);
  return metrics;
}

/// Heat-map colour of an error in [0, scale]: black, red, yellow, white.
inline void HeatColor(double error, double scale, unsigned char rgb[3])
{
  const double x = std::min(std::max(error / scale, 0.0), 1.0) * 3.0;
  rgb[0] = static_cast<unsigned char>(std::lround(255.0 * std::min(x, 1.0)));
  rgb[1] = static_cast<unsigned char>(std::lround(255.0 * std::min(std::max(x - 1.0, 0.0), 1.0)));
  rgb[2] = static_cast<unsigned char>(std::lround(255.0 * std::min(std::max(x - 2.0, 0.0), 1.0)));
}

} // namespace uv

#endif
