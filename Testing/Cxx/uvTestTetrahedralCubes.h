// Meshes of tetrahedra for the VTK-free tests: n^3 cubes split conformingly, warped, some left out;
// and the exact crossing of a ray with one tetrahedron (double precision).
#ifndef uvTestTetrahedralCubes_h
#define uvTestTetrahedralCubes_h

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace uvtest
{
struct Mesh
{
  std::vector<glm::dvec3> Points;
  std::vector<std::uint32_t> Corners;
  std::size_t Count() const { return this->Corners.size() / 4; }
  glm::dvec3 At(std::size_t t, int k) const { return this->Points[this->Corners[4 * t + k]]; }
};

/// n^3 cubes, each split into the 6 tetrahedra around its main diagonal (a conforming mesh), with
/// the points moved by `warp`.
template <typename Warp, typename Keep>
Mesh Cubes(int n, Warp warp, Keep keep)
{
  Mesh mesh;
  auto id = [n](int i, int j, int k) { return static_cast<std::uint32_t>((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        mesh.Points.push_back(warp(glm::dvec3(i, j, k) / double(n)));
  const int paths[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& path : paths)
        {
          if (!keep(i, j, k))
            break;
          int c[3] = { i, j, k };
          mesh.Corners.push_back(id(c[0], c[1], c[2]));
          for (int axis : path)
          {
            ++c[axis];
            mesh.Corners.push_back(id(c[0], c[1], c[2]));
          }
        }
  return mesh;
}

template <typename Warp>
Mesh Cubes(int n, Warp warp)
{
  return Cubes(n, warp, [](int, int, int) { return true; });
}

/// The entry and exit parameters of the ray through tetrahedron t, or false where it misses.
inline bool Crossing(const Mesh& mesh, std::size_t t, const glm::dvec3& origin, const glm::dvec3& direction, double& enter,
  double& leave)
{
  enter = 0.0;
  leave = 1e300;
  for (int k = 0; k < 4; ++k)
  {
    const glm::dvec3 a = mesh.At(t, (k + 1) % 4), b = mesh.At(t, (k + 2) % 4), c = mesh.At(t, (k + 3) % 4);
    glm::dvec3 n = glm::cross(b - a, c - a);
    if (glm::dot(n, mesh.At(t, k) - a) > 0.0)
      n = -n; // outward
    const double along = glm::dot(n, direction), at = glm::dot(n, origin - a);
    if (along < 0.0)
      enter = std::max(enter, -at / along);
    else if (along > 0.0)
      leave = std::min(leave, -at / along);
    else if (at > 0.0)
      return false;
  }
  return enter < leave;
}

} // namespace uvtest

#endif
