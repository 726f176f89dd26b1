// Splitting linear 3D cells into positively oriented tetrahedra, free of VTK so it can be tested alone.
//
// Conforming rule (unstructured meshes): every quadrilateral face is cut along the diagonal through
// its vertex of smallest global id, so two cells sharing a face always cut it the same way. A cell is
// then split as the cone from its own smallest-id vertex m over the faces that do not contain m. The
// faces that do contain m are cut through m by the same rule, so the cone's tets meet them exactly:
// no Steiner points, hexahedron -> 6, wedge -> 3, pyramid -> 2 tets.
//
// Local vertex numbering is VTK's (VTK_HEXAHEDRON, VTK_WEDGE, VTK_PYRAMID, VTK_TETRA). A tet (a,b,c,d)
// is positive when (b-a)x(c-a) points towards d, VTK's convention. The face lists below are oriented
// outwards for a valid cell, so reversing a face triangle and appending the inner apex gives a
// positive tet without looking at coordinates.
#ifndef uvLinearCellSplit_h
#define uvLinearCellSplit_h

#include <array>
#include <cstdint>
#include <utility>

namespace uv
{

struct LocalFace
{
  int Size; // 3 or 4
  std::array<int, 4> Vertices;
};

// Outward-oriented faces of VTK's linear cells.
constexpr std::array<LocalFace, 6> HexahedronFaces = { {
  { 4, { 0, 3, 2, 1 } },
  { 4, { 4, 5, 6, 7 } },
  { 4, { 0, 1, 5, 4 } },
  { 4, { 1, 2, 6, 5 } },
  { 4, { 2, 3, 7, 6 } },
  { 4, { 3, 0, 4, 7 } },
} };
constexpr std::array<LocalFace, 5> WedgeFaces = { {
  { 3, { 0, 1, 2, -1 } },
  { 3, { 3, 5, 4, -1 } },
  { 4, { 1, 0, 3, 4 } },
  { 4, { 2, 1, 4, 5 } },
  { 4, { 0, 2, 5, 3 } },
} };
constexpr std::array<LocalFace, 5> PyramidFaces = { {
  { 4, { 0, 3, 2, 1 } },
  { 3, { 0, 1, 4, -1 } },
  { 3, { 1, 2, 4, -1 } },
  { 3, { 2, 3, 4, -1 } },
  { 3, { 3, 0, 4, -1 } },
} };

// VTK_VOXEL numbers its corners x-fastest; this maps hexahedron local index -> voxel local index.
constexpr std::array<int, 8> VoxelToHexahedronOrder = { 0, 1, 3, 2, 4, 5, 7, 6 };

constexpr int MaxTetsPerCell = 6;

/// Splits a cell described by outward faces into tets (local indices), conforming by global ids.
/// Returns the number of tets written to `tets` (at most MaxTetsPerCell).
template <typename IdType, std::size_t NumFaces>
int SplitByMinimumVertexCone(const std::array<LocalFace, NumFaces>& faces, int numVertices,
  const IdType* globalIds, int tets[][4])
{
  int apex = 0;
  for (int v = 1; v < numVertices; ++v)
  {
    if (globalIds[v] < globalIds[apex])
    {
      apex = v;
    }
  }
  int count = 0;
  for (const LocalFace& face : faces)
  {
    bool containsApex = false;
    for (int i = 0; i < face.Size; ++i)
    {
      containsApex = containsApex || face.Vertices[i] == apex;
    }
    if (containsApex)
    {
      continue;
    }
    const auto& f = face.Vertices;
    if (face.Size == 3)
    {
      tets[count][0] = f[0];
      tets[count][1] = f[2];
      tets[count][2] = f[1];
      tets[count][3] = apex;
      ++count;
      continue;
    }
    // Cut the quad along the diagonal through its smallest global id.
    int lowest = 0;
    for (int i = 1; i < 4; ++i)
    {
      if (globalIds[f[i]] < globalIds[f[lowest]])
      {
        lowest = i;
      }
    }
    const int a = f[lowest], b = f[(lowest + 1) % 4], c = f[(lowest + 2) % 4], d = f[(lowest + 3) % 4];
    // Outward triangles (a,b,c) and (a,c,d), each reversed towards the apex.
    tets[count][0] = a;
    tets[count][1] = c;
    tets[count][2] = b;
    tets[count][3] = apex;
    ++count;
    tets[count][0] = a;
    tets[count][1] = d;
    tets[count][2] = c;
    tets[count][3] = apex;
    ++count;
  }
  return count;
}

template <typename IdType>
int SplitHexahedron(const IdType globalIds[8], int tets[][4])
{
  return SplitByMinimumVertexCone(HexahedronFaces, 8, globalIds, tets);
}

template <typename IdType>
int SplitWedge(const IdType globalIds[6], int tets[][4])
{
  return SplitByMinimumVertexCone(WedgeFaces, 6, globalIds, tets);
}

template <typename IdType>
int SplitPyramid(const IdType globalIds[5], int tets[][4])
{
  return SplitByMinimumVertexCone(PyramidFaces, 5, globalIds, tets);
}

/// Six times the signed volume of tet (a,b,c,d): positive for VTK's orientation.
template <typename Vec3>
double SixSignedVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  return (uy * vz - uz * vy) * wx + (uz * vx - ux * vz) * wy + (ux * vy - uy * vx) * wz;
}

/// The 5-tet split of a structured cell. Corners whose global (i+j+k) is even form the central tet,
/// each odd corner a tet with its three edge neighbours; the parity is global, so neighbouring cells
/// cut their shared face along the same (even-even) diagonal. `originParityOdd` is (i+j+k) % 2 of the
/// cell's corner 0. Local indices are in hexahedron order; the tables are oriented once on the unit
/// cube, so the order written below does not matter.
inline const int (*FiveTetSplit(bool originParityOdd))[4]
{
  // Hexahedron corner 0..7 at (x,y,z) = (0,0,0) (1,0,0) (1,1,0) (0,1,0) (0,0,1) (1,0,1) (1,1,1) (0,1,1).
  // Corners with even local parity: 0, 2, 5, 7; odd: 1, 3, 4, 6.
  struct Tables
  {
    int Even[5][4] = { { 0, 2, 5, 7 }, { 1, 0, 2, 5 }, { 3, 0, 2, 7 }, { 4, 0, 5, 7 }, { 6, 2, 5, 7 } };
    int Odd[5][4] = { { 1, 3, 4, 6 }, { 0, 1, 3, 4 }, { 2, 1, 3, 6 }, { 5, 1, 4, 6 }, { 7, 3, 4, 6 } };
    Tables()
    {
      const double cube[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
        { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
      for (auto* table : { &this->Even, &this->Odd })
      {
        for (auto& tet : *table)
        {
          if (SixSignedVolume(cube[tet[0]], cube[tet[1]], cube[tet[2]], cube[tet[3]]) < 0.0)
          {
            std::swap(tet[1], tet[2]);
          }
        }
      }
    }
  };
  static const Tables tables;
  return originParityOdd ? tables.Odd : tables.Even;
}

} // namespace uv

#endif
