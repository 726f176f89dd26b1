// Rays against linear tetrahedra and trilinear hexahedra, in double precision, free of VTK.
//
// Shared faces must give bit-identical hits from both cells, or rays leak through cracks; so every
// face is built from its vertices in a canonical order (by global id) before any arithmetic.
#ifndef uvRayCellGeometry_h
#define uvRayCellGeometry_h

#include "uvLinearCellSplit.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace uv
{

struct Ray
{
  glm::dvec3 Origin;
  glm::dvec3 Direction; // unit length, so t is a distance
};

struct Interval
{
  double Enter;
  double Exit;
};

/// A ray lying exactly in a face's plane belongs to one of the two cells sharing the face: the one
/// whose outward normal is lexicographically negative. Both cells compute the same plane (canonical
/// vertex order) with opposite normals, so exactly one claims it and the matter is counted once.
inline bool ClaimsRayInFacePlane(const glm::dvec3& outwardNormal)
{
  if (outwardNormal.x != 0.0)
  {
    return outwardNormal.x < 0.0;
  }
  if (outwardNormal.y != 0.0)
  {
    return outwardNormal.y < 0.0;
  }
  return outwardNormal.z < 0.0;
}

/// The part of the ray inside a tetrahedron, or false. `ids` order the face arithmetic.
inline bool IntersectTetrahedron(
  const Ray& ray, const glm::dvec3 p[4], const std::int64_t ids[4], Interval& inside)
{
  double enter = -std::numeric_limits<double>::infinity();
  double exit = std::numeric_limits<double>::infinity();
  for (int opposite = 0; opposite < 4; ++opposite)
  {
    int face[3], n = 0;
    for (int v = 0; v < 4; ++v)
    {
      if (v != opposite)
      {
        face[n++] = v;
      }
    }
    std::sort(face, face + 3, [&](int x, int y) { return ids[x] < ids[y]; });
    const glm::dvec3& a = p[face[0]];
    glm::dvec3 normal = glm::cross(p[face[1]] - a, p[face[2]] - a);
    if (glm::dot(normal, p[opposite] - a) > 0.0)
    {
      normal = -normal; // outward
    }
    const double rate = glm::dot(normal, ray.Direction);
    const double room = glm::dot(normal, a - ray.Origin);
    if (rate > 0.0)
    {
      exit = std::min(exit, room / rate);
    }
    else if (rate < 0.0)
    {
      enter = std::max(enter, room / rate);
    }
    else if (room < 0.0 || (room == 0.0 && !ClaimsRayInFacePlane(normal)))
    {
      return false; // parallel and outside, or in the face's plane and left to the neighbour
    }
  }
  inside = { enter, exit };
  return exit > enter;
}

/// Scalar at x in a tetrahedron by barycentric coordinates.
inline double TetrahedronScalar(const glm::dvec3 p[4], const double f[4], const glm::dvec3& x)
{
  const glm::dmat3 edges(p[1] - p[0], p[2] - p[0], p[3] - p[0]);
  const glm::dvec3 b = glm::inverse(edges) * (x - p[0]);
  return f[0] + b.x * (f[1] - f[0]) + b.y * (f[2] - f[0]) + b.z * (f[3] - f[0]);
}

/// Ray parameters where the ray meets the bilinear patch through q0, q1, q2, q3 (in cyclic order).
/// Appends 0, 1 or 2 values of t to `hits`.
inline void IntersectBilinearPatch(const Ray& ray, const glm::dvec3& q0, const glm::dvec3& q1,
  const glm::dvec3& q2, const glm::dvec3& q3, std::vector<double>& hits)
{
  // P(u,v) = q0 + u b + v c + u v e.
  const glm::dvec3 b = q1 - q0, c = q3 - q0, e = q2 - q1 - q3 + q0;
  // Two planes through the ray: n1, n2 perpendicular to it.
  const glm::dvec3 d = ray.Direction;
  const glm::dvec3 helper = std::abs(d.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 n1 = glm::normalize(glm::cross(d, helper));
  const glm::dvec3 n2 = glm::cross(d, n1);
  const glm::dvec3 a = q0 - ray.Origin;
  const double A1 = glm::dot(n1, a), B1 = glm::dot(n1, b), C1 = glm::dot(n1, c), E1 = glm::dot(n1, e);
  const double A2 = glm::dot(n2, a), B2 = glm::dot(n2, b), C2 = glm::dot(n2, c), E2 = glm::dot(n2, e);
  // Eliminating u gives a quadratic in v.
  const double qa = C2 * E1 - C1 * E2;
  const double qb = A2 * E1 + C2 * B1 - A1 * E2 - C1 * B2;
  const double qc = A2 * B1 - A1 * B2;
  double roots[2];
  int count = 0;
  const double scale = std::max({ std::abs(qa), std::abs(qb), std::abs(qc) });
  if (scale == 0.0)
  {
    return;
  }
  if (std::abs(qa) <= 1e-14 * scale)
  {
    if (qb != 0.0)
    {
      roots[count++] = -qc / qb;
    }
  }
  else
  {
    const double discriminant = qb * qb - 4.0 * qa * qc;
    if (discriminant < 0.0)
    {
      return;
    }
    // The stable pair of formulas: no cancellation in either root.
    const double q = -0.5 * (qb + std::copysign(std::sqrt(discriminant), qb));
    roots[count++] = q / qa;
    if (q != 0.0)
    {
      roots[count++] = qc / q;
    }
  }
  const double slack = 1e-12;
  for (int r = 0; r < count; ++r)
  {
    const double v = roots[r];
    if (v < -slack || v > 1.0 + slack)
    {
      continue;
    }
    const double denominator1 = B1 + E1 * v, denominator2 = B2 + E2 * v;
    double u;
    if (std::abs(denominator1) >= std::abs(denominator2))
    {
      if (denominator1 == 0.0)
      {
        continue;
      }
      u = -(A1 + C1 * v) / denominator1;
    }
    else
    {
      u = -(A2 + C2 * v) / denominator2;
    }
    if (u < -slack || u > 1.0 + slack)
    {
      continue;
    }
    const glm::dvec3 point = q0 + u * b + v * c + u * v * e;
    hits.push_back(glm::dot(point - ray.Origin, d));
  }
}

/// Corners of VTK's hexahedron on the unit cube, in VTK order.
inline constexpr std::array<std::array<int, 3>, 8> HexahedronCorners = { { { 0, 0, 0 }, { 1, 0, 0 },
  { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } } };

/// An isoparametric linear 3D cell: its map from parametric space (with Jacobian), its scalar, its
/// parametric domain and its faces (VTK's local numbering, outward; triangles have Size 3).
struct IsoparametricShape
{
  int Corners;
  const LocalFace* Faces;
  int NumberOfFaces;
  // Shape functions and their derivatives at xi.
  void (*Basis)(const glm::dvec3& xi, double n[8], glm::dvec3 dn[8]);
  bool (*Contains)(const glm::dvec3& xi, double margin);
  glm::dvec3 Centre;
};

inline void HexahedronBasis(const glm::dvec3& xi, double n[8], glm::dvec3 dn[8])
{
  for (int k = 0; k < 8; ++k)
  {
    const auto& c = HexahedronCorners[k];
    const double wx = c[0] ? xi.x : 1.0 - xi.x, wy = c[1] ? xi.y : 1.0 - xi.y, wz = c[2] ? xi.z : 1.0 - xi.z;
    n[k] = wx * wy * wz;
    dn[k] = glm::dvec3((c[0] ? 1.0 : -1.0) * wy * wz, (c[1] ? 1.0 : -1.0) * wx * wz, (c[2] ? 1.0 : -1.0) * wx * wy);
  }
}

/// VTK's wedge: (1 - r - s, r, s) on the triangle, times (1 - t) or t.
inline void WedgeBasis(const glm::dvec3& xi, double n[8], glm::dvec3 dn[8])
{
  const double l[3] = { 1.0 - xi.x - xi.y, xi.x, xi.y };
  const glm::dvec2 dl[3] = { { -1.0, -1.0 }, { 1.0, 0.0 }, { 0.0, 1.0 } };
  for (int k = 0; k < 6; ++k)
  {
    const int i = k % 3;
    const double w = k < 3 ? 1.0 - xi.z : xi.z;
    n[k] = l[i] * w;
    dn[k] = glm::dvec3(dl[i].x * w, dl[i].y * w, k < 3 ? -l[i] : l[i]);
  }
}

/// VTK's pyramid: a hexahedron whose top face collapses onto the apex.
inline void PyramidBasis(const glm::dvec3& xi, double n[8], glm::dvec3 dn[8])
{
  const double r = xi.x, s = xi.y, t = xi.z;
  n[0] = (1 - r) * (1 - s) * (1 - t);
  n[1] = r * (1 - s) * (1 - t);
  n[2] = r * s * (1 - t);
  n[3] = (1 - r) * s * (1 - t);
  n[4] = t;
  dn[0] = { -(1 - s) * (1 - t), -(1 - r) * (1 - t), -(1 - r) * (1 - s) };
  dn[1] = { (1 - s) * (1 - t), -r * (1 - t), -r * (1 - s) };
  dn[2] = { s * (1 - t), r * (1 - t), -r * s };
  dn[3] = { -s * (1 - t), (1 - r) * (1 - t), -(1 - r) * s };
  dn[4] = { 0, 0, 1 };
}

inline bool InUnitCube(const glm::dvec3& xi, double m)
{
  return xi.x >= -m && xi.y >= -m && xi.z >= -m && xi.x <= 1 + m && xi.y <= 1 + m && xi.z <= 1 + m;
}

inline bool InPrism(const glm::dvec3& xi, double m)
{
  return xi.x >= -m && xi.y >= -m && xi.x + xi.y <= 1 + m && xi.z >= -m && xi.z <= 1 + m;
}

inline const IsoparametricShape& HexahedronShape()
{
  static const IsoparametricShape shape{ 8, HexahedronFaces.data(), 6, HexahedronBasis, InUnitCube,
    glm::dvec3(0.5) };
  return shape;
}
inline const IsoparametricShape& WedgeShape()
{
  static const IsoparametricShape shape{ 6, WedgeFaces.data(), 5, WedgeBasis, InPrism,
    glm::dvec3(1.0 / 3.0, 1.0 / 3.0, 0.5) };
  return shape;
}
inline const IsoparametricShape& PyramidShape()
{
  static const IsoparametricShape shape{ 5, PyramidFaces.data(), 5, PyramidBasis, InUnitCube,
    glm::dvec3(0.5, 0.5, 0.25) };
  return shape;
}

inline glm::dvec3 IsoparametricPoint(
  const IsoparametricShape& shape, const glm::dvec3 p[8], const glm::dvec3& xi, glm::dmat3* jacobian)
{
  double n[8];
  glm::dvec3 dn[8];
  shape.Basis(xi, n, dn);
  glm::dvec3 x(0.0);
  glm::dmat3 j(0.0);
  for (int k = 0; k < shape.Corners; ++k)
  {
    x += n[k] * p[k];
    j[0] += dn[k].x * p[k];
    j[1] += dn[k].y * p[k];
    j[2] += dn[k].z * p[k];
  }
  if (jacobian)
  {
    *jacobian = j;
  }
  return x;
}

inline double IsoparametricScalar(const IsoparametricShape& shape, const double f[8], const glm::dvec3& xi)
{
  double n[8];
  glm::dvec3 dn[8];
  shape.Basis(xi, n, dn);
  double value = 0.0;
  for (int k = 0; k < shape.Corners; ++k)
  {
    value += n[k] * f[k];
  }
  return value;
}

/// Solves map(xi) = target for xi by safeguarded Newton (steps limited to half the reference cell,
/// iterates kept near it) from the given xi; `map(xi, jacobian)` returns the point and fills its
/// Jacobian. Returns false if it does not converge.
///
/// Converged means the step fell below 1e-12, or (where the cell's shape limits what double
/// precision resolves) stopped shrinking while the point it maps to lies within 1e-10 of `size` from
/// the target: a fixed step threshold near machine precision cannot be reached on every cell, and
/// calling those failures lost whole cells.
template <typename Map>
bool SafeguardedNewton(const Map& map, const glm::dvec3& target, double size, glm::dvec3& xi)
{
  double previous = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration < 60; ++iteration)
  {
    glm::dmat3 jacobian;
    const glm::dvec3 residual = map(xi, jacobian) - target;
    const double det = glm::determinant(jacobian);
    if (!(std::abs(det) > 0.0) || !std::isfinite(det))
    {
      return false;
    }
    glm::dvec3 step = glm::inverse(jacobian) * residual;
    const double longest = std::max({ std::abs(step.x), std::abs(step.y), std::abs(step.z) });
    if (!std::isfinite(longest))
    {
      return false;
    }
    if (longest < 1e-12)
    {
      xi -= step;
      return true;
    }
    if (longest >= 0.5 * previous && glm::length(residual) <= 1e-10 * size)
    {
      return true; // stalled at rounding with the point found
    }
    previous = longest;
    if (longest > 0.5)
    {
      step *= 0.5 / longest;
    }
    xi = glm::clamp(xi - step, glm::dvec3(-0.5), glm::dvec3(1.5));
  }
  return false;
}

/// Parametric coordinates of x in a linear isoparametric cell (SafeguardedNewton), working in
/// coordinates relative to the cell's first corner, so a cell far from the origin solves as well as
/// one at it.
inline bool InverseIsoparametric(
  const IsoparametricShape& shape, const glm::dvec3 p[8], const glm::dvec3& x, glm::dvec3& xi)
{
  glm::dvec3 local[8];
  glm::dvec3 low(0.0), high(0.0);
  for (int k = 0; k < shape.Corners; ++k)
  {
    local[k] = p[k] - p[0];
    low = glm::min(low, local[k]);
    high = glm::max(high, local[k]);
  }
  const double size = std::max({ high.x - low.x, high.y - low.y, high.z - low.z });
  const auto map = [&](const glm::dvec3& at, glm::dmat3& jacobian) {
    return IsoparametricPoint(shape, local, at, &jacobian);
  };
  return SafeguardedNewton(map, x - p[0], size, xi);
}

/// Hexahedron shorthands (the hexahedral mapper's math tests use them).
inline bool InverseTrilinear(const glm::dvec3 p[8], const glm::dvec3& x, glm::dvec3& xi)
{
  return InverseIsoparametric(HexahedronShape(), p, x, xi);
}

/// Face f's corners in the order both cells sharing it use (start at the smallest id, go towards
/// its smaller-id neighbour: the same patch arithmetic from either side); a triangle repeats its
/// last corner.
inline void CanonicalFaceCorners(
  const IsoparametricShape& shape, int f, const glm::dvec3 p[8], const std::int64_t ids[8], glm::dvec3 q[4])
{
  const LocalFace& face = shape.Faces[f];
  int start = 0;
  for (int i = 1; i < face.Size; ++i)
  {
    start = ids[face.Vertices[i]] < ids[face.Vertices[start]] ? i : start;
  }
  const int size = face.Size;
  const int next = face.Vertices[(start + 1) % size], previous = face.Vertices[(start + size - 1) % size];
  const int step = ids[next] < ids[previous] ? 1 : size - 1;
  for (int i = 0; i < size; ++i)
  {
    q[i] = p[face.Vertices[(start + step * i) % size]];
  }
  if (size == 3)
  {
    q[3] = q[2];
  }
}

/// Whether the cell claims the part of the ray around `x`. Where the ray runs in the plane of one of
/// its flat faces (within rounding), both cells sharing the face hold that part in their closure:
/// only the one ClaimsRayInFacePlane picks counts it, as for tetrahedra. The face's normal is the
/// same product of canonical corners in both cells, each turning it outward: exact opposites. Along
/// an edge (two such faces), of the cells around it only the one claiming by both counts it.
inline bool ClaimsPartAlongFaces(
  const IsoparametricShape& shape, const Ray& ray, const glm::dvec3 p[8], const std::int64_t ids[8], const glm::dvec3& x)
{
  glm::dvec3 centre(0.0);
  for (int k = 0; k < shape.Corners; ++k)
  {
    centre += p[k] / double(shape.Corners);
  }
  const glm::dvec3 direction = glm::normalize(ray.Direction);
  for (int f = 0; f < shape.NumberOfFaces; ++f)
  {
    glm::dvec3 q[4];
    CanonicalFaceCorners(shape, f, p, ids, q);
    glm::dvec3 normal = glm::cross(q[2] - q[0], q[3] - q[1]);
    const double area = glm::length(normal), size = glm::length(q[2] - q[0]) + glm::length(q[3] - q[1]);
    if (!(area > 0.0) || std::abs(glm::dot(normal, q[1] - q[0])) > 1e-9 * area * size)
    {
      continue; // collapsed, or not flat: a ray does not run inside a curved patch
    }
    if (glm::dot(normal, centre - q[0]) > 0.0)
    {
      normal = -normal; // outward
    }
    const bool alongPlane = std::abs(glm::dot(normal, direction)) <= 1e-9 * area &&
      std::abs(glm::dot(normal, x - q[0])) <= 1e-9 * area * size;
    if (alongPlane && !ClaimsRayInFacePlane(normal))
    {
      return false;
    }
  }
  return true;
}

/// The parts of the ray inside an isoparametric cell: its quadrilateral faces are bilinear patches
/// (a ray may enter a curved cell twice), triangles are patches with a repeated corner. `ids` give
/// the canonical face order. Appends to `parts`.
inline void IntersectIsoparametric(const IsoparametricShape& shape, const Ray& ray, const glm::dvec3 p[8],
  const std::int64_t ids[8], std::vector<Interval>& parts, std::vector<double>& scratch)
{
  scratch.clear();
  for (int f = 0; f < shape.NumberOfFaces; ++f)
  {
    glm::dvec3 q[4];
    CanonicalFaceCorners(shape, f, p, ids, q);
    IntersectBilinearPatch(ray, q[0], q[1], q[2], q[3], scratch);
  }
  std::sort(scratch.begin(), scratch.end());
  // Between consecutive hits the ray is inside or outside; test each gap's midpoint.
  for (std::size_t i = 0; i + 1 < scratch.size(); ++i)
  {
    const double a = scratch[i], b = scratch[i + 1];
    if (!(b - a > 1e-12 * (1.0 + std::abs(a))))
    {
      continue;
    }
    glm::dvec3 xi = shape.Centre;
    const glm::dvec3 middle = ray.Origin + 0.5 * (a + b) * ray.Direction;
    if (InverseIsoparametric(shape, p, middle, xi) && shape.Contains(xi, 1e-9) &&
      ClaimsPartAlongFaces(shape, ray, p, ids, middle))
    {
      if (!parts.empty() && parts.back().Exit == a)
      {
        parts.back().Exit = b; // the gap between two entries was a tangency: merge
      }
      else
      {
        parts.push_back({ a, b });
      }
    }
  }
}

inline void IntersectHexahedron(const Ray& ray, const glm::dvec3 p[8], const std::int64_t ids[8],
  std::vector<Interval>& parts, std::vector<double>& scratch)
{
  IntersectIsoparametric(HexahedronShape(), ray, p, ids, parts, scratch);
}

/// Axis-aligned boxes of cells in a bounding volume hierarchy (median split, leaves of <= 4).
class BoundingVolumeHierarchy
{
public:
  struct Box
  {
    glm::dvec3 Low{ std::numeric_limits<double>::infinity() };
    glm::dvec3 High{ -std::numeric_limits<double>::infinity() };
    void Add(const Box& other)
    {
      this->Low = glm::min(this->Low, other.Low);
      this->High = glm::max(this->High, other.High);
    }
  };

  /// `box` grown by a billionth of its diagonal. A ray in the plane of a cell's face, its direction
  /// off that plane by rounding, meets the exact boxes on one side of the plane only, and the cells
  /// there may leave it to their neighbours across (ClaimsRayInFacePlane): the cells on both sides
  /// must be offered it.
  static Box PaddedForRounding(const Box& box)
  {
    const glm::dvec3 pad(1e-9 * glm::length(box.High - box.Low));
    return { box.Low - pad, box.High + pad };
  }

  explicit BoundingVolumeHierarchy(std::vector<Box> cellBoxes)
    : CellBoxes(std::move(cellBoxes))
  {
    this->Order.resize(this->CellBoxes.size());
    for (std::size_t i = 0; i < this->Order.size(); ++i)
    {
      this->Order[i] = static_cast<std::int64_t>(i);
    }
    if (!this->Order.empty())
    {
      this->Build(0, static_cast<std::int64_t>(this->Order.size()));
    }
  }

  /// Calls visit(cell) for every cell whose box the ray crosses at t >= 0.
  template <typename Visit>
  void Traverse(const Ray& ray, Visit&& visit) const
  {
    if (this->Nodes.empty())
    {
      return;
    }
    const glm::dvec3 inverse = 1.0 / ray.Direction;
    std::int64_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0)
    {
      const Node& node = this->Nodes[stack[--top]];
      if (!Hits(node.Bounds, ray, inverse))
      {
        continue;
      }
      if (node.Count > 0)
      {
        for (std::int64_t i = node.First; i < node.First + node.Count; ++i)
        {
          visit(this->Order[i]);
        }
      }
      else
      {
        stack[top++] = node.Left;
        stack[top++] = node.Right;
      }
    }
  }

private:
  struct Node
  {
    Box Bounds;
    std::int64_t First = 0; // leaf: first index into Order
    std::int64_t Count = 0; // leaf: number of cells; 0 for inner nodes
    std::int64_t Left = 0;  // inner node: children
    std::int64_t Right = 0;
  };

  static bool Hits(const Box& box, const Ray& ray, const glm::dvec3& inverse)
  {
    double enter = 0.0, exit = std::numeric_limits<double>::infinity();
    for (int d = 0; d < 3; ++d)
    {
      double t0 = (box.Low[d] - ray.Origin[d]) * inverse[d];
      double t1 = (box.High[d] - ray.Origin[d]) * inverse[d];
      if (std::isnan(t0) || std::isnan(t1)) // ray in the slab's plane: inside if within it
      {
        if (ray.Origin[d] < box.Low[d] || ray.Origin[d] > box.High[d])
        {
          return false;
        }
        continue;
      }
      if (t0 > t1)
      {
        std::swap(t0, t1);
      }
      enter = std::max(enter, t0);
      exit = std::min(exit, t1);
    }
    return enter <= exit * (1.0 + 1e-12) + 1e-300;
  }

  std::int64_t Build(std::int64_t first, std::int64_t count)
  {
    const std::int64_t index = static_cast<std::int64_t>(this->Nodes.size());
    this->Nodes.push_back({});
    Box bounds, centres;
    for (std::int64_t i = first; i < first + count; ++i)
    {
      const Box& box = this->CellBoxes[this->Order[i]];
      bounds.Add(box);
      const glm::dvec3 centre = 0.5 * (box.Low + box.High);
      centres.Add({ centre, centre });
    }
    if (count <= 4)
    {
      this->Nodes[index].Bounds = bounds;
      this->Nodes[index].First = first;
      this->Nodes[index].Count = count;
      return index;
    }
    const glm::dvec3 extent = centres.High - centres.Low;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::int64_t half = count / 2;
    std::nth_element(this->Order.begin() + first, this->Order.begin() + first + half,
      this->Order.begin() + first + count, [&](std::int64_t a, std::int64_t b) {
        return this->CellBoxes[a].Low[axis] + this->CellBoxes[a].High[axis] <
          this->CellBoxes[b].Low[axis] + this->CellBoxes[b].High[axis];
      });
    const std::int64_t left = this->Build(first, half);
    const std::int64_t right = this->Build(first + half, count - half);
    this->Nodes[index].Bounds = bounds;
    this->Nodes[index].Left = left;
    this->Nodes[index].Right = right;
    return index;
  }

  std::vector<Box> CellBoxes;
  std::vector<std::int64_t> Order;
  std::vector<Node> Nodes;
};

} // namespace uv

#endif
