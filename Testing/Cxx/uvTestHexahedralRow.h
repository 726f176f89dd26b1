// A row of unit cubes as the VTK-free hexahedral mesh tests build it (uvHexahedralMesh.h layout:
// 8 point ids per cell, 4 floats per point with the scalar last), and a serial parallelFor.
#ifndef uvTestHexahedralRow_h
#define uvTestHexahedralRow_h

#include <cstdint>
#include <functional>
#include <vector>

namespace uvtest
{
inline void Serial(std::size_t count, const std::function<void(std::size_t, std::size_t)>& function)
{
  function(0, count);
}

/// nx x 1 x 1 unit cubes along x: points (i, j, k) numbered i + (nx + 1) (j + 2 k), each point's
/// scalar its x.
struct HexahedralRow
{
  std::vector<std::uint32_t> CellPoints;
  std::vector<float> PointData;

  explicit HexahedralRow(int nx)
  {
    auto id = [nx](int i, int j, int k) { return static_cast<std::uint32_t>(i + (nx + 1) * (j + 2 * k)); };
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i <= nx; ++i)
          this->PointData.insert(this->PointData.end(), { float(i), float(j), float(k), float(i) });
    for (int i = 0; i < nx; ++i)
      this->CellPoints.insert(this->CellPoints.end(), { id(i, 0, 0), id(i + 1, 0, 0), id(i + 1, 1, 0),
        id(i, 1, 0), id(i, 0, 1), id(i + 1, 0, 1), id(i + 1, 1, 1), id(i, 1, 1) });
  }
};
} // namespace uvtest

#endif
