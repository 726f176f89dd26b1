// Splitting a general polyhedron (VTK_POLYHEDRON's face stream) into positively oriented tetrahedra,
// free of VTK so it can be tested alone. The rules extend uvLinearCellSplit.h's:
//
// - Every face is fanned from its vertex of smallest global id (uv::FanFromLowest), so two cells
//   sharing a face, whatever their types, cut it into the same triangles.
// - A convex polyhedron is split as the cone from its smallest-id vertex m over the faces that do not
//   contain m, exactly as the fixed cell types are: no new point, and a hexahedron written as a
//   polyhedron gives the same tets as the VTK_HEXAHEDRON.
// - A polyhedron that is not convex, or convex but flat as seen from m (m in the plane of a face that
//   does not contain it, when two neighbouring faces are coplanar), gets one new point, its centre:
//   the mean of its distinct vertices (the caller gives every point-data array the same mean). It is
//   split as the cone from the centre over every face's fan; when a tet of that cone is not positive
//   the polyhedron is not star-shaped with respect to its centre, and that is an error.
//
// Face orientation in the stream does not matter: the faces are oriented consistently across their
// shared edges, then outwards by the sign of the enclosed volume. Errors (returned as text, the
// polyhedron gets no tets): a face with fewer than 3 points or a repeated point, a point id out of
// range, coincident points, a face that is not planar, not strictly convex as a polygon (hanging nodes
// on straight angles included, since their fans would not conform) or self-intersecting, faces that
// do not close (every edge must be used by exactly two faces), cannot be oriented or form several
// surfaces, a cell of no volume, and a non-star-shaped cell as above.
//
// Lengths are compared with PolyhedronTolerance times the cell's bounding-box diagonal, angles by
// their sine with PolyhedronTolerance, so the rules do not depend on the mesh's units.
#ifndef uvPolyhedronSplit_h
#define uvPolyhedronSplit_h

#include "uvLinearCellSplit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace uv
{

constexpr double PolyhedronTolerance = 1e-6;

template <typename IdType>
struct PolyhedronSplit
{
  /// Stands for the added centre point in Tets.
  static constexpr IdType CentreId = -1;
  std::vector<std::array<IdType, 4>> Tets; // global point ids, positively oriented
  bool HasCentre = false;
  std::array<double, 3> Centre{};
  std::vector<IdType> Vertices; // distinct point ids, ascending: the centre is their mean
  std::string Error;            // why the polyhedron has no tets; empty when it was split
};

namespace polyhedron_detail
{
using Vec = std::array<double, 3>;

inline Vec Sub(const Vec& a, const Vec& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
inline Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
inline double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline double Norm(const Vec& a)
{
  return std::sqrt(Dot(a, a));
}

template <typename IdType>
using Faces = std::vector<std::vector<IdType>>;

/// Reads (numFaces, n0, ids..., n1, ids...) from `length` values; checks sizes, ranges, repeats.
template <typename IdType>
bool ParseFaces(const IdType* stream, std::size_t length, IdType numPoints, Faces<IdType>& faces,
  std::string& error)
{
  if (length < 1 || stream[0] < 4)
  {
    error = "a polyhedron needs at least 4 faces";
    return false;
  }
  std::size_t at = 1;
  for (IdType f = 0; f < stream[0]; ++f)
  {
    const IdType n = at < length ? stream[at] : 0;
    if (at >= length || (n >= 0 && at + 1 + static_cast<std::size_t>(n) > length))
    {
      error = "the face stream ends inside face " + std::to_string(f);
      return false;
    }
    if (n < 3)
    {
      error = "face " + std::to_string(f) + " has fewer than 3 points";
      return false;
    }
    std::vector<IdType> face(stream + at + 1, stream + at + 1 + n);
    std::vector<IdType> sorted = face;
    std::sort(sorted.begin(), sorted.end());
    if (sorted.front() < 0 || sorted.back() >= numPoints)
    {
      error = "face " + std::to_string(f) + " has a point id out of range";
      return false;
    }
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    {
      error = "face " + std::to_string(f) + " repeats point " +
        std::to_string(*std::adjacent_find(sorted.begin(), sorted.end()));
      return false;
    }
    faces.push_back(std::move(face));
    at += 1 + static_cast<std::size_t>(n);
  }
  return true;
}

/// Faces using each undirected edge (smaller id first), with whether they run it forwards.
template <typename IdType>
std::map<std::pair<IdType, IdType>, std::vector<std::pair<std::size_t, bool>>> EdgeUses(
  const Faces<IdType>& faces)
{
  std::map<std::pair<IdType, IdType>, std::vector<std::pair<std::size_t, bool>>> uses;
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    for (std::size_t i = 0; i < faces[f].size(); ++i)
    {
      const IdType a = faces[f][i], b = faces[f][(i + 1) % faces[f].size()];
      uses[{ std::min(a, b), std::max(a, b) }].push_back({ f, a < b });
    }
  }
  return uses;
}

/// Checks the faces close (each edge used by two faces) and reverses faces so that every shared
/// edge is run once each way: a consistently oriented, connected surface.
template <typename IdType>
bool OrientConsistently(Faces<IdType>& faces, std::string& error)
{
  const auto uses = EdgeUses(faces);
  // Each face's neighbours, and whether a neighbour must be flipped relative to the face.
  std::vector<std::vector<std::pair<std::size_t, bool>>> neighbours(faces.size());
  for (const auto& edge : uses)
  {
    if (edge.second.size() != 2)
    {
      error = "edge (" + std::to_string(edge.first.first) + ", " + std::to_string(edge.first.second) +
        ") is used by " + std::to_string(edge.second.size()) + " face(s), not 2: the faces do not close";
      return false;
    }
    const auto& [f, forwardF] = edge.second[0];
    const auto& [g, forwardG] = edge.second[1];
    neighbours[f].push_back({ g, forwardF == forwardG });
    neighbours[g].push_back({ f, forwardF == forwardG });
  }
  std::vector<int> flip(faces.size(), -1); // -1: not reached yet
  std::vector<std::size_t> stack = { 0 };
  flip[0] = 0;
  while (!stack.empty())
  {
    const std::size_t f = stack.back();
    stack.pop_back();
    for (const auto& [g, opposite] : neighbours[f])
    {
      const int wanted = opposite ? 1 - flip[f] : flip[f];
      if (flip[g] == -1)
      {
        flip[g] = wanted;
        stack.push_back(g);
      }
      else if (flip[g] != wanted)
      {
        error = "the faces cannot be oriented consistently";
        return false;
      }
    }
  }
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    if (flip[f] == -1)
    {
      error = "the faces form more than one closed surface";
      return false;
    }
    if (flip[f] == 1)
    {
      std::reverse(faces[f].begin(), faces[f].end());
    }
  }
  return true;
}

/// Six times the volume enclosed by consistently oriented faces (positive when they face outwards),
/// by the divergence theorem over fans from each face's first vertex, relative to `origin`.
template <typename IdType, typename PointOf>
double SixEnclosedVolume(const Faces<IdType>& faces, PointOf&& pointOf, const Vec& origin)
{
  double six = 0.0;
  for (const std::vector<IdType>& face : faces)
  {
    for (std::size_t i = 1; i + 1 < face.size(); ++i)
    {
      six += SixSignedVolume(origin, pointOf(face[0]), pointOf(face[i]), pointOf(face[i + 1]));
    }
  }
  return six;
}

/// Newell's area vector of a polygon: its normal times twice its area, exact for planar polygons.
template <typename IdType, typename PointOf>
Vec AreaVector(const std::vector<IdType>& face, PointOf&& pointOf)
{
  Vec sum{ 0, 0, 0 };
  const Vec first = pointOf(face[0]);
  for (std::size_t i = 1; i + 1 < face.size(); ++i)
  {
    const Vec c = Cross(Sub(pointOf(face[i]), first), Sub(pointOf(face[i + 1]), first));
    for (int d = 0; d < 3; ++d)
    {
      sum[d] += c[d];
    }
  }
  return sum;
}

/// A face's plane: a point on it (the vertex mean) and its unit normal along the face's orientation.
struct Plane
{
  Vec Point;
  Vec Normal;
};

template <typename IdType, typename PointOf>
Plane FacePlane(const std::vector<IdType>& face, PointOf&& pointOf)
{
  Plane plane{ { 0, 0, 0 }, AreaVector(face, pointOf) };
  const double length = Norm(plane.Normal);
  for (int d = 0; d < 3; ++d)
  {
    plane.Normal[d] = length > 0.0 ? plane.Normal[d] / length : 0.0;
  }
  for (IdType id : face)
  {
    const Vec p = pointOf(id);
    for (int d = 0; d < 3; ++d)
    {
      plane.Point[d] += p[d] / face.size();
    }
  }
  return plane;
}

/// Planar within `tolerance`, no coincident points, every corner turning the same way by more than
/// PolyhedronTolerance (sine), and one turn in all: a strictly convex, simple polygon.
template <typename IdType, typename PointOf>
bool CheckFace(const std::vector<IdType>& face, PointOf&& pointOf, double tolerance, std::string& error)
{
  const Plane plane = FacePlane(face, pointOf);
  const std::size_t n = face.size();
  double turning = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const Vec p = pointOf(face[i]);
    const Vec in = Sub(p, pointOf(face[(i + n - 1) % n]));
    const Vec out = Sub(pointOf(face[(i + 1) % n]), p);
    if (Norm(out) <= tolerance)
    {
      error = "points " + std::to_string(face[i]) + " and " + std::to_string(face[(i + 1) % n]) + " coincide";
      return false;
    }
    if (std::abs(Dot(Sub(p, plane.Point), plane.Normal)) > tolerance)
    {
      error = "is not planar";
      return false;
    }
    const double sine = Dot(Cross(in, out), plane.Normal) / (Norm(in) * Norm(out));
    if (!(sine > PolyhedronTolerance))
    {
      error = "is not strictly convex (at point " + std::to_string(face[i]) + ")";
      return false;
    }
    turning += std::atan2(Dot(Cross(in, out), plane.Normal), Dot(in, out));
  }
  // All turns positive: the total is a whole number of turns, one for a simple polygon.
  if (turning > 3.0 * std::acos(-1.0))
  {
    error = "intersects itself";
    return false;
  }
  return true;
}

/// True when every vertex lies on the inner side of every (outward) face plane, within `tolerance`.
template <typename IdType, typename PointOf>
bool IsConvex(const Faces<IdType>& faces, const std::vector<IdType>& vertices, PointOf&& pointOf,
  double tolerance)
{
  for (const std::vector<IdType>& face : faces)
  {
    const Plane plane = FacePlane(face, pointOf);
    for (IdType id : vertices)
    {
      if (Dot(Sub(pointOf(id), plane.Point), plane.Normal) > tolerance)
      {
        return false;
      }
    }
  }
  return true;
}

/// Tets from `apex` over the outward fans of the faces that do not contain `apexId`; false when one
/// is not positive, i.e. its apex is not more than `tolerance` inside its base triangle's plane.
template <typename IdType, typename PointOf>
bool Cone(const Faces<IdType>& faces, IdType apexId, const Vec& apex, PointOf&& pointOf,
  double tolerance, std::vector<std::array<IdType, 4>>& tets)
{
  bool positive = true;
  for (const std::vector<IdType>& face : faces)
  {
    if (std::find(face.begin(), face.end(), apexId) != face.end())
    {
      continue;
    }
    FanFromLowest(
      static_cast<int>(face.size()), [&](int i) { return face[i]; },
      [&](int i, int j, int k) {
        const Vec a = pointOf(face[i]), b = pointOf(face[j]), c = pointOf(face[k]);
        // The height of the apex over the reversed triangle: six volumes over twice the area.
        const double height = SixSignedVolume(a, c, b, apex) / Norm(Cross(Sub(b, a), Sub(c, a)));
        positive = positive && height > tolerance;
        tets.push_back({ face[i], face[k], face[j], apexId });
      });
  }
  return positive;
}

/// The cell's distinct vertices, ascending, and its bounding-box diagonal.
template <typename IdType, typename PointOf>
double Vertices(const Faces<IdType>& faces, PointOf&& pointOf, std::vector<IdType>& vertices)
{
  for (const std::vector<IdType>& face : faces)
  {
    vertices.insert(vertices.end(), face.begin(), face.end());
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  Vec low = pointOf(vertices[0]), high = low;
  for (IdType id : vertices)
  {
    const Vec p = pointOf(id);
    for (int d = 0; d < 3; ++d)
    {
      low[d] = std::min(low[d], p[d]);
      high[d] = std::max(high[d], p[d]);
    }
  }
  return Norm(Sub(high, low));
}
} // namespace polyhedron_detail

/// Checks and orients a polyhedron's faces: true and `faces` outward, or false with `error`.
/// `scale` receives the bounding-box diagonal and `vertices` the distinct ids, ascending.
template <typename IdType, typename PointOf>
bool ReadPolyhedron(const IdType* stream, std::size_t length, IdType numPoints, PointOf&& pointOf,
  polyhedron_detail::Faces<IdType>& faces, std::vector<IdType>& vertices, double& scale, std::string& error)
{
  using namespace polyhedron_detail;
  if (!ParseFaces(stream, length, numPoints, faces, error) || !OrientConsistently(faces, error))
  {
    return false;
  }
  scale = Vertices(faces, pointOf, vertices);
  const double tolerance = PolyhedronTolerance * scale;
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    std::string why;
    if (!CheckFace(faces[f], pointOf, tolerance, why))
    {
      error = "face " + std::to_string(f) + " " + why;
      return false;
    }
  }
  const double six = SixEnclosedVolume(faces, pointOf, pointOf(vertices[0]));
  if (!(std::abs(six) > PolyhedronTolerance * scale * scale * scale))
  {
    error = "the polyhedron has no volume";
    return false;
  }
  if (six < 0.0)
  {
    for (std::vector<IdType>& face : faces)
    {
      std::reverse(face.begin(), face.end());
    }
  }
  return true;
}

/// Splits the polyhedron of a face stream (numFaces, n0, ids..., n1, ids...) of `length` values.
/// pointOf(id) gives a point's coordinates as std::array<double, 3>; ids must be below numPoints.
template <typename IdType, typename PointOf>
PolyhedronSplit<IdType> SplitPolyhedron(
  const IdType* stream, std::size_t length, IdType numPoints, PointOf&& pointOf)
{
  using namespace polyhedron_detail;
  PolyhedronSplit<IdType> split;
  Faces<IdType> faces;
  double scale = 0.0;
  if (!ReadPolyhedron(stream, length, numPoints, pointOf, faces, split.Vertices, scale, split.Error))
  {
    split.Vertices.clear();
    return split;
  }
  const double tolerance = PolyhedronTolerance * scale;
  const IdType lowest = split.Vertices.front();
  if (IsConvex(faces, split.Vertices, pointOf, tolerance) &&
    Cone(faces, lowest, pointOf(lowest), pointOf, tolerance, split.Tets))
  {
    return split;
  }
  split.Tets.clear();
  split.HasCentre = true;
  for (IdType id : split.Vertices)
  {
    const Vec p = pointOf(id);
    for (int d = 0; d < 3; ++d)
    {
      split.Centre[d] += p[d] / split.Vertices.size();
    }
  }
  if (!Cone(faces, PolyhedronSplit<IdType>::CentreId, split.Centre, pointOf, tolerance, split.Tets))
  {
    split.Tets.clear();
    split.Error = "the polyhedron is not convex and not star-shaped with respect to its centre "
                  "(the mean of its vertices)";
  }
  return split;
}

} // namespace uv

#endif
