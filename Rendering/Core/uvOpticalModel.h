// The project's optical model, free of VTK: emission-absorption with colour and extinction
// piecewise linear in the scalar, and the exact integral of it along a ray segment.
//
// Along a ray, with scalar s(t), extinction tau(s) and colour c(s):
//   premultiplied colour  C = integral c(s(t)) tau(s(t)) exp(-integral_0^t tau) dt
//   opacity               A = 1 - exp(-integral tau dt)
// composited front to back over a transparent background. A vtkVolumeProperty maps to it as:
// each opacity node alpha at unit distance d gives tau = -ln(1 - alpha) / d (alpha is clamped below
// 1 - 1e-9 so tau stays finite); tau and colour are linear in s between the union of the colour and
// opacity nodes, and constant beyond the first and last node.
#ifndef uvOpticalModel_h
#define uvOpticalModel_h

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace uv
{

/// Extinction coefficient of an opacity `alpha` reached over `unitDistance`.
inline double ExtinctionFromOpacity(double alpha, double unitDistance)
{
  const double clamped = std::min(std::max(alpha, 0.0), 1.0 - 1e-9);
  return -std::log1p(-clamped) / unitDistance;
}

/// Colour and extinction, linear in the scalar between nodes, constant outside them.
class TransferFunction
{
public:
  struct Node
  {
    double Scalar;
    glm::dvec3 Color;
    double Extinction;

    bool operator==(const Node& other) const
    {
      return this->Scalar == other.Scalar && this->Color == other.Color && this->Extinction == other.Extinction;
    }
    bool operator!=(const Node& other) const { return !(*this == other); }
  };

  /// Nodes must be sorted by scalar, with distinct scalars; at least one.
  explicit TransferFunction(std::vector<Node> nodes)
    : Nodes(std::move(nodes))
  {
  }

  const std::vector<Node>& GetNodes() const { return this->Nodes; }

  /// Index i such that Nodes[i].Scalar <= s < Nodes[i+1].Scalar; -1 below, size-1 above.
  int Segment(double s) const
  {
    const auto above = std::upper_bound(this->Nodes.begin(), this->Nodes.end(), s,
      [](double value, const Node& node) { return value < node.Scalar; });
    return static_cast<int>(above - this->Nodes.begin()) - 1;
  }

  double Extinction(double s) const { return this->Evaluate(s).Extinction; }
  glm::dvec3 Color(double s) const { return this->Evaluate(s).Color; }

  Node Evaluate(double s) const
  {
    const int i = this->Segment(s);
    if (i < 0)
    {
      return { s, this->Nodes.front().Color, this->Nodes.front().Extinction };
    }
    if (i >= static_cast<int>(this->Nodes.size()) - 1)
    {
      return { s, this->Nodes.back().Color, this->Nodes.back().Extinction };
    }
    const Node& a = this->Nodes[i];
    const Node& b = this->Nodes[i + 1];
    const double w = (s - a.Scalar) / (b.Scalar - a.Scalar);
    return { s, a.Color + w * (b.Color - a.Color), a.Extinction + w * (b.Extinction - a.Extinction) };
  }

  /// True when every node's extinction is zero: nothing to see at all.
  bool IsInvisible() const
  {
    return std::all_of(this->Nodes.begin(), this->Nodes.end(), [](const Node& n) { return n.Extinction <= 0.0; });
  }

private:
  std::vector<Node> Nodes;
};

/// Front-to-back compositing of premultiplied colour and optical depth.
struct RayAccumulator
{
  glm::dvec3 Color{ 0.0 };
  double Transmittance = 1.0;

  void Composite(const glm::dvec3& premultipliedColor, double opticalDepth)
  {
    this->Color += this->Transmittance * premultipliedColor;
    this->Transmittance *= std::exp(-opticalDepth);
  }
  double Opacity() const { return 1.0 - this->Transmittance; }
};

/// What the medium holds at a point: extinction and emitted premultiplied light (extinction times
/// colour). Where cells overlap, their media add.
struct Medium
{
  double Extinction = 0.0;
  glm::dvec3 Emission{ 0.0 };
};

namespace detail
{
// 6-point Gauss-Legendre on [-1, 1]: exact for polynomials up to degree 11.
constexpr std::array<double, 6> GaussNodes = { -0.9324695142031520278, -0.6612093864662645137,
  -0.2386191860831969086, 0.2386191860831969086, 0.6612093864662645137, 0.9324695142031520278 };
constexpr std::array<double, 6> GaussWeights = { 0.1713244923791703450, 0.3607615730481386076,
  0.4679139345726910474, 0.4679139345726910474, 0.3607615730481386076, 0.1713244923791703450 };

struct PieceIntegral
{
  glm::dvec3 Color{ 0.0 };
  double Depth = 0.0;
};

/// Optical depth and premultiplied colour of [a, b] by nested Gauss-Legendre, where the medium is
/// smooth (no scalar crosses a transfer-function node).
template <typename MediumAt>
PieceIntegral GaussPiece(const MediumAt& mediumAt, double a, double b)
{
  PieceIntegral result;
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  for (std::size_t k = 0; k < GaussNodes.size(); ++k)
  {
    const double t = mid + half * GaussNodes[k];
    const Medium here = mediumAt(t);
    // Optical depth from a to t, by the same rule on [a, t].
    double inner = 0.0;
    const double innerHalf = 0.5 * (t - a), innerMid = 0.5 * (a + t);
    for (std::size_t j = 0; j < GaussNodes.size(); ++j)
    {
      inner += GaussWeights[j] * mediumAt(innerMid + innerHalf * GaussNodes[j]).Extinction;
    }
    inner *= innerHalf;
    result.Depth += GaussWeights[k] * here.Extinction;
    result.Color += GaussWeights[k] * std::exp(-inner) * here.Emission;
  }
  result.Depth *= half;
  result.Color *= half;
  return result;
}

inline double Difference(const PieceIntegral& x, const PieceIntegral& y)
{
  const glm::dvec3 d = glm::abs(x.Color - y.Color);
  return std::max({ std::abs(x.Depth - y.Depth), d.x, d.y, d.z });
}

/// Gauss-Legendre integrates exp(-depth) well only over pieces of small optical depth: a denser piece
/// is bisected even where its halves agree, or the thin layer in front where all its light comes from
/// falls between the nodes (an opaque medium came out black).
constexpr double MaximumPieceDepth = 0.25;

/// A piece too short to bisect further: its medium taken as constant, the colour of its front.
template <typename MediumAt>
void CompositeConstantPiece(const MediumAt& mediumAt, double a, const PieceIntegral& whole, RayAccumulator& accumulator)
{
  const Medium front = mediumAt(a);
  const glm::dvec3 color = front.Extinction > 0.0 ? front.Emission / front.Extinction : glm::dvec3(0.0);
  accumulator.Composite(color * -std::expm1(-whole.Depth), whole.Depth);
}

/// Adaptive bisection until whole and halves agree within `tolerance` and each piece is thin
/// (MaximumPieceDepth); composited in order, left first, so that what lies behind a piece that
/// made the ray opaque (to within a thousandth of the tolerance) is never integrated: an opaque
/// medium costs the bisections down to its front layer, not its whole length.
/// `budget` bounds the bisections of one segment: a scalar that never resolves (a cell so distorted
/// its inverse map fails) costs at most that many, not 2^depth.
template <typename MediumAt>
void AdaptivePiece(const MediumAt& mediumAt, double a, double b, const PieceIntegral& whole,
  double tolerance, int depth, int& budget, RayAccumulator& accumulator)
{
  if (accumulator.Transmittance <= 1e-3 * tolerance)
  {
    return;
  }
  const double m = 0.5 * (a + b);
  if (depth >= 80 || !(m > a && m < b))
  {
    CompositeConstantPiece(mediumAt, a, whole, accumulator);
    return;
  }
  const PieceIntegral left = GaussPiece(mediumAt, a, m);
  const PieceIntegral right = GaussPiece(mediumAt, m, b);
  PieceIntegral halves;
  halves.Depth = left.Depth + right.Depth;
  halves.Color = left.Color + std::exp(-left.Depth) * right.Color;
  const bool resolved = whole.Depth <= MaximumPieceDepth && Difference(whole, halves) <= tolerance;
  if (resolved || --budget <= 0)
  {
    accumulator.Composite(left.Color, left.Depth);
    accumulator.Composite(right.Color, right.Depth);
    return;
  }
  AdaptivePiece(mediumAt, a, m, left, 0.5 * tolerance, depth + 1, budget, accumulator);
  AdaptivePiece(mediumAt, m, b, right, 0.5 * tolerance, depth + 1, budget, accumulator);
}

/// Appends to `cuts` the t in (t0, t1) where s(t) crosses a transfer-function node (found between
/// `probes` samples, refined by bisection), then t1.
template <typename ScalarAt>
void AppendNodeCrossings(const TransferFunction& tf, const ScalarAt& scalarAt, double t0, double t1,
  int probes, std::vector<double>& cuts)
{
  double previousT = t0, previousS = scalarAt(t0);
  for (int i = 1; i <= probes; ++i)
  {
    const double t = t0 + (t1 - t0) * i / probes;
    const double s = scalarAt(t);
    const double low = std::min(previousS, s), high = std::max(previousS, s);
    const std::size_t first = cuts.size();
    for (const TransferFunction::Node& node : tf.GetNodes())
    {
      if (node.Scalar > low && node.Scalar < high)
      {
        double a = previousT, b = t;
        const bool rising = s > previousS;
        for (int iteration = 0; iteration < 60 && b - a > 1e-15 * (1.0 + std::abs(b)); ++iteration)
        {
          const double m = 0.5 * (a + b);
          ((scalarAt(m) < node.Scalar) == rising ? a : b) = m;
        }
        cuts.push_back(0.5 * (a + b));
      }
    }
    std::sort(cuts.begin() + first, cuts.end());
    cuts.push_back(t);
    previousT = t;
    previousS = s;
  }
}

/// Integrates a medium smooth between consecutive `cuts` and composites it into `accumulator`.
template <typename MediumAt>
void IntegrateBetweenCuts(const MediumAt& mediumAt, const std::vector<double>& cuts, double tolerance,
  RayAccumulator& accumulator)
{
  const double pieceTolerance = tolerance / static_cast<double>(std::max<std::size_t>(cuts.size(), 1));
  int budget = 4096; // bisections for the whole segment; far above what smooth integrands need
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
  {
    if (cuts[i + 1] > cuts[i])
    {
      const PieceIntegral whole = GaussPiece(mediumAt, cuts[i], cuts[i + 1]);
      AdaptivePiece(mediumAt, cuts[i], cuts[i + 1], whole, pieceTolerance, 0, budget, accumulator);
    }
  }
}
} // namespace detail

/// Integrates the optical model along t in [t0, t1] for a smooth scalar s(t) (linear in a tet,
/// isoparametric in a hexahedron) and composites it into `accumulator`. The segment is first cut
/// where s crosses a transfer-function node, then each piece is integrated adaptively to an
/// absolute error below `tolerance`.
template <typename ScalarAt>
void IntegrateSegment(const TransferFunction& tf, const ScalarAt& scalarAt, double t0, double t1,
  double tolerance, RayAccumulator& accumulator, int probes = 8)
{
  if (!(t1 > t0))
  {
    return;
  }
  std::vector<double> cuts = { t0 };
  detail::AppendNodeCrossings(tf, scalarAt, t0, t1, probes, cuts);
  const auto mediumAt = [&](double t) {
    const TransferFunction::Node node = tf.Evaluate(scalarAt(t));
    return Medium{ node.Extinction, node.Extinction * node.Color };
  };
  detail::IntegrateBetweenCuts(mediumAt, cuts, tolerance, accumulator);
}

/// The same where several cells overlap on [t0, t1] (tangled or overlapping cells): the medium is
/// their superposition, each cell adding its own extinction and emission, so the result does not
/// depend on the cells' order. Cut at every cell's node crossings.
template <typename ScalarAt>
void IntegrateOverlap(const TransferFunction& tf, const std::vector<ScalarAt>& scalarsAt, double t0,
  double t1, double tolerance, RayAccumulator& accumulator, int probes = 8)
{
  if (!(t1 > t0))
  {
    return;
  }
  std::vector<double> cuts = { t0 };
  for (const ScalarAt& scalarAt : scalarsAt)
  {
    detail::AppendNodeCrossings(tf, scalarAt, t0, t1, probes, cuts);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  const auto mediumAt = [&](double t) {
    Medium sum;
    for (const ScalarAt& scalarAt : scalarsAt)
    {
      const TransferFunction::Node node = tf.Evaluate(scalarAt(t));
      sum.Extinction += node.Extinction;
      sum.Emission += node.Extinction * node.Color;
    }
    return sum;
  };
  detail::IntegrateBetweenCuts(mediumAt, cuts, tolerance, accumulator);
}

} // namespace uv

#endif
