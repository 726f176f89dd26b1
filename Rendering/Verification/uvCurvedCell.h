// Higher-order (curved) 3D cells for the exact reference: the ray's parts inside a cell whose faces
// are curved patches, and the inverse of its isoparametric map. The shape functions come from the
// caller (a functor), so the header knows nothing of VTK; it only knows VTK's parametric domains.
#ifndef uvCurvedCell_h
#define uvCurvedCell_h

#include "uvCellFamily.h"
#include "uvRayCellGeometry.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace uv
{
/// One face as a flat map of (u, v) into parametric space: xi = Origin + u U + v V, on the unit
/// triangle (u, v >= 0, u + v <= 1) or the unit square.
struct ParametricFace
{
  glm::dvec3 Origin, U, V;
  bool Triangle;

  glm::dvec3 At(double u, double v) const { return this->Origin + u * this->U + v * this->V; }
  bool Contains(double u, double v, double m) const
  {
    return u >= -m && v >= -m && (this->Triangle ? u + v <= 1 + m : u <= 1 + m && v <= 1 + m);
  }
};

inline const std::vector<ParametricFace>& FacesOf(CellFamily family)
{
  using F = ParametricFace;
  const glm::dvec3 o(0.0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  static const std::vector<F> tetrahedron = { F{ o, x, y, true }, F{ o, x, z, true }, F{ o, y, z, true },
    F{ x, y - x, z - x, true } };
  static const std::vector<F> hexahedron = { F{ o, y, z, false }, F{ x, y, z, false }, F{ o, x, z, false },
    F{ y, x, z, false }, F{ o, x, y, false }, F{ z, x, y, false } };
  static const std::vector<F> wedge = { F{ o, x, y, true }, F{ z, x, y, true }, F{ o, x, z, false },
    F{ o, y, z, false }, F{ x, y - x, z, false } };
  // The top face of the cube is the apex: no area, no face.
  static const std::vector<F> pyramid = { F{ o, x, y, false }, F{ o, y, z, false }, F{ x, y, z, false },
    F{ o, x, z, false }, F{ y, x, z, false } };
  switch (family)
  {
    case CellFamily::Tetrahedron:
      return tetrahedron;
    case CellFamily::Hexahedron:
      return hexahedron;
    case CellFamily::Wedge:
      return wedge;
    default:
      return pyramid;
  }
}

inline bool InFamilyDomain(CellFamily family, const glm::dvec3& xi, double m)
{
  switch (family)
  {
    case CellFamily::Tetrahedron:
      return xi.x >= -m && xi.y >= -m && xi.z >= -m && xi.x + xi.y + xi.z <= 1 + m;
    case CellFamily::Wedge:
      return InPrism(xi, m);
    default:
      return InUnitCube(xi, m);
  }
}

inline glm::dvec3 FamilyCentre(CellFamily family)
{
  switch (family)
  {
    case CellFamily::Tetrahedron:
      return glm::dvec3(0.25);
    case CellFamily::Wedge:
      return glm::dvec3(1.0 / 3.0, 1.0 / 3.0, 0.5);
    case CellFamily::Pyramid:
      return glm::dvec3(0.5, 0.5, 0.25);
    default:
      return glm::dvec3(0.5);
  }
}

/// A curved cell: its nodes (positions and values) and shape functions. `Basis(xi, weights,
/// derivatives)` fills Nodes weights and, unless `derivatives` is null, 3 * Nodes derivatives in
/// VTK's layout (all d/dr, then all d/ds, then all d/dt).
template <typename Basis>
class CurvedCell
{
public:
  static constexpr int MaximumNodes = 64;

  CurvedCell(CellFamily family, const Basis& basis, int nodes, const glm::dvec3* positions, const double* values)
    : Family(family)
    , TheBasis(basis)
    , Nodes(std::min(nodes, MaximumNodes))
  {
    glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-low);
    for (int k = 0; k < this->Nodes; ++k)
    {
      this->Positions[k] = positions[k] - positions[0]; // small coordinates, wherever the cell lies
      this->Values[k] = values ? values[k] : 0.0;
      low = glm::min(low, this->Positions[k]);
      high = glm::max(high, this->Positions[k]);
    }
    this->Anchor = positions[0];
    this->Size = std::max(glm::length(high - low), std::numeric_limits<double>::min());
  }

  double Diameter() const { return this->Size; }

  /// Position (relative to the anchor) and Jacobian at xi.
  glm::dvec3 Map(const glm::dvec3& xi, glm::dmat3* jacobian) const
  {
    double w[MaximumNodes], d[3 * MaximumNodes];
    this->TheBasis(xi, w, jacobian ? d : nullptr);
    glm::dvec3 x(0.0);
    for (int k = 0; k < this->Nodes; ++k)
      x += w[k] * this->Positions[k];
    if (jacobian)
    {
      glm::dmat3 j(0.0);
      for (int k = 0; k < this->Nodes; ++k)
      {
        j[0] += d[k] * this->Positions[k];
        j[1] += d[this->Nodes + k] * this->Positions[k];
        j[2] += d[2 * this->Nodes + k] * this->Positions[k];
      }
      *jacobian = j;
    }
    return x;
  }

  glm::dvec3 Point(const glm::dvec3& xi) const { return this->Anchor + this->Map(xi, nullptr); }

  double Scalar(const glm::dvec3& xi) const
  {
    double w[MaximumNodes];
    this->TheBasis(xi, w, nullptr);
    double value = 0.0;
    for (int k = 0; k < this->Nodes; ++k)
      value += w[k] * this->Values[k];
    return value;
  }

  /// Parametric coordinates of x by safeguarded Newton from xi (uvRayCellGeometry.h). False if it
  /// does not converge.
  bool Inverse(const glm::dvec3& x, glm::dvec3& xi) const
  {
    const auto map = [this](const glm::dvec3& at, glm::dmat3& jacobian) { return this->Map(at, &jacobian); };
    return SafeguardedNewton(map, x - this->Anchor, this->Size, xi);
  }

  bool Contains(const glm::dvec3& x, glm::dvec3& xi) const
  {
    return this->Inverse(x, xi) && InFamilyDomain(this->Family, xi, 1e-9);
  }

  /// A point where the ray meets a face: its ray parameter and parametric coordinates.
  struct Hit
  {
    double T;
    glm::dvec3 Xi;
  };

  /// The parts of the ray inside the cell, appended to `parts` (entry and exit parametric
  /// coordinates in `xi`, one pair per part). Every face hit is found by Newton on the curved face
  /// from the flat face's hit, or from a grid of starts on the face where that Newton leaves it (it
  /// may have headed for a second root); a cell whose hits still do not pair up is searched again
  /// from the grid on every face.
  void Intersect(const Ray& ray, std::vector<Interval>& parts, std::vector<std::array<glm::dvec3, 2>>& xi,
    std::vector<Hit>& hits) const
  {
    hits.clear();
    for (const ParametricFace& face : FacesOf(this->Family))
      this->HitFace(ray, face, false, hits);
    this->SortAndMerge(hits);
    if (hits.size() % 2 == 1)
    {
      for (const ParametricFace& face : FacesOf(this->Family))
        this->HitFace(ray, face, true, hits);
      this->SortAndMerge(hits);
    }
    for (std::size_t i = 0; i + 1 < hits.size(); ++i)
    {
      const Hit& a = hits[i];
      const Hit& b = hits[i + 1];
      glm::dvec3 middle = 0.5 * (a.Xi + b.Xi);
      if (!this->Contains(ray.Origin + 0.5 * (a.T + b.T) * ray.Direction, middle))
        continue;
      if (!parts.empty() && parts.back().Exit == a.T)
      {
        parts.back().Exit = b.T; // the gap between two entries was a tangency: merge
        xi.back()[1] = b.Xi;
      }
      else
      {
        parts.push_back({ a.T, b.T });
        xi.push_back({ a.Xi, b.Xi });
      }
    }
  }

private:
  /// Newton on (u, v, t): the curved face's point at (u, v) equals the ray's at t.
  bool SolveFaceHit(const Ray& ray, const ParametricFace& face, double u, double v, Hit& hit) const
  {
    const glm::dvec3 origin = ray.Origin - this->Anchor;
    double t = glm::dot(this->Map(face.At(u, v), nullptr) - origin, ray.Direction);
    for (int iteration = 0; iteration < 30; ++iteration)
    {
      glm::dmat3 jacobian;
      const glm::dvec3 xi = face.At(u, v);
      const glm::dvec3 residual = this->Map(xi, &jacobian) - (origin + t * ray.Direction);
      const glm::dmat3 system(jacobian * face.U, jacobian * face.V, -ray.Direction);
      const double det = glm::determinant(system);
      if (!(std::abs(det) > 0.0) || !std::isfinite(det))
        return false;
      glm::dvec3 step = glm::inverse(system) * residual;
      const double longest = std::max(std::abs(step.x), std::abs(step.y));
      if (!std::isfinite(longest) || !std::isfinite(step.z))
        return false;
      if (longest > 0.5)
        step *= 0.5 / longest;
      u -= step.x;
      v -= step.y;
      t -= step.z;
      if (!face.Contains(u, v, 1.0))
        return false; // wandered off the face
      if (longest < 1e-13 || glm::length(residual) <= 1e-13 * this->Size)
      {
        hit = { t, face.At(u, v) };
        return face.Contains(u, v, 1e-9);
      }
    }
    return false;
  }

  /// Appends the face's hits: from the flat face's hit, or (`grid`) from starts all over it.
  void HitFace(const Ray& ray, const ParametricFace& face, bool grid, std::vector<Hit>& hits) const
  {
    Hit hit;
    if (grid)
    {
      constexpr int N = 4;
      for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j)
        {
          const double u = (i + 0.5) / N, v = (j + 0.5) / N;
          if ((!face.Triangle || u + v <= 1.0) && this->SolveFaceHit(ray, face, u, v, hit))
            hits.push_back(hit);
        }
      return;
    }
    double u, v;
    switch (this->FlatFaceHit(ray, face, u, v))
    {
      case FlatHit::Off:
        return;
      case FlatHit::Grazing:
        this->HitFace(ray, face, true, hits); // the plane tells little about where a grazing ray meets
        return;
      default:
        break;
    }
    if (!this->SolveFaceHit(ray, face, u, v, hit))
    {
      this->HitFace(ray, face, true, hits); // Newton left the face: the hit may lie elsewhere on it
      return;
    }
    hits.push_back(hit);
    // A curved face may be crossed twice, on either side of where the ray meets its plane: start
    // again mirrored across the flat hit.
    const glm::dvec2 first = this->FaceCoordinates(face, hit.Xi);
    const double mirroredU = 2.0 * u - first.x, mirroredV = 2.0 * v - first.y;
    if (face.Contains(mirroredU, mirroredV, 1.0) && this->SolveFaceHit(ray, face, mirroredU, mirroredV, hit))
      hits.push_back(hit);
  }

  /// (u, v) of a parametric point on the face.
  static glm::dvec2 FaceCoordinates(const ParametricFace& face, const glm::dvec3& xi)
  {
    return PlaneCoordinates(xi - face.Origin, face.U, face.V);
  }

  /// The (u, v) with u du + v dv closest to p (least squares).
  static glm::dvec2 PlaneCoordinates(const glm::dvec3& p, const glm::dvec3& du, const glm::dvec3& dv)
  {
    const double uu = glm::dot(du, du), uv = glm::dot(du, dv), vv = glm::dot(dv, dv);
    const double det = uu * vv - uv * uv;
    return { (vv * glm::dot(p, du) - uv * glm::dot(p, dv)) / det, (uu * glm::dot(p, dv) - uv * glm::dot(p, du)) / det };
  }

  enum class FlatHit
  {
    Near,    // (u, v) is where the ray meets the plane through the face's corners, near the face
    Off,     // that lies far off the face
    Grazing, // the ray runs nearly along that plane
  };

  /// Where the ray meets the plane through the face's corners, in the face's (u, v) (least squares
  /// over its first three corners).
  FlatHit FlatFaceHit(const Ray& ray, const ParametricFace& face, double& u, double& v) const
  {
    const glm::dvec3 origin = ray.Origin - this->Anchor;
    const glm::dvec3 a = this->Map(face.At(0, 0), nullptr);
    const glm::dvec3 du = this->Map(face.At(1, 0), nullptr) - a;
    const glm::dvec3 dv = this->Map(face.At(0, 1), nullptr) - a;
    const glm::dvec3 normal = glm::cross(du, dv);
    const double along = glm::dot(normal, ray.Direction);
    if (!(std::abs(along) > 0.2 * glm::length(normal)))
      return FlatHit::Grazing;
    const glm::dvec2 uv = PlaneCoordinates(origin + (glm::dot(normal, a - origin) / along) * ray.Direction - a, du, dv);
    u = uv.x;
    v = uv.y;
    return face.Contains(u, v, 3.0) ? FlatHit::Near : FlatHit::Off; // a curved face reaches past its plane
  }

  /// Hits in ray order, those at the same point (an edge or corner shared by faces) once.
  void SortAndMerge(std::vector<Hit>& hits) const
  {
    std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.T < b.T; });
    std::size_t kept = 0;
    for (std::size_t i = 0; i < hits.size(); ++i)
    {
      if (kept > 0 && hits[i].T - hits[kept - 1].T <= 1e-10 * this->Size)
        continue;
      hits[kept++] = hits[i];
    }
    hits.resize(kept);
  }

  CellFamily Family;
  Basis TheBasis;
  int Nodes;
  glm::dvec3 Anchor{ 0.0 };
  double Size = 1.0;
  glm::dvec3 Positions[MaximumNodes];
  double Values[MaximumNodes];
};
} // namespace uv

#endif
