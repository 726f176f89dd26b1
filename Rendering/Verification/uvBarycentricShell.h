// Rays through a tetrahedron in its own barycentric coordinates, free of VTK and OpenGL: the math of
// the barycentric shell mapper (after Georgii and Westermann), checked alone by the unit tests.
//
// Eye space, eye at the origin. A tetrahedron v0..v3 maps a point x to barycentric coordinates
// b = M^-1 (x, 1), M the 4x4 matrix with columns (v_i, 1). Along the ray from the eye in the unit
// direction u, at distance z, b(z) = b_eye + z M^-1 (u, 0), where b_eye = M^-1 (0, 0, 0, 1) is the
// last column of M^-1: the eye's own barycentric coordinates. At vertex i, M^-1 (v_i, 0) = e_i -
// b_eye, so per element only b_eye is needed; the vertices carry b_i = e_i - b_eye and l_i = |v_i|.
// Across a face the attribute b interpolates (perspective-correctly) to M^-1 (x, 0) exactly, x the
// fragment's eye-space point; with l = |x| the fragment's ray is b(z) = b_eye + z b / l, so the
// spherical shell of radius z is sampled without leaving barycentric space. Inside the tetrahedron
// all four coordinates are >= 0; the scalar there is the linear sum of the vertex values weighted
// by b, so an isovalue is crossed at one distance, found in closed form.
//
// Templates on the scalar: double for the reference checks, float for what a shader can do.
#ifndef uvBarycentricShell_h
#define uvBarycentricShell_h

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace uv
{

/// One tetrahedron, prepared for barycentric ray sampling in eye space (eye at the origin).
/// M^-1 is kept in its translated form: with E the 3x3 matrix of edges v_i - v0 (i = 1..3), the
/// coordinates 1..3 of x are E^-1 (x - v0) and coordinate 0 is one minus their sum. It is the same
/// map; inverting the 4x4 matrix directly in float loses the digits the eye's distance costs (the
/// unit test measures both on tetrahedra far from the eye).
template <typename T>
struct BarycentricTetrahedron
{
  glm::vec<3, T> Origin;         ///< v0
  glm::mat<3, 3, T> EdgeInverse; ///< E^-1
  glm::vec<4, T> Eye;            ///< b_eye: the eye's coordinates, the last column of M^-1
  bool Valid = false;            ///< false for a flat tetrahedron (no inverse)
};

namespace detail
{
template <typename T>
glm::vec<4, T> FromEdgeCoordinates(const glm::vec<3, T>& q, T first)
{
  return glm::vec<4, T>(first - q.x - q.y - q.z, q.x, q.y, q.z);
}
} // namespace detail

/// Flat tetrahedra (volume zero to the precision of T, relative to their edges) are not Valid.
template <typename T>
BarycentricTetrahedron<T> MakeBarycentricTetrahedron(const glm::vec<3, T> v[4])
{
  BarycentricTetrahedron<T> tet;
  const glm::mat<3, 3, T> edges(v[1] - v[0], v[2] - v[0], v[3] - v[0]);
  const T det = glm::determinant(edges);
  const T scale = std::max({ glm::length(edges[0]), glm::length(edges[1]), glm::length(edges[2]) });
  if (!(std::abs(det) > T(16) * std::numeric_limits<T>::epsilon() * scale * scale * scale))
  {
    return tet;
  }
  tet.Origin = v[0];
  tet.EdgeInverse = glm::inverse(edges);
  tet.Eye = detail::FromEdgeCoordinates(tet.EdgeInverse * -v[0], T(1));
  tet.Valid = true;
  return tet;
}

/// Barycentric coordinates of the point x.
template <typename T>
glm::vec<4, T> BarycentricOf(const BarycentricTetrahedron<T>& tet, const glm::vec<3, T>& x)
{
  return detail::FromEdgeCoordinates(tet.EdgeInverse * (x - tet.Origin), T(1));
}

/// The barycentric direction attribute of an eye-space point x on the tetrahedron's surface:
/// M^-1 (x, 0), i.e. b(x) - b_eye (at vertex i, e_i - b_eye). Linear in x, so it interpolates exactly
/// across faces.
template <typename T>
glm::vec<4, T> BarycentricDirection(const BarycentricTetrahedron<T>& tet, const glm::vec<3, T>& x)
{
  return detail::FromEdgeCoordinates(tet.EdgeInverse * x, T(0));
}

/// The sample at distance z from the eye along the ray through the fragment whose direction
/// attribute is b and eye distance l: b^k = b / l * z + b_eye.
template <typename T>
glm::vec<4, T> ShellSample(
  const glm::vec<4, T>& eye, const glm::vec<4, T>& direction, T length, T z)
{
  return direction * (z / length) + eye;
}

/// The same sample from the fragment's own coordinates on the face it was rasterised from (the
/// vertices' e_i interpolated, so small and exact): b^k = b_face + (z - l) b / l. Mathematically equal
/// to ShellSample (b_face = b_eye + b); in float it avoids b_eye, whose size grows with the eye's
/// distance in cell lengths and whose digits the sum then loses (measured in the unit test).
template <typename T>
glm::vec<4, T> ShellSampleFromFace(
  const glm::vec<4, T>& face, const glm::vec<4, T>& direction, T length, T z)
{
  return direction * ((z - length) / length) + face;
}

/// Inside (or on) the tetrahedron: every coordinate >= -tolerance.
template <typename T>
bool InsideBarycentric(const glm::vec<4, T>& b, T tolerance = T(0))
{
  return std::min({ b.x, b.y, b.z, b.w }) >= -tolerance;
}

/// The eye distance where the ray (unit-distance direction `perUnit` = b / l) crosses `isovalue` of
/// the linear field with vertex values `scalars`; NaN when the field is constant along the ray. The
/// crossing may lie outside the tetrahedron: test it with InsideBarycentric(ShellSample(...)).
/// Computed from any point of the ray with known coordinates `at` and eye distance `length`:
/// length + (isovalue - f(at)) / slope; from the fragment's face coordinates (see
/// ShellSampleFromFace) it avoids the eye's large coordinates.
template <typename T>
T IsovalueDistanceFromFace(const glm::vec<4, T>& at, const glm::vec<4, T>& perUnit, T length,
  const glm::vec<4, T>& scalars, T isovalue)
{
  const T slope = glm::dot(scalars, perUnit);
  if (slope == T(0))
  {
    return std::numeric_limits<T>::quiet_NaN();
  }
  return length + (isovalue - glm::dot(scalars, at)) / slope;
}

/// The same from the eye's own coordinates.
template <typename T>
T IsovalueDistance(const glm::vec<4, T>& eye, const glm::vec<4, T>& perUnit,
  const glm::vec<4, T>& scalars, T isovalue)
{
  return IsovalueDistanceFromFace(eye, perUnit, T(0), scalars, isovalue); // the eye: distance 0
}

} // namespace uv

#endif
