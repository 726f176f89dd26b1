// Gradient of a point scalar over one linear 3D cell, free of VTK so it can be tested alone.
//
// Each function returns the gradient at the cell's parametric centre and a weight (the cell's volume,
// or the isoparametric Jacobian determinant at the centre, which equals it for parallelepipeds and
// approximates it otherwise). All are exact for fields linear in x, y, z on any valid cell, because
// isoparametric interpolation reproduces linear functions. The gradient does not depend on the
// cell's orientation, so mirrored cells (negative image spacing, left-handed grids) count with
// |det J|. A zero weight means the cell is degenerate; callers skip such cells.
#ifndef uvCellGradient_h
#define uvCellGradient_h

#include <glm/glm.hpp>

#include <cmath>

namespace uv
{

struct CellGradient
{
  glm::dvec3 Gradient{ 0.0 };
  double Weight = 0.0;
};

namespace detail
{
/// grad f = J^-T df/dxi, where J's columns are dx/dxi_k. Weight = |det J|.
inline CellGradient FromJacobian(const glm::dmat3& jacobian, const glm::dvec3& dfdxi)
{
  CellGradient result;
  const double det = std::abs(glm::determinant(jacobian));
  // Relative test: a cell whose Jacobian is this close to singular carries no usable gradient.
  const double scale = glm::length(jacobian[0]) * glm::length(jacobian[1]) * glm::length(jacobian[2]);
  if (!(det > 1e-12 * scale))
  {
    return result;
  }
  result.Gradient = glm::transpose(glm::inverse(jacobian)) * dfdxi;
  result.Weight = det;
  return result;
}
} // namespace detail

/// Tetrahedron in VTK order; weight = volume.
inline CellGradient TetrahedronGradient(const glm::dvec3 p[4], const double f[4])
{
  const glm::dmat3 jacobian(p[1] - p[0], p[2] - p[0], p[3] - p[0]);
  CellGradient result =
    detail::FromJacobian(jacobian, glm::dvec3(f[1] - f[0], f[2] - f[0], f[3] - f[0]));
  result.Weight /= 6.0;
  return result;
}

/// Hexahedron in VTK order, trilinear on the unit cube; weight = det J at the centre.
inline CellGradient HexahedronGradient(const glm::dvec3 p[8], const double f[8])
{
  // Corner k sits at (x,y,z) in {0,1}^3; at the centre dN_k/dxi_d = +-1/4 by that coordinate.
  static const int corner[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
    { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
  glm::dmat3 jacobian(0.0);
  glm::dvec3 dfdxi(0.0);
  for (int k = 0; k < 8; ++k)
  {
    for (int d = 0; d < 3; ++d)
    {
      const double dN = corner[k][d] ? 0.25 : -0.25;
      jacobian[d] += dN * p[k];
      dfdxi[d] += dN * f[k];
    }
  }
  return detail::FromJacobian(jacobian, dfdxi);
}

/// Wedge in VTK order (triangle 0,1,2 at t=0, triangle 3,4,5 at t=1), at the centroid; weight = volume
/// for straight-sided wedges.
inline CellGradient WedgeGradient(const glm::dvec3 p[6], const double f[6])
{
  // N = L_i(r,s) * (1-t) or t, L = (1-r-s, r, s); evaluated at r = s = 1/3, t = 1/2.
  static const double dNdr[6] = { -0.5, 0.5, 0.0, -0.5, 0.5, 0.0 };
  static const double dNds[6] = { -0.5, 0.0, 0.5, -0.5, 0.0, 0.5 };
  static const double dNdt[6] = { -1.0 / 3, -1.0 / 3, -1.0 / 3, 1.0 / 3, 1.0 / 3, 1.0 / 3 };
  glm::dmat3 jacobian(0.0);
  glm::dvec3 dfdxi(0.0);
  // VTK's valid wedge has (0,1,2) facing away from (3,4,5), i.e. (r,s,t) is left-handed; take the
  // columns in (s,r,t) order so a valid wedge has a positive determinant.
  for (int k = 0; k < 6; ++k)
  {
    jacobian[0] += dNds[k] * p[k];
    jacobian[1] += dNdr[k] * p[k];
    jacobian[2] += dNdt[k] * p[k];
    dfdxi += glm::dvec3(dNds[k], dNdr[k], dNdt[k]) * f[k];
  }
  CellGradient result = detail::FromJacobian(jacobian, dfdxi);
  result.Weight *= 0.5; // the reference prism has volume 1/2
  return result;
}

/// Pyramid in VTK order (base 0..3, apex 4): volume-weighted mean of the two tets across the base
/// diagonal 0-2, which keeps it exact for linear fields without the pyramid's rational basis.
inline CellGradient PyramidGradient(const glm::dvec3 p[5], const double f[5])
{
  const glm::dvec3 firstPoints[4] = { p[0], p[1], p[2], p[4] };
  const double firstValues[4] = { f[0], f[1], f[2], f[4] };
  const glm::dvec3 secondPoints[4] = { p[0], p[2], p[3], p[4] };
  const double secondValues[4] = { f[0], f[2], f[3], f[4] };
  const CellGradient first = TetrahedronGradient(firstPoints, firstValues);
  const CellGradient second = TetrahedronGradient(secondPoints, secondValues);
  CellGradient result;
  result.Weight = first.Weight + second.Weight;
  if (first.Weight <= 0.0 || second.Weight <= 0.0) // a degenerate half
  {
    result.Weight = 0.0;
    return result;
  }
  result.Gradient = (first.Weight * first.Gradient + second.Weight * second.Gradient) / result.Weight;
  return result;
}

} // namespace uv

#endif
