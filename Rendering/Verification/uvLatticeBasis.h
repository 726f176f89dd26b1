// Shape functions of higher-order cells on the equispaced lattice of order n, in two bases: Lagrange
// (the nodes' values are interpolated: VTK's Lagrange cells) and Bernstein (the nodes are control
// points: VTK's non-rational Bezier cells); for tetrahedra, wedges (a triangle's basis times a
// line's) and hexahedra (three lines'). A tetrahedron's node is named by its lattice index
// (a0, a1, a2, a3), a0 + a1 + a2 + a3 = n, over the barycentric coordinates (r, s, t, 1 - r - s - t)
// of VTK's parametric tetrahedron; a wedge's by (a0, a1, a2, k): its triangle index over
// (r, s, 1 - r - s) and its layer k over t; a hexahedron's by (i, j, k, 0). Which index a VTK node
// has is the caller's business (the parametric coordinates VTK gives it, times n). Derivatives are
// with respect to (r, s, t), in VTK's usual layout (all d/dr, then all d/ds, then all d/dt): VTK
// 9.1's own derivatives of these cells are not (interleaved for Lagrange and Bezier hexahedra,
// wrong for Bezier tetrahedra and wedges), and its static wedge and hexahedron functions are slow
// enough to dominate the reference's time, which is why these are written out here. VTK-free.
#ifndef uvLatticeBasis_h
#define uvLatticeBasis_h

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <vector>

namespace uv
{
using SimplexIndex = std::array<int, 4>;

/// The Lagrange factor of order n and degree a in one barycentric coordinate: the product over
/// i < a of (n lambda - i) / (i + 1), which is 1 at lambda = a / n and 0 at 0, 1/n, ..., (a-1)/n;
/// the product of a node's four factors is 1 at the node and 0 at every other lattice point.
inline void LagrangeFactor(int n, int a, double lambda, double& value, double& derivative)
{
  value = 1.0;
  derivative = 0.0;
  for (int i = 0; i < a; ++i)
  {
    const double factor = (n * lambda - i) / (i + 1);
    derivative = derivative * factor + value * n / (i + 1);
    value *= factor;
  }
}

/// The Bernstein factor lambda^a / a! (the node's weight is n! times the product of its four).
inline void BernsteinFactor(int, int a, double lambda, double& value, double& derivative)
{
  value = 1.0;
  derivative = 0.0;
  for (int i = 1; i <= a; ++i)
  {
    derivative = derivative * lambda / i + value / i;
    value *= lambda / i;
  }
}

enum class SimplexBasisKind
{
  Lagrange,
  Bernstein
};

/// n! for a Bernstein basis (per simplex factor of the element), 1 for a Lagrange one.
inline double BasisScale(SimplexBasisKind kind, int order)
{
  double scale = 1.0;
  for (int i = 2; kind == SimplexBasisKind::Bernstein && i <= order; ++i)
    scale *= i;
  return scale;
}

/// Weights (and, when `derivatives` is not null, their derivatives) of `nodes` at xi = (r, s, t).
inline void EvaluateSimplexBasis(SimplexBasisKind kind, int order, const std::vector<SimplexIndex>& nodes,
  const glm::dvec3& xi, double* weights, double* derivatives)
{
  const double lambda[4] = { xi.x, xi.y, xi.z, 1.0 - xi.x - xi.y - xi.z };
  const double scale = BasisScale(kind, order);
  const int count = static_cast<int>(nodes.size());
  for (int k = 0; k < count; ++k)
  {
    double value[4], slope[4];
    for (int m = 0; m < 4; ++m)
    {
      if (kind == SimplexBasisKind::Lagrange)
        LagrangeFactor(order, nodes[k][m], lambda[m], value[m], slope[m]);
      else
        BernsteinFactor(order, nodes[k][m], lambda[m], value[m], slope[m]);
    }
    weights[k] = scale * value[0] * value[1] * value[2] * value[3];
    if (!derivatives)
      continue;
    // d lambda_m / d xi_j is 1 for m == j and -1 for the last coordinate.
    const double last = slope[3] * value[0] * value[1] * value[2];
    derivatives[k] = scale * (slope[0] * value[1] * value[2] * value[3] - last);
    derivatives[count + k] = scale * (value[0] * slope[1] * value[2] * value[3] - last);
    derivatives[2 * count + k] = scale * (value[0] * value[1] * slope[2] * value[3] - last);
  }
}

/// One node's factor along a line: the basis of degree n over the barycentric pair (u, 1 - u) at
/// lattice index (k, n - k), which is the 1D Lagrange polynomial of the node u = k / n or the
/// Bernstein polynomial (without its binomial, which the caller's scale holds).
inline void LineFactor(SimplexBasisKind kind, int n, int k, double u, double& value, double& derivative)
{
  double a, da, b, db;
  if (kind == SimplexBasisKind::Lagrange)
  {
    LagrangeFactor(n, k, u, a, da);
    LagrangeFactor(n, n - k, 1.0 - u, b, db);
  }
  else
  {
    BernsteinFactor(n, k, u, a, da);
    BernsteinFactor(n, n - k, 1.0 - u, b, db);
  }
  value = a * b;
  derivative = da * b - a * db;
}

/// Weights (and, when `derivatives` is not null, their derivatives) of a Lagrange or Bezier
/// wedge's `nodes` (triangle index, layer) at xi = (r, s, t): the triangle's basis over
/// (r, s, 1 - r - s) times the line's over t.
inline void EvaluateWedgeBasis(SimplexBasisKind kind, int order, const std::vector<SimplexIndex>& nodes,
  const glm::dvec3& xi, double* weights, double* derivatives)
{
  const double triangle[3] = { xi.x, xi.y, 1.0 - xi.x - xi.y };
  const double scale = BasisScale(kind, order) * BasisScale(kind, order);
  const int count = static_cast<int>(nodes.size());
  for (int k = 0; k < count; ++k)
  {
    double value[3], slope[3], line, lineSlope;
    for (int m = 0; m < 3; ++m)
    {
      if (kind == SimplexBasisKind::Lagrange)
        LagrangeFactor(order, nodes[k][m], triangle[m], value[m], slope[m]);
      else
        BernsteinFactor(order, nodes[k][m], triangle[m], value[m], slope[m]);
    }
    LineFactor(kind, order, nodes[k][3], xi.z, line, lineSlope);
    const double area = value[0] * value[1] * value[2];
    weights[k] = scale * area * line;
    if (!derivatives)
      continue;
    const double last = slope[2] * value[0] * value[1]; // d/dr and d/ds of 1 - r - s are -1
    derivatives[k] = scale * (slope[0] * value[1] * value[2] - last) * line;
    derivatives[count + k] = scale * (value[0] * slope[1] * value[2] - last) * line;
    derivatives[2 * count + k] = scale * area * lineSlope;
  }
}

/// Weights (and, when `derivatives` is not null, their derivatives) of a Lagrange or Bezier
/// hexahedron's `nodes` (i, j, k, unused) at xi = (r, s, t): the product of three lines' bases.
inline void EvaluateHexahedronBasis(SimplexBasisKind kind, int order, const std::vector<SimplexIndex>& nodes,
  const glm::dvec3& xi, double* weights, double* derivatives)
{
  const double scale = BasisScale(kind, order) * BasisScale(kind, order) * BasisScale(kind, order);
  const int count = static_cast<int>(nodes.size());
  for (int k = 0; k < count; ++k)
  {
    double value[3], slope[3];
    for (int axis = 0; axis < 3; ++axis)
      LineFactor(kind, order, nodes[k][axis], xi[axis], value[axis], slope[axis]);
    weights[k] = scale * value[0] * value[1] * value[2];
    if (!derivatives)
      continue;
    derivatives[k] = scale * slope[0] * value[1] * value[2];
    derivatives[count + k] = scale * value[0] * slope[1] * value[2];
    derivatives[2 * count + k] = scale * value[0] * value[1] * slope[2];
  }
}

/// The lattice index of a node at parametric coordinates xi on the lattice of `order`.
inline SimplexIndex SimplexIndexAt(int order, const glm::dvec3& xi)
{
  const int a = static_cast<int>(std::lround(order * xi.x));
  const int b = static_cast<int>(std::lround(order * xi.y));
  const int c = static_cast<int>(std::lround(order * xi.z));
  return { a, b, c, order - a - b - c };
}

/// A hexahedron's node at parametric coordinates xi: (i, j, k, 0).
inline SimplexIndex HexahedronIndexAt(int order, const glm::dvec3& xi)
{
  return { static_cast<int>(std::lround(order * xi.x)), static_cast<int>(std::lround(order * xi.y)),
    static_cast<int>(std::lround(order * xi.z)), 0 };
}

/// A wedge's node at parametric coordinates xi: (triangle index, layer).
inline SimplexIndex WedgeIndexAt(int order, const glm::dvec3& xi)
{
  const int a = static_cast<int>(std::lround(order * xi.x));
  const int b = static_cast<int>(std::lround(order * xi.y));
  return { a, b, order - a - b, static_cast<int>(std::lround(order * xi.z)) };
}
}

#endif
