// Projected tetrahedra, free of VTK: how a tetrahedron's four projected vertices split the screen
// into the triangles of a fan around one "thick vertex", and where the eye ray through that vertex
// enters and leaves the tetrahedron. uvPreIntegratedTetrahedraGS.glsl is the GPU twin of this code
// (same steps, same names); this copy is what the unit tests check.
//
// Classification. The four projected points P0..P3 have one affine dependency
//   sum_k A_k P_k = 0,  sum_k A_k = 0,  A_k = (-1)^k * orient(the three points other than k),
// and the signs of the A_k (the four cross-product sign tests) are the projection's class:
//   one sign against three  class 1: the lone point lies inside the triangle of the others;
//   two against two         class 2: the segments joining equal signs cross;
//   one zero, then 1 vs 2   class 3: a point lies on the edge joining the other side's two;
//   two zeros               class 4: two points coincide (an edge seen end-on);
//   all zero                the tetrahedron projects onto a line: nothing to draw.
// Every one of the 3^4 sign patterns falls in exactly one of these, including the 24 + 12
// degenerate cases of classes 3 and 4. The thick vertex is the point both sides share (Radon's point)
//   T = sum_{A_k>0} A_k P_k / sum_{A_k>0} A_k = sum_{A_k<0} A_k P_k / sum_{A_k<0} A_k,
// so the weights |A_k| / sum are the screen-space barycentric coordinates of T on each side's
// simplex (a vertex, an edge or a face). The fan joins T to the edges of the projected outline.
#ifndef uvProjectedTetrahedron_h
#define uvProjectedTetrahedron_h

#include <glm/glm.hpp>

#include <array>
#include <cmath>

namespace uv
{

inline double Orient2D(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c)
{
  const glm::dvec2 u = b - a, v = c - a;
  return u.x * v.y - u.y * v.x;
}

/// How four projected points split into the fan of triangles around the thick vertex.
struct ProjectionClass
{
  int Class = 0;                    ///< 1..4, or 0 when the projection has no area
  std::array<int, 4> Side{};        ///< +1 or -1 (the two sides of the dependency), 0 for neither
  std::array<double, 4> Weight{};   ///< screen-space weight of each point in T within its side
  int TriangleCount = 0;            ///< fan triangles (T, P_i, P_j)
  std::array<std::array<int, 2>, 4> Triangles{};
};

/// The affine dependency A_k of four 2D points (see the header comment).
inline std::array<double, 4> AffineDependency(const std::array<glm::dvec2, 4>& p)
{
  return { Orient2D(p[1], p[2], p[3]), -Orient2D(p[0], p[2], p[3]), Orient2D(p[0], p[1], p[3]),
    -Orient2D(p[0], p[1], p[2]) };
}

/// Classifies the projection. A coefficient counts as zero when its magnitude is at most
/// `zeroTolerance` times the sum of all magnitudes (0 for exact arithmetic on exact inputs).
inline ProjectionClass ClassifyProjection(const std::array<glm::dvec2, 4>& p, double zeroTolerance = 0.0)
{
  ProjectionClass result;
  const std::array<double, 4> a = AffineDependency(p);
  const double total = std::abs(a[0]) + std::abs(a[1]) + std::abs(a[2]) + std::abs(a[3]);
  if (!(total > 0.0))
  {
    return result; // all four on a line (or not finite)
  }
  int positives = 0, negatives = 0;
  double positiveSum = 0.0, negativeSum = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    if (std::abs(a[k]) <= zeroTolerance * total)
    {
      result.Side[k] = 0;
    }
    else if (a[k] > 0.0)
    {
      result.Side[k] = 1;
      ++positives;
      positiveSum += a[k];
    }
    else
    {
      result.Side[k] = -1;
      ++negatives;
      negativeSum -= a[k];
    }
  }
  if (positives == 0 || negatives == 0)
  {
    return result; // the dependency collapsed to zero: no area
  }
  for (int k = 0; k < 4; ++k)
  {
    result.Weight[k] = result.Side[k] > 0 ? a[k] / positiveSum : result.Side[k] < 0 ? -a[k] / negativeSum : 0.0;
  }
  // Name the smaller side "lone" (the thick vertex side when it is one point).
  const int lone = positives <= negatives ? 1 : -1;
  const int loneCount = std::min(positives, negatives), otherCount = std::max(positives, negatives);
  auto add = [&result](int i, int j) { result.Triangles[result.TriangleCount++] = { i, j }; };
  if (loneCount == 1 && otherCount == 3)
  {
    result.Class = 1; // outline: the triangle of the other three
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (result.Side[i] == -lone && result.Side[j] == -lone)
          add(i, j);
  }
  else if (loneCount == 2)
  {
    result.Class = 2; // outline: a quadrilateral whose diagonals cross at T
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (result.Side[i] != result.Side[j])
          add(i, j);
  }
  else if (loneCount == 1 && otherCount == 2)
  {
    result.Class = 3; // T on the edge of the two: the outline is the triangle (edge, zero point)
    int zero = 0;
    while (result.Side[zero] != 0)
      ++zero;
    for (int i = 0; i < 4; ++i)
      if (result.Side[i] == -lone)
        add(std::min(i, zero), std::max(i, zero));
  }
  else
  {
    result.Class = 4; // one point each side, coincident: the outline is the other two and T
    int first = -1, second = -1;
    for (int i = 0; i < 4; ++i)
      if (result.Side[i] == 0)
        (first < 0 ? first : second) = i;
    add(first, second);
  }
  return result;
}

/// The thick vertex's screen position.
inline glm::dvec2 ThickVertex(const ProjectionClass& c, const std::array<glm::dvec2, 4>& p)
{
  glm::dvec2 t(0.0);
  for (int k = 0; k < 4; ++k)
  {
    if (c.Side[k] > 0)
    {
      t += c.Weight[k] * p[k];
    }
  }
  return t;
}

/// Where the eye ray through the thick vertex meets one side's simplex, as weights of the four
/// vertices: screen weights divided by each vertex's clip w, renormalised (perspective-correct).
inline std::array<double, 4> SideWeights3D(const ProjectionClass& c, int side, const std::array<double, 4>& clipW)
{
  std::array<double, 4> mu{};
  double sum = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    if (c.Side[k] == side)
    {
      mu[k] = c.Weight[k] / clipW[k];
      sum += mu[k];
    }
  }
  for (double& m : mu)
  {
    m /= sum;
  }
  return mu;
}

} // namespace uv

#endif
