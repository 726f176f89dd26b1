// Partial pre-integration (Moreland and Angel, 2004), free of VTK.
//
// On a ray segment of length D where extinction and colour are both linear (from tau_f, c_f at the
// front to tau_b, c_b at the back), the optical model of uvOpticalModel.h integrates to
//   zeta = exp(-D (tau_f + tau_b) / 2)                       (transmittance)
//   Psi  = (1/D) integral_0^D exp(-integral_0^t tau) dt      (mean transmittance)
//   C    = c_f (1 - Psi) + c_b (Psi - zeta),  A = 1 - zeta   (premultiplied colour, opacity)
// (integrate c tau exp(..) by parts). Psi depends on a = tau_f D and b = tau_b D alone:
//   Psi(a, b) = integral_0^1 exp(-(a u + (b - a) u^2 / 2)) du,
// tabulated over gamma = sqrt(x) / (1 + sqrt(x)) in [0, 1]^2. (Moreland and Angel use x / (1 + x);
// but where b grows large with a small, Psi ~ sqrt(pi / 2b), which is ~ sqrt(1 - gamma) in their
// coordinate, so bilinear reads near gamma_b = 1 err badly. In the square-root coordinate Psi is
// ~ (1 - gamma) / gamma there, and smooth at 0 too; TestPreIntegration bounds the read error.)
//
// A segment of a tetrahedron has a linear scalar, so extinction and colour are linear between the
// points where the scalar crosses a transfer-function node: cutting there makes the formula exact.
// IntegrateLinearScalarSegment is that algorithm on the CPU; the fragment shader
// (uvPreIntegratedTetrahedraFS.glsl) runs the same steps with the table as a texture.
#ifndef uvPreIntegration_h
#define uvPreIntegration_h

#include "uvOpticalModel.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace uv
{

/// Psi(a, b) by composite Gauss-Legendre on cells refined geometrically towards u = 0, where the
/// integrand falls fastest when a or b is large (checked against a fine quadrature in the tests).
inline double PsiExact(double a, double b)
{
  const double k = b - a;
  auto integrand = [a, k](double u) { return std::exp(-(a * u + 0.5 * k * u * u)); };
  // Beyond uEnd the integrand is below exp(-40).
  double uEnd = 1.0;
  const double rate = std::max(a, 0.0) + 1e-300;
  if (k >= 0.0)
  {
    // q(u) >= a u and q(u) >= k u^2 / 2.
    uEnd = std::min({ 1.0, 40.0 / rate, std::sqrt(80.0 / std::max(k, 1e-300)) });
  }
  else
  {
    // q(u) is concave; q(u) >= min over [0,1] of the chord, i.e. >= u * min(a, (a + b) / 2).
    uEnd = std::min(1.0, 40.0 / std::max(std::min(a, 0.5 * (a + b)), 1e-300));
  }
  // Geometric cells (ratio 0.6) from uEnd down to about uEnd * 1e-9, then one last cell to zero:
  // each cell is a few decay lengths wide at most, where 6-point Gauss-Legendre is exact to ~1e-13.
  double sum = 0.0;
  double hi = uEnd;
  constexpr int cells = 41;
  for (int cell = 0; cell < cells && hi > 0.0; ++cell)
  {
    const double lo = cell == cells - 1 ? 0.0 : hi * 0.6;
    const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
    for (std::size_t g = 0; g < detail::GaussNodes.size(); ++g)
    {
      sum += half * detail::GaussWeights[g] * integrand(mid + half * detail::GaussNodes[g]);
    }
    hi = lo;
  }
  return sum;
}

/// The table size the mapper uploads (a 2D float texture of this many texels squared).
constexpr int PsiTableSize = 512;

/// gamma = sqrt(x) / (1 + sqrt(x)): the table's coordinate for an optical depth x >= 0.
inline double PsiGamma(double opticalDepth)
{
  const double root = std::sqrt(opticalDepth);
  return root / (1.0 + root);
}

/// The Psi table: Size x Size samples at gamma_f = i / (Size - 1), gamma_b = j / (Size - 1), row j
/// (row-major, front index fastest), read back with bilinear interpolation like a GPU texture.
class PsiTable
{
public:
  explicit PsiTable(int size = PsiTableSize)
    : Size(size)
    , Values(static_cast<std::size_t>(size) * size)
  {
    for (int j = 0; j < size; ++j)
    {
      for (int i = 0; i < size; ++i)
      {
        this->Values[static_cast<std::size_t>(j) * size + i] =
          static_cast<float>(PsiExact(DepthOf(i), DepthOf(j)));
      }
    }
  }

  int GetSize() const { return this->Size; }
  const std::vector<float>& GetValues() const { return this->Values; }

  double Lookup(double frontDepth, double backDepth) const
  {
    const double x = PsiGamma(frontDepth) * (this->Size - 1), y = PsiGamma(backDepth) * (this->Size - 1);
    const int i = std::min(static_cast<int>(x), this->Size - 2), j = std::min(static_cast<int>(y), this->Size - 2);
    const double fx = x - i, fy = y - j;
    auto at = [this](int ii, int jj) { return static_cast<double>(this->Values[static_cast<std::size_t>(jj) * this->Size + ii]); };
    return (1 - fy) * ((1 - fx) * at(i, j) + fx * at(i + 1, j)) + fy * ((1 - fx) * at(i, j + 1) + fx * at(i + 1, j + 1));
  }

private:
  double DepthOf(int index) const
  {
    const double gamma = static_cast<double>(index) / (this->Size - 1);
    const double root = gamma / (1.0 - gamma);
    return gamma >= 1.0 ? 1e300 : root * root;
  }

  int Size;
  std::vector<float> Values;
};

/// The table every mapper reads: built once per process (its exact quadratures take a moment).
inline const PsiTable& SharedPsiTable()
{
  static const PsiTable table;
  return table;
}

/// Psi for small optical depths by its series (error below (a + b)^3 / 24), where a table read
/// would lose relative accuracy.
inline double PsiSeries(double a, double b)
{
  const double k = b - a;
  return 1.0 - (a / 2.0 + k / 6.0) + 0.5 * (a * a / 3.0 + a * k / 4.0 + k * k / 20.0);
}

/// Depth below which the fragment shader uses PsiSeries instead of the table.
constexpr double PsiSeriesLimit = 1e-2;

struct SegmentColor
{
  glm::dvec3 Color{ 0.0 }; ///< premultiplied
  double OpticalDepth = 0.0;
};

/// The pre-integrated colour of one linear piece; `psi` is Psi(a, b) by any of the routes above.
inline SegmentColor PreIntegratedPiece(
  const glm::dvec3& frontColor, double frontDepth, const glm::dvec3& backColor, double backDepth, double psi)
{
  const double depth = 0.5 * (frontDepth + backDepth);
  const double zeta = std::exp(-depth);
  return { frontColor * (1.0 - psi) + backColor * (psi - zeta), depth };
}

/// The exact integral of the optical model over a segment of `length` where the scalar runs
/// linearly from `frontScalar` to `backScalar`: cut at every transfer-function node in between,
/// each piece pre-integrated. `table` null: Psi exact (the reference); else the table, with the
/// series for small depths (what the GPU does).
inline void IntegrateLinearScalarSegment(const TransferFunction& tf, double frontScalar, double backScalar,
  double length, RayAccumulator& accumulator, const PsiTable* table = nullptr)
{
  if (!(length > 0.0))
  {
    return;
  }
  const auto& nodes = tf.GetNodes();
  std::vector<double> cuts;
  const double low = std::min(frontScalar, backScalar), high = std::max(frontScalar, backScalar);
  for (const auto& node : nodes)
  {
    if (node.Scalar > low && node.Scalar < high)
    {
      cuts.push_back(node.Scalar);
    }
  }
  if (backScalar < frontScalar)
  {
    std::reverse(cuts.begin(), cuts.end());
  }
  cuts.push_back(backScalar);
  const double span = backScalar - frontScalar;
  double previousFraction = 0.0;
  TransferFunction::Node previous = tf.Evaluate(frontScalar);
  for (double cut : cuts)
  {
    const double fraction = span != 0.0 ? (cut - frontScalar) / span : 1.0;
    const TransferFunction::Node next = tf.Evaluate(cut);
    const double pieceLength = length * (fraction - previousFraction);
    const double a = previous.Extinction * pieceLength, b = next.Extinction * pieceLength;
    const double psi = !table ? PsiExact(a, b) : (a + b < PsiSeriesLimit ? PsiSeries(a, b) : table->Lookup(a, b));
    const SegmentColor piece = PreIntegratedPiece(previous.Color, a, next.Color, b, psi);
    accumulator.Composite(piece.Color, piece.OpticalDepth);
    previous = next;
    previousFraction = fraction;
  }
}

/// The classic pre-integration table (Engel, Kraus and Ertl) for segments of one fixed `length`:
/// texel (i, j) holds the premultiplied colour and opacity (r, g, b, 1 - transmittance) of a segment
/// whose scalar runs linearly from i / (size - 1) to j / (size - 1), integrated exactly
/// (IntegrateLinearScalarSegment, exact Psi). Row-major, j the row. Read with bilinear filtering it
/// stands in for the whole walk when every segment has the same length (sampling at a fixed
/// distance); the unit test measures what the filtering costs. `forRows(count, function)` runs
/// function(row) for every row, in parallel if it likes.
template <typename ForRows>
std::vector<float> SegmentTable(const TransferFunction& tf, double length, int size, const ForRows& forRows)
{
  std::vector<float> texels(4 * static_cast<std::size_t>(size) * size);
  forRows(size, [&](int j) {
    for (int i = 0; i < size; ++i)
    {
      RayAccumulator segment;
      IntegrateLinearScalarSegment(
        tf, static_cast<double>(i) / (size - 1), static_cast<double>(j) / (size - 1), length, segment);
      float* texel = &texels[4 * (static_cast<std::size_t>(j) * size + i)];
      texel[0] = static_cast<float>(segment.Color.r);
      texel[1] = static_cast<float>(segment.Color.g);
      texel[2] = static_cast<float>(segment.Color.b);
      texel[3] = static_cast<float>(segment.Opacity());
    }
  });
  return texels;
}

inline std::vector<float> SegmentTable(const TransferFunction& tf, double length, int size)
{
  return SegmentTable(tf, length, size, [](int count, const auto& function) {
    for (int row = 0; row < count; ++row)
      function(row);
  });
}

/// `table` (a SegmentTable of `size` squared texels) read at front scalar sf and back scalar sb as a
/// GPU's bilinear filter reads it: premultiplied (r, g, b) and opacity.
inline std::array<double, 4> ReadSegmentTable(const std::vector<float>& table, int size, double sf, double sb)
{
  const auto texel = [&](int i, int j, int c) { return static_cast<double>(table[4 * (j * size + i) + c]); };
  const double x = std::min(std::max(sf, 0.0), 1.0) * (size - 1), y = std::min(std::max(sb, 0.0), 1.0) * (size - 1);
  const int i = std::min(static_cast<int>(x), size - 2), j = std::min(static_cast<int>(y), size - 2);
  const double fx = x - i, fy = y - j;
  std::array<double, 4> read{};
  for (int c = 0; c < 4; ++c)
    read[c] = (1 - fy) * ((1 - fx) * texel(i, j, c) + fx * texel(i + 1, j, c)) +
      fy * ((1 - fx) * texel(i, j + 1, c) + fx * texel(i + 1, j + 1, c));
  return read;
}

/// The largest difference in any channel between `table` read bilinearly and the exact segment of
/// `length`, over `samples` pairs of scalars (a fixed pseudo-random set, so the answer repeats): what
/// the table costs in accuracy for this transfer function, measured rather than guessed from it.
inline double SegmentTableError(
  const TransferFunction& tf, double length, const std::vector<float>& table, int size, int samples)
{
  std::mt19937 random(9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (int n = 0; n < samples; ++n)
  {
    const double sf = unit(random), sb = unit(random);
    RayAccumulator exact;
    IntegrateLinearScalarSegment(tf, sf, sb, length, exact);
    const double expected[4] = { exact.Color.r, exact.Color.g, exact.Color.b, exact.Opacity() };
    const std::array<double, 4> read = ReadSegmentTable(table, size, sf, sb);
    for (int c = 0; c < 4; ++c)
      worst = std::max(worst, std::abs(read[c] - expected[c]));
  }
  return worst;
}

/// The narrowest gap between transfer-function nodes (infinity for one node): features narrower
/// than a few texels of a SegmentTable are blurred by its bilinear reads.
inline double NarrowestNodeGap(const std::vector<TransferFunction::Node>& nodes)
{
  double gap = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < nodes.size(); ++k)
    gap = std::min(gap, nodes[k].Scalar - nodes[k - 1].Scalar);
  return gap;
}

} // namespace uv

#endif
