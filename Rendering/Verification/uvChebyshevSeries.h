// Chebyshev interpolation of a smooth function on an interval, free of VTK. The reference renderer
// fits the scalar along a ray inside a hexahedron (an inverse-trilinear solve per sample) once per
// segment and then integrates the cheap series; the fit certifies itself by its tail coefficients.
#ifndef uvChebyshevSeries_h
#define uvChebyshevSeries_h

#include <array>
#include <cmath>

namespace uv
{

class ChebyshevSeries
{
public:
  static constexpr int Degree = 16;

  /// Interpolates f at the Chebyshev points of [a, b]. Returns false when the last three
  /// coefficients exceed `tolerance` (the function is not resolved; do not use the series).
  template <typename Function>
  bool Fit(const Function& f, double a, double b, double tolerance)
  {
    const double pi = 3.14159265358979323846;
    this->Low = a;
    this->High = b;
    std::array<double, Degree + 1> samples;
    for (int k = 0; k <= Degree; ++k)
    {
      const double x = std::cos(pi * k / Degree);
      samples[k] = f(0.5 * (a + b) + 0.5 * (b - a) * x);
    }
    // Coefficients of the interpolant through the Chebyshev-Lobatto points (a type-I DCT).
    for (int j = 0; j <= Degree; ++j)
    {
      double sum = 0.0;
      for (int k = 0; k <= Degree; ++k)
      {
        const double weight = (k == 0 || k == Degree) ? 0.5 : 1.0;
        sum += weight * samples[k] * std::cos(pi * j * k / Degree);
      }
      this->Coefficients[j] = sum * 2.0 / Degree * ((j == 0 || j == Degree) ? 0.5 : 1.0);
    }
    double tail = 0.0;
    for (int j = Degree - 2; j <= Degree; ++j)
    {
      tail = std::max(tail, std::abs(this->Coefficients[j]));
    }
    return tail <= tolerance;
  }

  /// The series at t (Clenshaw's recurrence).
  double operator()(double t) const
  {
    const double x = (2.0 * t - this->Low - this->High) / (this->High - this->Low);
    double b1 = 0.0, b2 = 0.0;
    for (int j = Degree; j >= 1; --j)
    {
      const double b0 = 2.0 * x * b1 - b2 + this->Coefficients[j];
      b2 = b1;
      b1 = b0;
    }
    return x * b1 - b2 + this->Coefficients[0];
  }

private:
  double Low = 0.0, High = 1.0;
  std::array<double, Degree + 1> Coefficients{};
};

} // namespace uv

#endif
