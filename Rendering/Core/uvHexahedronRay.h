// The exact trilinear field along a ray through a hexahedron, and its ray integral, free of VTK:
// the math of vtkHexahedralRayCastMapper (Miranda and Celes), checked alone by the unit tests.
//
// Frame. Miranda and Celes fit f = c0 + c1 x + ... + c7 xyz in world coordinates, which is exact only
// for axis-aligned boxes and whose 8x8 system is singular for some valid cells (a cube rotated 45
// degrees about an axis). Here the field stays in the cell's own trilinear coordinates xi in
// [0,1]^3, and a ray is mapped into them by the cell's affine frame (centre and averaged edge
// vectors). For every parallelepiped, in any orientation, the frame is the cell's exact map, so
// xi is affine along the ray and f is exactly a cubic in the ray parameter; the frame's 3x3 matrix
// is well conditioned for every cell that is not itself nearly flat. For curved or twisted cells the
// frame is an approximation of the isoparametric map; the tests and the benchmark measure that error.
//
// Integral. Between the ray's split points -- the cubic's extrema (roots of f') and the points where
// it crosses a transfer-function node, found per monotonic interval by safeguarded Newton -- the
// extinction and colour are cubics in the ray parameter (the transfer function is linear there), so
// the optical depth is an exact quartic and the colour integral is smooth:
//   Accurate     Gauss-Legendre per piece (pieces subdivided to optical depth <= 1/4), exact depth;
//   Fast         the scalar taken linear between split points, each piece pre-integrated (Psi);
//   FixedSteps   N equal steps per cell at the midpoint scalar (the paper's Hexa_CONST).
#ifndef uvHexahedronRay_h
#define uvHexahedronRay_h

#include "uvOpticalModel.h"
#include "uvPreIntegration.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace uv
{

/// A hexahedron's affine frame: x = Origin + Axes * xi, corners in VTK's order (corner k at
/// xi = HexahedronCorners[k] of uvRayCellGeometry.h: 0 (0,0,0), 1 (1,0,0), 2 (1,1,0), 3 (0,1,0),
/// then 4-7 the same at t = 1).
struct HexahedronFrame
{
  glm::dvec3 Origin;
  glm::dmat3 Axes;
  glm::dmat3 Inverse;
};

inline HexahedronFrame MakeHexahedronFrame(const glm::dvec3 p[8])
{
  // Edges along r: 0-1, 3-2, 4-5, 7-6; along s: 0-3, 1-2, 4-7, 5-6; along t: 0-4, 1-5, 2-6, 3-7.
  const glm::dvec3 r = 0.25 * ((p[1] - p[0]) + (p[2] - p[3]) + (p[5] - p[4]) + (p[6] - p[7]));
  const glm::dvec3 s = 0.25 * ((p[3] - p[0]) + (p[2] - p[1]) + (p[7] - p[4]) + (p[6] - p[5]));
  const glm::dvec3 t = 0.25 * ((p[4] - p[0]) + (p[5] - p[1]) + (p[6] - p[2]) + (p[7] - p[3]));
  glm::dvec3 centre(0.0);
  for (int k = 0; k < 8; ++k)
  {
    centre += 0.125 * p[k];
  }
  HexahedronFrame frame;
  frame.Axes = glm::dmat3(r, s, t);
  frame.Origin = centre - 0.5 * (r + s + t);
  frame.Inverse = glm::inverse(frame.Axes);
  return frame;
}

/// Whether the cell's trilinear map folds over itself: its Jacobian determinant takes both signs
/// over the corners and the centre (where it is extreme for most cells). Zeros, as at a collapsed
/// edge, do not count. A ray through such a cell may meet a face several times either way, and
/// overlapping neighbours: the reference takes the cell's parts by Newton from its centre and adds
/// overlapping cells' media; the hexahedral walk takes the parts alike and adds the media of the
/// cells it overlaps (uvOverlappingCells.h).
inline bool IsTangledHexahedron(const glm::dvec3 p[8])
{
  auto determinant = [p](double r, double s, double t) {
    const glm::dvec3 dr = (1 - s) * (1 - t) * (p[1] - p[0]) + s * (1 - t) * (p[2] - p[3]) +
      (1 - s) * t * (p[5] - p[4]) + s * t * (p[6] - p[7]);
    const glm::dvec3 ds = (1 - r) * (1 - t) * (p[3] - p[0]) + r * (1 - t) * (p[2] - p[1]) +
      (1 - r) * t * (p[7] - p[4]) + r * t * (p[6] - p[5]);
    const glm::dvec3 dt = (1 - r) * (1 - s) * (p[4] - p[0]) + r * (1 - s) * (p[5] - p[1]) +
      r * s * (p[6] - p[2]) + (1 - r) * s * (p[7] - p[3]);
    return glm::dot(dr, glm::cross(ds, dt));
  };
  double scale = 0.0;
  for (int k = 1; k < 8; ++k)
    scale = std::max(scale, glm::length(p[k] - p[0]));
  const double tiny = 1e-12 * scale * scale * scale;
  bool positive = false, negative = false;
  for (int corner = 0; corner < 9; ++corner)
  {
    const double d = corner < 8 ? determinant(corner & 1 ? 1 : 0, corner & 2 ? 1 : 0, corner & 4 ? 1 : 0)
                                : determinant(0.5, 0.5, 0.5);
    positive = positive || d > tiny;
    negative = negative || d < -tiny;
  }
  return positive && negative;
}

inline glm::dvec3 FrameParametric(const HexahedronFrame& frame, const glm::dvec3& x)
{
  return frame.Inverse * (x - frame.Origin);
}

/// f(u) = c[0] + c[1] u + c[2] u^2 + c[3] u^3.
struct Cubic
{
  std::array<double, 4> c{};

  double operator()(double u) const { return c[0] + u * (c[1] + u * (c[2] + u * c[3])); }
  double Derivative(double u) const { return c[1] + u * (2.0 * c[2] + 3.0 * u * c[3]); }
};

/// The trilinear field of the 8 corner values (VTK order) along xi(u) = xi0 + u (xi1 - xi0), exactly.
inline Cubic TrilinearAlongSegment(const double f[8], const glm::dvec3& xi0, const glm::dvec3& xi1)
{
  // f = a000 + a100 r + a010 s + a001 t + a110 rs + a101 rt + a011 st + a111 rst.
  const double f0 = f[0], f1 = f[1], f2 = f[2], f3 = f[3], f4 = f[4], f5 = f[5], f6 = f[6], f7 = f[7];
  const double a000 = f0;
  const double a100 = f1 - f0;
  const double a010 = f3 - f0;
  const double a001 = f4 - f0;
  const double a110 = f0 - f1 + f2 - f3;
  const double a101 = f0 - f1 - f4 + f5;
  const double a011 = f0 - f3 - f4 + f7;
  const double a111 = -f0 + f1 - f2 + f3 + f4 - f5 + f6 - f7;
  const double r = xi0.x, s = xi0.y, t = xi0.z;
  const glm::dvec3 d = xi1 - xi0;
  const double fr = a100 + a110 * s + a101 * t + a111 * s * t;
  const double fs = a010 + a110 * r + a011 * t + a111 * r * t;
  const double ft = a001 + a101 * r + a011 * s + a111 * r * s;
  Cubic cubic;
  cubic.c[0] = a000 + a100 * r + a010 * s + a001 * t + a110 * r * s + a101 * r * t + a011 * s * t + a111 * r * s * t;
  cubic.c[1] = fr * d.x + fs * d.y + ft * d.z;
  cubic.c[2] = (a110 + a111 * t) * d.x * d.y + (a101 + a111 * s) * d.x * d.z + (a011 + a111 * r) * d.y * d.z;
  cubic.c[3] = a111 * d.x * d.y * d.z;
  return cubic;
}

/// Where a curved cell's field is sampled inside a segment (with its ends): the Chebyshev-Lobatto
/// points of a cubic on [0, 1].
constexpr double CurvedSampleNear = 0.25;
constexpr double CurvedSampleFar = 0.75;

/// The cubic through the values at u = 0, 1/4, 3/4, 1. With the isoparametric field's exact values
/// there (inverse map) it is the segment's field on curved cells: exact wherever the field along the
/// ray is a cubic (every parallelepiped), a cubic interpolant of it otherwise, rather than the field
/// along a straight path in trilinear coordinates, which a curved cell's ray does not follow.
inline Cubic CubicThroughSamples(double f0, double fNear, double fFar, double f1)
{
  Cubic cubic;
  cubic.c[0] = f0;
  cubic.c[1] = (-19.0 * f0 + 24.0 * fNear - 8.0 * fFar + 3.0 * f1) / 3.0;
  cubic.c[2] = (32.0 * f0 - 56.0 * fNear + 40.0 * fFar - 16.0 * f1) / 3.0;
  cubic.c[3] = 16.0 * (-f0 + 2.0 * fNear - 2.0 * fFar + f1) / 3.0;
  return cubic;
}

/// Roots of f' strictly inside (0, 1), ascending: where the cubic turns.
inline std::vector<double> CubicExtrema(const Cubic& f)
{
  // f'(u) = 3 c3 u^2 + 2 c2 u + c1, solved without cancellation.
  const double a = 3.0 * f.c[3], b = 2.0 * f.c[2], c = f.c[1];
  std::vector<double> roots;
  const double scale = std::abs(a) + std::abs(b) + std::abs(c);
  if (scale == 0.0)
  {
    return roots;
  }
  if (std::abs(a) <= 1e-14 * scale)
  {
    if (b != 0.0)
      roots.push_back(-c / b);
  }
  else
  {
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant >= 0.0)
    {
      const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
      roots.push_back(q / a);
      if (q != 0.0)
        roots.push_back(c / q);
    }
  }
  std::vector<double> inside;
  for (double u : roots)
  {
    if (u > 0.0 && u < 1.0)
      inside.push_back(u);
  }
  std::sort(inside.begin(), inside.end());
  inside.erase(std::unique(inside.begin(), inside.end()), inside.end());
  return inside;
}

/// The u in [a, b] where f(u) = value, f monotonic on [a, b] with value between f(a) and f(b):
/// Newton steps kept inside a shrinking bracket, bisection when a step would leave it.
inline double CubicRootInBracket(const Cubic& f, double value, double a, double b)
{
  const bool rising = f(b) > f(a);
  double u = 0.5 * (a + b);
  for (int iteration = 0; iteration < 100; ++iteration)
  {
    const double fu = f(u) - value;
    if (fu == 0.0)
      return u;
    // Keep the root bracketed: [a, b] with f(a) - value and f(b) - value of opposite signs.
    if ((fu < 0.0) == rising)
      a = u;
    else
      b = u;
    const double slope = f.Derivative(u);
    double next = slope != 0.0 ? u - fu / slope : 0.5 * (a + b);
    if (!(next > a && next < b))
      next = 0.5 * (a + b);
    if (std::abs(next - u) <= 1e-15 * (1.0 + std::abs(u)) || b - a <= 1e-15)
      return next;
    u = next;
  }
  return u;
}

/// Split points of the cubic on [0, 1]: 0, its extrema, every crossing of a node scalar, 1 (sorted).
inline std::vector<double> SplitPoints(const Cubic& f, const std::vector<double>& nodeScalars)
{
  std::vector<double> bounds = { 0.0 };
  for (double u : CubicExtrema(f))
    bounds.push_back(u);
  bounds.push_back(1.0);
  std::vector<double> cuts = bounds;
  for (std::size_t i = 0; i + 1 < bounds.size(); ++i)
  {
    const double a = bounds[i], b = bounds[i + 1];
    const double fa = f(a), fb = f(b);
    const double low = std::min(fa, fb), high = std::max(fa, fb);
    for (double v : nodeScalars)
    {
      if (v > low && v < high)
        cuts.push_back(CubicRootInBracket(f, v, a, b));
    }
  }
  std::sort(cuts.begin(), cuts.end());
  return cuts;
}

enum class HexahedronIntegration
{
  Accurate,
  Fast,
  FixedSteps
};

namespace detail
{
/// Integral over [0, x] of a cubic: a quartic.
inline double CubicIntegral(const std::array<double, 4>& p, double x)
{
  return x * (p[0] + x * (p[1] / 2.0 + x * (p[2] / 3.0 + x * p[3] / 4.0)));
}
} // namespace detail

/// Integrates the optical model along a ray segment of `length` whose scalar is the cubic f(u),
/// u in [0, 1], compositing into `accumulator`. Accurate uses 6-point Gauss-Legendre per piece;
/// `steps` is the step count of FixedSteps.
inline void IntegrateCubicSegment(const TransferFunction& tf, const Cubic& f, double length,
  HexahedronIntegration mode, RayAccumulator& accumulator, int steps = 8)
{
  if (!(length > 0.0))
    return;
  if (mode == HexahedronIntegration::FixedSteps)
  {
    const double h = length / steps;
    for (int i = 0; i < steps; ++i)
    {
      const TransferFunction::Node n = tf.Evaluate(f((i + 0.5) / steps));
      const double depth = n.Extinction * h;
      accumulator.Composite((1.0 - std::exp(-depth)) * n.Color, depth);
    }
    return;
  }
  std::vector<double> scalars;
  for (const auto& node : tf.GetNodes())
    scalars.push_back(node.Scalar);
  const std::vector<double> cuts = SplitPoints(f, scalars);
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
  {
    const double u0 = cuts[i], u1 = cuts[i + 1];
    if (!(u1 > u0))
      continue;
    if (mode == HexahedronIntegration::Fast)
    {
      const TransferFunction::Node a = tf.Evaluate(f(u0)), b = tf.Evaluate(f(u1));
      const double pieceLength = length * (u1 - u0);
      const double da = a.Extinction * pieceLength, db = b.Extinction * pieceLength;
      const SegmentColor piece = PreIntegratedPiece(a.Color, da, b.Color, db, PsiExact(da, db));
      accumulator.Composite(piece.Color, piece.OpticalDepth);
      continue;
    }
    // Accurate: on this piece the transfer function is linear in f, so extinction and colour are
    // cubics in u. Re-expand them about u0 in w = u - u0, w in [0, u1 - u0].
    const double mid = 0.5 * (u0 + u1);
    const int segment = tf.Segment(f(mid));
    const auto& nodes = tf.GetNodes();
    double slopeTau = 0.0, baseTau, baseScalar;
    glm::dvec3 slopeColor(0.0), baseColor;
    if (segment < 0 || segment >= static_cast<int>(nodes.size()) - 1)
    {
      const auto& n = segment < 0 ? nodes.front() : nodes.back();
      baseTau = n.Extinction;
      baseColor = n.Color;
      baseScalar = 0.0;
    }
    else
    {
      const auto& n0 = nodes[segment];
      const auto& n1 = nodes[segment + 1];
      const double width = n1.Scalar - n0.Scalar;
      slopeTau = (n1.Extinction - n0.Extinction) / width;
      slopeColor = (n1.Color - n0.Color) / width;
      baseTau = n0.Extinction;
      baseColor = n0.Color;
      baseScalar = n0.Scalar;
    }
    // f about u0: g(w) = f(u0 + w), coefficients by Taylor expansion.
    const std::array<double, 4> g = { f(u0), f.Derivative(u0), f.c[2] + 3.0 * f.c[3] * u0, f.c[3] };
    // Extinction per unit u (times length): tau(w) = L (baseTau + slopeTau (g(w) - baseScalar)).
    std::array<double, 4> tau = { length * (baseTau + slopeTau * (g[0] - baseScalar)), length * slopeTau * g[1],
      length * slopeTau * g[2], length * slopeTau * g[3] };
    const double width = u1 - u0;
    const double totalDepth = detail::CubicIntegral(tau, width);
    const int pieces = std::min(128, std::max(1, static_cast<int>(std::ceil(4.0 * totalDepth))));
    for (int k = 0; k < pieces; ++k)
    {
      const double w0 = width * k / pieces, w1 = width * (k + 1) / pieces;
      const double depthBefore = detail::CubicIntegral(tau, w0);
      const double half = 0.5 * (w1 - w0), centre = 0.5 * (w0 + w1);
      glm::dvec3 color(0.0);
      for (std::size_t q = 0; q < detail::GaussNodes.size(); ++q)
      {
        const double w = centre + half * detail::GaussNodes[q];
        const double scalar = g[0] + w * (g[1] + w * (g[2] + w * g[3]));
        const double extinction = tau[0] + w * (tau[1] + w * (tau[2] + w * tau[3]));
        const glm::dvec3 c = baseColor + slopeColor * (scalar - baseScalar);
        color += detail::GaussWeights[q] * extinction * std::exp(-(detail::CubicIntegral(tau, w) - depthBefore)) * c;
      }
      color *= half;
      accumulator.Composite(color, detail::CubicIntegral(tau, w1) - depthBefore);
    }
  }
}

} // namespace uv

#endif
