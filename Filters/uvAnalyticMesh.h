// Analytic scalar fields and grid distortions for generated test meshes, free of VTK.
// Fields are defined in world space on [-1,1]^3, so a field sampled on a distorted grid is still the
// same function of position (a linear field stays exactly linear).
#ifndef uvAnalyticMesh_h
#define uvAnalyticMesh_h

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>

namespace uv
{

enum class AnalyticField
{
  Linear,
  MarschnerLobb,
  Steiner
};

inline double EvaluateLinear(const glm::dvec3& p)
{
  return 0.5 + 0.25 * p.x + 0.15 * p.y + 0.1 * p.z;
}

/// Marschner and Lobb's test signal (1994), alpha = 0.25, f_M = 6; range [0, 1].
inline double EvaluateMarschnerLobb(const glm::dvec3& p)
{
  const double pi = 3.14159265358979323846;
  const double alpha = 0.25, frequency = 6.0;
  const double r = std::sqrt(p.x * p.x + p.y * p.y);
  const double rho = std::cos(2.0 * pi * frequency * std::cos(pi * r / 2.0));
  return (1.0 - std::sin(pi * p.z / 2.0) + alpha * (1.0 + rho)) / (2.0 * (1.0 + alpha));
}

/// The Steiner-surface field of Miranda and Celes' hexahedral paper: x^2y^2 + y^2z^2 + z^2x^2 + xyz.
inline double EvaluateSteiner(const glm::dvec3& p)
{
  return p.x * p.x * p.y * p.y + p.y * p.y * p.z * p.z + p.z * p.z * p.x * p.x + p.x * p.y * p.z;
}

inline double EvaluateField(AnalyticField field, const glm::dvec3& p)
{
  switch (field)
  {
    case AnalyticField::MarschnerLobb:
      return EvaluateMarschnerLobb(p);
    case AnalyticField::Steiner:
      return EvaluateSteiner(p);
    default:
      return EvaluateLinear(p);
  }
}

/// Rotation about z growing linearly from 0 at z = -1 to `angle` radians at z = 1.
inline glm::dvec3 Twist(const glm::dvec3& p, double angle)
{
  const double theta = angle * 0.5 * (p.z + 1.0);
  const double c = std::cos(theta), s = std::sin(theta);
  return { c * p.x - s * p.y, s * p.x + c * p.y, p.z };
}

/// 45 degrees about z: every cube becomes one whose world-space trilinear fit is singular.
inline glm::dvec3 Rotate45(const glm::dvec3& p)
{
  const double h = std::sqrt(0.5);
  return { h * (p.x - p.y), h * (p.x + p.y), p.z };
}

/// Deterministic pseudo-random value in [-1, 1] for (index, seed): the same on every platform.
inline double HashToSymmetricUnit(std::uint64_t index, std::uint64_t seed)
{
  std::uint64_t z = index * 0x9E3779B97F4A7C15ull + seed * 0xBF58476D1CE4E5B9ull + 0x94D049BB133111EBull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

/// Moves an interior grid point by up to `fraction` of the spacing per axis. Boundary points stay,
/// so the domain keeps its faces. With fraction <= 0.15 every edge-vector Jacobian of a cell stays
/// diagonally dominant, so the cells stay valid.
inline glm::dvec3 Jitter(const glm::dvec3& p, const glm::dvec3& spacing, std::uint64_t pointIndex,
  std::uint64_t seed, double fraction, const bool onBoundary[3])
{
  glm::dvec3 q = p;
  for (int d = 0; d < 3; ++d)
  {
    if (!onBoundary[d])
    {
      q[d] += fraction * spacing[d] * HashToSymmetricUnit(3 * pointIndex + d, seed);
    }
  }
  return q;
}

} // namespace uv

#endif
