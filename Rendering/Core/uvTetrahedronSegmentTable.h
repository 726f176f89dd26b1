// A pre-integration table for segments of any length up to a tetrahedron's diameter, free of VTK:
// texel (i, j, k) holds the premultiplied colour and opacity of the segment whose scalar runs
// linearly from i / (S - 1) to j / (S - 1) over the k-th of L lengths from 0 to MaxLength, integrated
// like the fragment shader's exact walk (cut at every node, each piece pre-integrated). The lengths
// are spaced evenly in log(1 + length / LengthScale), LengthScale the length over which the densest
// node reaches optical depth 1: opacity changes fastest over short segments and hardly at all once
// a segment is opaque, so dense media (long cells, short unit distances) need their texels short. Read with
// trilinear filtering it replaces that walk with one texture read, whatever the number of nodes;
// what the filtering costs is measured against the exact segments when the table is built, so the
// mapper uses it only where that error is within its tolerance.
//
// A segment through a tetrahedron is never longer than its longest edge (the diameter of a convex
// hull of four points), so MaxLength = the longest edge bounds the length axis.
#ifndef uvTetrahedronSegmentTable_h
#define uvTetrahedronSegmentTable_h

#include "uvOpticalModel.h"
#include "uvPreIntegration.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace uv
{

struct TetrahedronSegmentTable
{
  int ScalarSize = 0;      ///< texels along each scalar axis
  int LengthSize = 0;      ///< texels along the length axis
  double MaxLength = 0.0;  ///< the length of the last texel
  double LengthScale = 1.0; ///< lengths are spaced evenly in log(1 + length / LengthScale)
  std::vector<float> Texels; ///< RGBA, front scalar fastest, then back scalar, then length

  /// The texture coordinate (in [0, 1], texel centres at the ends) of normalised scalar `s`.
  double ScalarCoordinate(double s) const
  {
    return (std::min(std::max(s, 0.0), 1.0) * (this->ScalarSize - 1) + 0.5) / this->ScalarSize;
  }

  /// log(1 + MaxLength / LengthScale): the length axis's extent in its warped coordinate.
  double LengthWarp() const { return std::log1p(this->MaxLength / this->LengthScale); }

  /// The texture coordinate of segment `length`.
  double LengthCoordinate(double length) const
  {
    const double x = this->MaxLength > 0.0
      ? std::min(std::max(std::log1p(std::max(length, 0.0) / this->LengthScale) / this->LengthWarp(), 0.0), 1.0)
      : 0.0;
    return (x * (this->LengthSize - 1) + 0.5) / this->LengthSize;
  }

  /// The length texel k holds.
  double LengthAt(int k) const
  {
    if (k >= this->LengthSize - 1)
      return this->MaxLength;
    return this->LengthScale * std::expm1(this->LengthWarp() * k / (this->LengthSize - 1));
  }

  /// The table read at (sf, sb, length) as a GPU's trilinear filter reads it: premultiplied
  /// (r, g, b) and opacity.
  std::array<double, 4> Read(double sf, double sb, double length) const
  {
    const double x = this->ScalarCoordinate(sf) * this->ScalarSize - 0.5;
    const double y = this->ScalarCoordinate(sb) * this->ScalarSize - 0.5;
    const double z = this->LengthCoordinate(length) * this->LengthSize - 0.5;
    const int i = std::min(static_cast<int>(x), this->ScalarSize - 2);
    const int j = std::min(static_cast<int>(y), this->ScalarSize - 2);
    const int k = std::min(static_cast<int>(z), this->LengthSize - 2);
    const double w[3] = { x - i, y - j, z - k };
    std::array<double, 4> read{};
    for (int corner = 0; corner < 8; ++corner)
    {
      const int di = corner & 1, dj = (corner >> 1) & 1, dk = (corner >> 2) & 1;
      const double weight = (di ? w[0] : 1 - w[0]) * (dj ? w[1] : 1 - w[1]) * (dk ? w[2] : 1 - w[2]);
      const float* texel = &this->Texels[this->Index(i + di, j + dj, k + dk)];
      for (int c = 0; c < 4; ++c)
        read[c] += weight * texel[c];
    }
    return read;
  }

  std::size_t Index(int i, int j, int k) const
  {
    return 4 * ((static_cast<std::size_t>(k) * this->ScalarSize + j) * this->ScalarSize + i);
  }
};

/// The pieces of the segment from `frontScalar` to `backScalar` between its cuts at the nodes: each
/// piece's share of the length and the transfer function at its two ends.
struct SegmentPieces
{
  std::vector<double> Shares;
  std::vector<TransferFunction::Node> Ends; ///< Shares.size() + 1 of them

  SegmentPieces(const TransferFunction& tf, double frontScalar, double backScalar)
  {
    const double low = std::min(frontScalar, backScalar), high = std::max(frontScalar, backScalar);
    std::vector<double> cuts;
    for (const auto& node : tf.GetNodes())
      if (node.Scalar > low && node.Scalar < high)
        cuts.push_back(node.Scalar);
    if (backScalar < frontScalar)
      std::reverse(cuts.begin(), cuts.end());
    cuts.push_back(backScalar);
    const double span = backScalar - frontScalar;
    double previous = 0.0;
    this->Ends.push_back(tf.Evaluate(frontScalar));
    for (double cut : cuts)
    {
      const double fraction = span != 0.0 ? (cut - frontScalar) / span : 1.0;
      this->Shares.push_back(fraction - previous);
      this->Ends.push_back(tf.Evaluate(cut));
      previous = fraction;
    }
  }

  /// The segment integrated over `length`, Psi read from `psi` (the fragment shader's route).
  RayAccumulator Integrate(double length, const PsiTable& psi) const
  {
    RayAccumulator segment;
    for (std::size_t p = 0; p < this->Shares.size(); ++p)
    {
      const double pieceLength = length * this->Shares[p];
      const double a = this->Ends[p].Extinction * pieceLength, b = this->Ends[p + 1].Extinction * pieceLength;
      if (!(a + b > 0.0))
        continue;
      const double value = a + b < PsiSeriesLimit ? PsiSeries(a, b) : psi.Lookup(a, b);
      const SegmentColor piece = PreIntegratedPiece(this->Ends[p].Color, a, this->Ends[p + 1].Color, b, value);
      segment.Composite(piece.Color, piece.OpticalDepth);
    }
    return segment;
  }
};

/// The table of `tf` for lengths up to `maxLength`, `scalarSize` texels per scalar axis and
/// `lengthSize` along the length. `forRows(count, function)` runs function(row) for every row (a
/// pair of front and back scalars), in parallel if it likes.
template <typename ForRows>
TetrahedronSegmentTable MakeTetrahedronSegmentTable(const TransferFunction& tf, double maxLength, int scalarSize,
  int lengthSize, const PsiTable& psi, const ForRows& forRows)
{
  TetrahedronSegmentTable table;
  table.ScalarSize = scalarSize;
  table.LengthSize = lengthSize;
  table.MaxLength = maxLength;
  // Optical depth 1 at the densest node, kept within [1e-4, 1] of the longest: a fully transparent
  // function spaces the lengths nearly evenly, and the warp stays small enough for float shaders.
  double densest = 0.0;
  for (const auto& node : tf.GetNodes())
    densest = std::max(densest, node.Extinction);
  table.LengthScale = densest > 0.0 ? std::min(std::max(1.0 / densest, 1e-4 * maxLength), maxLength) : maxLength;
  if (!(table.LengthScale > 0.0))
    table.LengthScale = 1.0; // no extent: every length reads texel 0
  table.Texels.resize(4 * static_cast<std::size_t>(scalarSize) * scalarSize * lengthSize);
  forRows(scalarSize * scalarSize, [&](int row) {
    const int i = row % scalarSize, j = row / scalarSize;
    const SegmentPieces pieces(tf, static_cast<double>(i) / (scalarSize - 1), static_cast<double>(j) / (scalarSize - 1));
    for (int k = 0; k < lengthSize; ++k)
    {
      const RayAccumulator segment = pieces.Integrate(table.LengthAt(k), psi);
      float* texel = &table.Texels[table.Index(i, j, k)];
      texel[0] = static_cast<float>(segment.Color.r);
      texel[1] = static_cast<float>(segment.Color.g);
      texel[2] = static_cast<float>(segment.Color.b);
      texel[3] = static_cast<float>(segment.Opacity());
    }
  });
  return table;
}

/// The largest difference in any channel between `table` read trilinearly and the exact segment
/// (exact Psi), over `samples` segments of random scalars and lengths up to the table's (a fixed
/// pseudo-random set, so the answer repeats).
inline double TetrahedronSegmentTableError(const TransferFunction& tf, const TetrahedronSegmentTable& table, int samples)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (int n = 0; n < samples; ++n)
  {
    const double sf = unit(random), sb = unit(random), length = table.MaxLength * unit(random);
    RayAccumulator exact;
    IntegrateLinearScalarSegment(tf, sf, sb, length, exact);
    const double expected[4] = { exact.Color.r, exact.Color.g, exact.Color.b, exact.Opacity() };
    const std::array<double, 4> read = table.Read(sf, sb, length);
    for (int c = 0; c < 4; ++c)
      worst = std::max(worst, std::abs(read[c] - expected[c]));
  }
  return worst;
}

/// The longest squared edge of tetrahedra [begin, end) of `tetrahedronPoints` (4 ids each), whose
/// points are (x, y, z, scalar) in `pointData`.
inline double LongestSquaredEdge(
  const std::vector<float>& pointData, const std::vector<std::uint32_t>& tetrahedronPoints, std::size_t begin, std::size_t end)
{
  double longest = 0.0;
  for (std::size_t t = begin; t < end; ++t)
  {
    const std::uint32_t* ids = &tetrahedronPoints[4 * t];
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
      {
        const float* p = &pointData[4 * static_cast<std::size_t>(ids[a])];
        const float* q = &pointData[4 * static_cast<std::size_t>(ids[b])];
        const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
        longest = std::max(longest, dx * dx + dy * dy + dz * dz);
      }
  }
  return longest;
}

/// The most `linear` stretches any length (its largest singular value), by power iteration on
/// its transpose times itself: a length in model space is at most this times longer in eye space.
inline double LargestStretch(const glm::dmat3& linear)
{
  const glm::dmat3 square = glm::transpose(linear) * linear;
  glm::dvec3 v(1.0, 0.7, 0.3);
  double value = 0.0;
  for (int iteration = 0; iteration < 64; ++iteration)
  {
    const glm::dvec3 next = square * v;
    const double length = glm::length(next);
    if (!(length > 0.0))
      return 0.0;
    value = length / glm::length(v);
    v = next / length;
  }
  return std::sqrt(value);
}

} // namespace uv

#endif
