// Visibility across the gaps of a non-convex mesh of tetrahedra, free of VTK.
//
// The face order (uvFaceAdjacencyOrder.h) is exact wherever a ray goes from one tetrahedron into
// the next through a shared face. Where the mesh is not convex, a ray can leave it through a boundary
// face and enter it again further on; nothing orders those two tetrahedra, and the centroid order
// that stands in for a constraint is wrong for some pairs. An image only needs the order along the
// rays through its pixel centres, so the missing constraints are found by those rays (the idea of
// Silva, Mitchell and Williams' XMPVO, taken at the pixels): each boundary face is intersected with
// the rays of the pixels its projection covers, and along each ray the tetrahedron it enters next
// after leaving the mesh lies behind the one it left. Together with the face constraints, every
// ray's tetrahedra are then ordered back to front.
//
// A convex mesh has no gap; BoundaryIsConvex tells it once per mesh so that its views skip the rays,
// and FacesOffTheHull leaves out the faces no gap can lie next to.
#ifndef uvBoundaryGapOrder_h
#define uvBoundaryGapOrder_h

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

namespace uv
{

/// The rays of an image: pixel (x, y) looks along the ray through its centre (x + 0.5, y + 0.5),
/// from the near plane (parameter 0) towards the far plane (parameter 1). Model space, any projection.
struct PixelGrid
{
  glm::dmat4 ModelToClip{ 1.0 };
  int Width = 0, Height = 0;

  bool operator==(const PixelGrid& other) const
  {
    return this->ModelToClip == other.ModelToClip && this->Width == other.Width && this->Height == other.Height;
  }
  bool operator!=(const PixelGrid& other) const { return !(*this == other); }

  /// The ray of pixel (x, y): its point on the near plane and the step to the far plane.
  void Ray(int x, int y, const glm::dmat4& clipToModel, glm::dvec3& origin, glm::dvec3& step) const
  {
    const double u = 2.0 * (x + 0.5) / this->Width - 1.0, v = 2.0 * (y + 0.5) / this->Height - 1.0;
    const glm::dvec4 near = clipToModel * glm::dvec4(u, v, -1.0, 1.0), far = clipToModel * glm::dvec4(u, v, 1.0, 1.0);
    origin = glm::dvec3(near) / near.w;
    step = glm::dvec3(far) / far.w - origin;
  }
};

/// Every pixel's ray of a grid from three: the near and far points of a pixel's ray are affine in the
/// pixel under any projection (w is constant on a plane of constant depth).
struct PixelRays
{
  glm::dvec3 Origin0, OriginX, OriginY; ///< the ray's near point: Origin0 + x OriginX + y OriginY
  glm::dvec3 Step0, StepX, StepY;       ///< and its step to the far point, likewise

  explicit PixelRays(const PixelGrid& grid)
  {
    const glm::dmat4 clipToModel = glm::inverse(grid.ModelToClip);
    grid.Ray(0, 0, clipToModel, this->Origin0, this->Step0);
    grid.Ray(1, 0, clipToModel, this->OriginX, this->StepX);
    grid.Ray(0, 1, clipToModel, this->OriginY, this->StepY);
    this->OriginX -= this->Origin0, this->StepX -= this->Step0;
    this->OriginY -= this->Origin0, this->StepY -= this->Step0;
  }

  /// The ray of pixel (x, y).
  void At(int x, int y, glm::dvec3& origin, glm::dvec3& step) const
  {
    origin = this->Origin0 + double(x) * this->OriginX + double(y) * this->OriginY;
    step = this->Step0 + double(x) * this->StepX + double(y) * this->StepY;
  }
};

/// The pixels whose centres a triangle can cover, clipped to the grid; false where none (behind the
/// near plane or off the image). The part beyond the near plane is projected, so a triangle that
/// crosses it is bounded too.
inline bool ScreenBounds(const PixelGrid& grid, const glm::dvec3 (&p)[3], int& x0, int& x1, int& y0, int& y1)
{
  glm::dvec4 clip[3];
  for (int j = 0; j < 3; ++j)
    clip[j] = grid.ModelToClip * glm::dvec4(p[j], 1.0);
  // Clip against the near plane z >= -w (one Sutherland-Hodgman step), then project.
  glm::dvec4 kept[4];
  int count = 0;
  for (int j = 0; j < 3; ++j)
  {
    const glm::dvec4 &a = clip[j], &b = clip[(j + 1) % 3];
    const double da = a.z + a.w, db = b.z + b.w;
    if (da >= 0.0)
      kept[count++] = a;
    if ((da >= 0.0) != (db >= 0.0))
      kept[count++] = a + (b - a) * (da / (da - db));
  }
  if (count == 0)
    return false;
  double low[2] = { 1e300, 1e300 }, high[2] = { -1e300, -1e300 };
  for (int j = 0; j < count; ++j)
  {
    const double w = std::max(kept[j].w, 1e-300);
    const double sx = (kept[j].x / w + 1.0) * 0.5 * grid.Width, sy = (kept[j].y / w + 1.0) * 0.5 * grid.Height;
    low[0] = std::min(low[0], sx);
    high[0] = std::max(high[0], sx);
    low[1] = std::min(low[1], sy);
    high[1] = std::max(high[1], sy);
  }
  // Pixel centres x + 0.5 within the bounds, one pixel wider for rounding; clamped to the image in
  // double first, as a face just beyond the near plane can project billions of pixels away.
  const double xLow = std::floor(low[0] - 0.5) - 1.0, xHigh = std::ceil(high[0] - 0.5) + 1.0;
  const double yLow = std::floor(low[1] - 0.5) - 1.0, yHigh = std::ceil(high[1] - 0.5) + 1.0;
  if (xLow > grid.Width - 1.0 || yLow > grid.Height - 1.0 || xHigh < 0.0 || yHigh < 0.0)
    return false;
  x0 = static_cast<int>(std::max(0.0, xLow));
  y0 = static_cast<int>(std::max(0.0, yLow));
  x1 = static_cast<int>(std::min(grid.Width - 1.0, xHigh));
  y1 = static_cast<int>(std::min(grid.Height - 1.0, yHigh));
  return x0 <= x1 && y0 <= y1;
}

/// A triangle's projection onto the image as three edge functions of the screen point, each the
/// distance in pixels from its edge, positive inside: a pixel whose centre lies well outside one
/// cannot have its ray meet the triangle, and is passed over without the exact test.
struct ScreenTriangle
{
  double A[3], B[3], C[3];

  /// How far inside every edge the screen point (x, y) lies, in pixels (negative: outside one).
  double Clearance(double x, double y) const
  {
    double nearest = this->A[0] * x + this->B[0] * y + this->C[0];
    for (int i = 1; i < 3; ++i)
      nearest = std::min(nearest, this->A[i] * x + this->B[i] * y + this->C[i]);
    return nearest;
  }

  /// Whether the screen point (x, y) lies more than `margin` pixels outside an edge.
  bool Outside(double x, double y, double margin) const { return this->Clearance(x, y) < -margin; }
};

/// The triangle's ScreenTriangle, where it lies wholly beyond the near plane and is not seen
/// edge-on; false otherwise (every pixel of its bounds is then tested exactly).
inline bool ProjectTriangle(const PixelGrid& grid, const glm::dvec3 (&p)[3], ScreenTriangle& triangle)
{
  double x[3], y[3];
  for (int j = 0; j < 3; ++j)
  {
    const glm::dvec4 clip = grid.ModelToClip * glm::dvec4(p[j], 1.0);
    if (!(clip.w > 0.0) || clip.z + clip.w < 0.0)
      return false;
    x[j] = (clip.x / clip.w + 1.0) * 0.5 * grid.Width;
    y[j] = (clip.y / clip.w + 1.0) * 0.5 * grid.Height;
  }
  const double area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
  if (!(std::abs(area) > 1e-9))
    return false;
  const double side = area > 0.0 ? 1.0 : -1.0; // inside is left of each edge, counter-clockwise
  for (int i = 0; i < 3; ++i)
  {
    const int j = (i + 1) % 3;
    const double dx = x[j] - x[i], dy = y[j] - y[i], length = std::sqrt(dx * dx + dy * dy);
    triangle.A[i] = -dy * side / length;
    triangle.B[i] = dx * side / length;
    triangle.C[i] = -(triangle.A[i] * x[i] + triangle.B[i] * y[i]);
  }
  return true;
}

/// Whether the ray origin + s step (s >= 0) meets the triangle, edges included within rounding
/// (a ray along an edge meets both faces on it, so no gap is missed); `at` is s there.
inline bool RayMeetsTriangle(const glm::dvec3& origin, const glm::dvec3& step, const glm::dvec3 (&p)[3], double& at)
{
  const glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
  const glm::dvec3 h = glm::cross(step, e2);
  const double det = glm::dot(e1, h);
  if (det == 0.0)
    return false; // the ray lies in the triangle's plane: it crosses no volume there
  const double inverse = 1.0 / det;
  const glm::dvec3 s = origin - p[0];
  const double u = glm::dot(s, h) * inverse;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(step, q) * inverse;
  constexpr double slack = 1e-9;
  if (u < -slack || v < -slack || u + v > 1.0 + slack)
    return false;
  at = glm::dot(e2, q) * inverse;
  return at >= 0.0;
}

/// The boundary faces of a mesh: (tetrahedron, corner opposite the face) for each face with no
/// neighbour in `neighbours` (uvFaceAdjacencyOrder.h's MakeTetrahedronFaceAdjacency).
inline std::vector<std::pair<std::uint32_t, int>> BoundaryFaces(const std::vector<std::int32_t>& neighbours)
{
  std::vector<std::pair<std::uint32_t, int>> faces;
  for (std::size_t i = 0; i < neighbours.size(); ++i)
    if (neighbours[i] < 0)
      faces.emplace_back(static_cast<std::uint32_t>(i / 4), static_cast<int>(i % 4));
  return faces;
}

/// Whether the boundary of the mesh bounds a convex region: one connected closed surface, each of
/// whose edges joins two faces that bend inwards or lie in one plane (within `tolerance` of the
/// faces' size). Such a surface is convex; any other answer is "no", so that the rays run.
/// `corners`: 4 point ids per tetrahedron; `position(t, k)`: corner k of tetrahedron t.
template <typename Position>
bool BoundaryIsConvex(const std::vector<std::uint32_t>& corners, Position&& position,
  const std::vector<std::int32_t>& neighbours, double tolerance = 1e-9)
{
  const auto faces = BoundaryFaces(neighbours);
  if (faces.empty())
    return false;
  // Each boundary edge (ids ascending) and the faces on it: two for a closed surface.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> edges;
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    const std::uint32_t t = faces[f].first;
    const int k = faces[f].second;
    for (int j = 0; j < 3; ++j)
    {
      std::uint32_t a = corners[4 * t + (k + 1 + j) % 4], b = corners[4 * t + (k + 1 + (j + 1) % 3) % 4];
      edges[{ std::min(a, b), std::max(a, b) }].push_back(f);
    }
  }
  std::vector<std::size_t> root(faces.size());
  std::iota(root.begin(), root.end(), std::size_t(0));
  const auto find = [&root](std::size_t f) {
    while (root[f] != f)
      f = root[f] = root[root[f]];
    return f;
  };
  for (const auto& edge : edges)
  {
    if (edge.second.size() != 2)
      return false; // open or non-manifold
    const std::size_t f = edge.second[0], g = edge.second[1];
    // g's corner off the edge must lie on the inner side of f's plane.
    const std::uint32_t tf = faces[f].first, tg = faces[g].first;
    const int kf = faces[f].second, kg = faces[g].second;
    const glm::dvec3 a = position(tf, (kf + 1) % 4), b = position(tf, (kf + 2) % 4), c = position(tf, (kf + 3) % 4);
    glm::dvec3 normal = glm::cross(b - a, c - a);
    if (glm::dot(normal, position(tf, kf) - a) > 0.0)
      normal = -normal; // outward
    const double size = std::max({ glm::length(b - a), glm::length(c - a), glm::length(c - b) });
    for (int j = 1; j <= 3; ++j)
    {
      const std::uint32_t id = corners[4 * tg + (kg + j) % 4];
      if (id == edge.first.first || id == edge.first.second)
        continue;
      const double height = glm::dot(normal, position(tg, (kg + j) % 4) - a);
      if (height > tolerance * size * glm::length(normal))
        return false;
    }
    root[find(f)] = find(g);
  }
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (find(f) != find(0))
      return false;
  return true;
}

/// The boundary faces that can be crossed between two others: those off the mesh's convex hull.
/// A ray enters through a face in a supporting plane of the mesh only before anything else and
/// leaves through one only after everything, so such a face is never next to a gap and its rays
/// need not be cast. A face is on the hull when no point of the mesh lies beyond its plane by more
/// than `tolerance` of the mesh's size; the bounding box tells it at once for faces on its walls,
/// the boundary points (the hull's corners are among them) for the others.
template <typename Position, typename ParallelFor>
std::vector<std::pair<std::uint32_t, int>> FacesOffTheHull(const std::vector<std::pair<std::uint32_t, int>>& faces,
  Position&& position, ParallelFor&& parallelFor, double tolerance = 1e-9)
{
  std::vector<glm::dvec3> points;
  points.reserve(3 * faces.size());
  for (const auto& face : faces)
    for (int j = 1; j <= 3; ++j)
      points.push_back(position(face.first, (face.second + j) % 4));
  // Each point once (faces share them): sorted and made unique.
  const auto less = [](const glm::dvec3& a, const glm::dvec3& b) {
    return a.x != b.x ? a.x < b.x : (a.y != b.y ? a.y < b.y : a.z < b.z);
  };
  std::sort(points.begin(), points.end(), less);
  points.erase(std::unique(points.begin(), points.end()), points.end());
  glm::dvec3 low(1e300), high(-1e300);
  for (const glm::dvec3& p : points)
    low = glm::min(low, p), high = glm::max(high, p);
  const double slack = tolerance * glm::length(high - low);
  std::vector<std::uint8_t> off(faces.size(), 0);
  parallelFor(faces.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f)
    {
      const std::uint32_t t = faces[f].first;
      const int k = faces[f].second;
      const glm::dvec3 a = position(t, (k + 1) % 4), b = position(t, (k + 2) % 4), c = position(t, (k + 3) % 4);
      glm::dvec3 normal = glm::cross(b - a, c - a);
      if (glm::dot(normal, position(t, k) - a) > 0.0)
        normal = -normal;
      const double length = glm::length(normal);
      if (!(length > 0.0))
        continue; // no plane: no volume behind it either
      normal /= length;
      const double plane = glm::dot(normal, a) + slack;
      // The box's farthest corner along the normal bounds every point.
      const glm::dvec3 corner(normal.x > 0.0 ? high.x : low.x, normal.y > 0.0 ? high.y : low.y,
        normal.z > 0.0 ? high.z : low.z);
      if (glm::dot(normal, corner) <= plane)
        continue;
      for (const glm::dvec3& p : points)
        if (glm::dot(normal, p) > plane)
        {
          off[f] = 1;
          break;
        }
    }
  });
  std::vector<std::pair<std::uint32_t, int>> kept;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (off[f])
      kept.push_back(faces[f]);
  return kept;
}

/// The pixels of row y (centres at y + 0.5) within [first, last] whose centres may lie inside a
/// projected triangle by `margin`: [first, last] narrowed to them, one pixel wider for rounding
/// (each pixel is still tested; the span only spares the loop the bounds' corners).
inline void NarrowToRow(const ScreenTriangle& triangle, double y, double margin, int& first, int& last)
{
  double low = -1e300, high = 1e300; // pixel centres x + 0.5 allowed by every edge
  for (int i = 0; i < 3; ++i)
  {
    // A x + B y + C >= -margin
    const double rest = triangle.B[i] * y + triangle.C[i] + margin;
    if (triangle.A[i] > 0.0)
      low = std::max(low, -rest / triangle.A[i]);
    else if (triangle.A[i] < 0.0)
      high = std::min(high, -rest / triangle.A[i]);
    else if (rest < 0.0)
      low = 1e300;
  }
  // Clamped to [first, last] in double first: the bounds can lie far off the row, or be empty.
  const double from = std::max(static_cast<double>(first), std::floor(low - 0.5) - 1.0);
  const double to = std::min(static_cast<double>(last), std::ceil(high - 0.5) + 1.0);
  if (!(from <= to))
  {
    last = first - 1;
    return;
  }
  first = static_cast<int>(from);
  last = static_cast<int>(to);
}

/// A boundary face made ready for the pixel rays (GapConstraints): its corners, outward normal and
/// tetrahedron, the pixels its projection can cover and, where it has one, that projection.
struct GapFace
{
  glm::dvec3 P[3];
  glm::dvec3 Outward;
  std::uint32_t Tetrahedron = 0;
  int X0 = 0, X1 = -1, Y0 = 0, Y1 = -1; // empty unless ScreenBounds found pixels
  bool Projected = false;               // Screen holds the projection (else every pixel is tested)
  ScreenTriangle Screen;
  // The ray of pixel (x, y) meets the face's plane where Outward . (origin + at step - P[0]) = 0;
  // both dot products are affine in the pixel: at = (Base - OriginDot . (1, x, y)) / StepDot . (1, x, y).
  double Base = 0.0;
  glm::dvec3 OriginDot{ 0.0 }, StepDot{ 0.0 };
};

/// Where a pixel's ray crosses a boundary face (GapConstraints).
struct GapCrossing
{
  std::uint32_t Pixel; // in its band of rows
  std::uint32_t Tetrahedron;
  double At; // ray parameter
  bool Leaves;
};

/// The gap pairs along one pixel's ray, from its crossings (sorted here): the tetrahedron the ray
/// enters the mesh by again lies behind every one it left the mesh from just before.
inline void PairsAlongRay(std::vector<GapCrossing>::iterator begin, std::vector<GapCrossing>::iterator end,
  std::vector<std::uint32_t>& left, std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs)
{
  if (end - begin < 2 || (end - begin == 2 && !begin->Leaves && !(begin + 1)->Leaves))
    return;
  // Leaving before entering where they coincide (a gap of width 0).
  std::sort(begin, end, [](const GapCrossing& a, const GapCrossing& b) {
    return a.At != b.At ? a.At < b.At : (a.Leaves && !b.Leaves);
  });
  if (end - begin == 2 && !begin->Leaves)
    return; // in and out: no gap
  left.clear();
  for (auto c = begin; c != end; ++c)
  {
    if (c->Leaves)
    {
      if (c != begin && !(c - 1)->Leaves)
        left.clear(); // a new exit after an entry: the earlier exits are not next to what follows
      left.push_back(c->Tetrahedron);
    }
    else
    {
      for (std::uint32_t front : left)
        if (front != c->Tetrahedron && (pairs.empty() || pairs.back() != std::make_pair(front, c->Tetrahedron)))
          pairs.emplace_back(front, c->Tetrahedron);
    }
  }
}

/// Face k of tetrahedron t (corners from `position(t, corner)`) made ready for GapConstraints: its
/// corners, outward normal, screen bounds and projection, and its plane's terms along `rays`.
template <typename Position>
GapFace PreparedGapFace(std::uint32_t t, int k, Position&& position, const PixelGrid& grid, const PixelRays& rays)
{
  GapFace face;
  face.Tetrahedron = t;
  for (int j = 0; j < 3; ++j)
    face.P[j] = position(t, (k + 1 + j) % 4);
  face.Outward = glm::cross(face.P[1] - face.P[0], face.P[2] - face.P[0]);
  if (glm::dot(face.Outward, position(t, k) - face.P[0]) > 0.0)
    face.Outward = -face.Outward;
  if (!ScreenBounds(grid, face.P, face.X0, face.X1, face.Y0, face.Y1))
    face.X0 = 0, face.X1 = -1, face.Y0 = 0, face.Y1 = -1;
  else
    face.Projected = ProjectTriangle(grid, face.P, face.Screen);
  face.Base = glm::dot(face.Outward, face.P[0]);
  face.OriginDot = glm::dvec3(glm::dot(face.Outward, rays.Origin0), glm::dot(face.Outward, rays.OriginX),
    glm::dot(face.Outward, rays.OriginY));
  face.StepDot = glm::dvec3(
    glm::dot(face.Outward, rays.Step0), glm::dot(face.Outward, rays.StepX), glm::dot(face.Outward, rays.StepY));
  return face;
}

/// Bands of image rows, and the faces whose screen bounds reach each (a counting sort): band b's
/// faces are Faces[First[b], First[b + 1]).
struct FacesByBand
{
  FacesByBand(const std::vector<GapFace>& faces, int height)
  {
    constexpr int TargetBands = 64;
    this->Rows = std::max(1, (height + TargetBands - 1) / TargetBands);
    this->Count = (height + this->Rows - 1) / this->Rows;
    this->First.assign(this->Count + 1, 0);
    for (const GapFace& face : faces)
      for (int b = face.Y0 / this->Rows; face.Y0 <= face.Y1 && b <= face.Y1 / this->Rows; ++b)
        ++this->First[b + 1];
    for (int b = 0; b < this->Count; ++b)
      this->First[b + 1] += this->First[b];
    this->Faces.resize(this->First.back());
    std::vector<std::uint32_t> next(this->First.begin(), this->First.end() - 1);
    for (std::size_t f = 0; f < faces.size(); ++f)
      for (int b = faces[f].Y0 / this->Rows; faces[f].Y0 <= faces[f].Y1 && b <= faces[f].Y1 / this->Rows; ++b)
        this->Faces[next[b]++] = static_cast<std::uint32_t>(f);
  }
  int Rows = 1, Count = 0;
  std::vector<std::uint32_t> First, Faces;
};

/// The crossings of `face` with the rays of rows [rowBegin, rowEnd), pixels numbered from the
/// band's first row, appended to `crossings`.
inline void FaceCrossingsInRows(const GapFace& face, const PixelGrid& grid, const PixelRays& rays, int rowBegin,
  int rowEnd, std::vector<GapCrossing>& crossings)
{
  // Pixels this far outside a face's projection are passed over: far beyond the rounding of the
  // projection and of the exact test's edge slack.
  constexpr double PrefilterMargin = 0.01;
  for (int y = std::max(face.Y0, rowBegin); y <= std::min(face.Y1, rowEnd - 1); ++y)
  {
    int x0 = face.X0, x1 = face.X1;
    if (face.Projected)
      NarrowToRow(face.Screen, y + 0.5, PrefilterMargin, x0, x1);
    for (int x = x0; x <= x1; ++x)
    {
      const double clearance = face.Projected ? face.Screen.Clearance(x + 0.5, y + 0.5) : 0.0;
      if (clearance < -PrefilterMargin)
        continue;
      const std::uint32_t pixel = static_cast<std::uint32_t>((y - rowBegin) * grid.Width + x);
      if (clearance > PrefilterMargin)
      {
        // Well inside the projection: the ray meets the face wherever the exact test would say
        // so, where it meets the face's plane.
        const glm::dvec3 pixelTerms(1.0, double(x), double(y));
        const double along = glm::dot(face.StepDot, pixelTerms);
        const double at = (face.Base - glm::dot(face.OriginDot, pixelTerms)) / along;
        if (at >= 0.0)
          crossings.push_back({ pixel, face.Tetrahedron, at, along > 0.0 });
        continue;
      }
      glm::dvec3 origin, step;
      rays.At(x, y, origin, step);
      double at;
      if (RayMeetsTriangle(origin, step, face.P, at))
        crossings.push_back({ pixel, face.Tetrahedron, at, glm::dot(face.Outward, step) > 0.0 });
    }
  }
}

/// The pairs of a band of `pixels` pixels from its crossings: grouped by pixel (a counting sort),
/// then each pixel's few crossings taken along its ray. Sorted, each once. `first`, `grouped` and
/// `left` are scratch.
inline void PairsOfBand(const std::vector<GapCrossing>& crossings, std::size_t pixels, std::vector<std::uint32_t>& first,
  std::vector<GapCrossing>& grouped, std::vector<std::uint32_t>& left,
  std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs)
{
  first.assign(pixels + 1, 0);
  for (const GapCrossing& c : crossings)
    ++first[c.Pixel + 1];
  for (std::size_t i = 1; i < first.size(); ++i)
    first[i] += first[i - 1];
  grouped.resize(crossings.size());
  for (const GapCrossing& c : crossings)
    grouped[first[c.Pixel]++] = c; // first[p] ends at pixel p's end, its start is first[p - 1]
  for (std::size_t pixel = 0; pixel + 1 < first.size(); ++pixel)
    PairsAlongRay(grouped.begin() + (pixel == 0 ? 0 : first[pixel - 1]), grouped.begin() + first[pixel], left, pairs);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

/// The order constraints a non-convex mesh's gaps add for the rays of `grid`: pairs (front, behind),
/// each once, sorted, meaning a ray through the image leaves the mesh from `front` and enters it
/// again next at `behind`, which must then be drawn first. `faces` from BoundaryFaces, or only those
/// FacesOffTheHull (the same pairs, sooner); `parallelFor(count, function(begin, end))` runs over
/// faces and then over bands of rows, in parallel if it likes (the result does not depend on it).
/// The image is taken a band of rows at a time, so the crossings held at once are those of a band,
/// not of the whole image.
template <typename Position, typename ParallelFor>
std::vector<std::pair<std::uint32_t, std::uint32_t>> GapConstraints(
  const std::vector<std::pair<std::uint32_t, int>>& faces, Position&& position, const PixelGrid& grid, ParallelFor&& parallelFor)
{
  using Pair = std::pair<std::uint32_t, std::uint32_t>;
  if (grid.Width <= 0 || grid.Height <= 0)
    return {};
  const PixelRays rays(grid);
  std::vector<GapFace> ready(faces.size());
  parallelFor(faces.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f)
      ready[f] = PreparedGapFace(faces[f].first, faces[f].second, position, grid, rays);
  });
  const FacesByBand bands(ready, grid.Height);
  std::vector<std::vector<Pair>> bandPairs(bands.Count);
  parallelFor(static_cast<std::size_t>(bands.Count), [&](std::size_t begin, std::size_t end) {
    std::vector<GapCrossing> crossings, grouped;
    std::vector<std::uint32_t> first, left;
    for (std::size_t b = begin; b < end; ++b)
    {
      const int rowBegin = static_cast<int>(b) * bands.Rows, rowEnd = std::min(grid.Height, rowBegin + bands.Rows);
      crossings.clear();
      for (std::uint32_t i = bands.First[b]; i < bands.First[b + 1]; ++i)
        FaceCrossingsInRows(ready[bands.Faces[i]], grid, rays, rowBegin, rowEnd, crossings);
      PairsOfBand(crossings, std::size_t(rowEnd - rowBegin) * grid.Width, first, grouped, left, bandPairs[b]);
    }
  });
  std::vector<Pair> pairs;
  for (const auto& list : bandPairs)
    pairs.insert(pairs.end(), list.begin(), list.end());
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

} // namespace uv

#endif
