// Splitting linear 3D cells into positively oriented tetrahedra, free of VTK so it can be tested alone.
//
// Conforming rule (unstructured meshes): every polygonal face (quadrilateral, pentagon, hexagon) is
// fanned from its vertex of smallest global id, so two cells sharing a face always cut it the same
// way; for a quadrilateral the fan is the cut along the diagonal through that vertex. A cell is then
// split as the cone from its own smallest-id vertex m over the faces that do not contain m. The faces
// that do contain m have m as their smallest vertex, so they are fanned from m and the cone's tets meet
// them exactly: no Steiner points, hexahedron -> 6, wedge -> 3, pyramid -> 2, pentagonal prism -> 9,
// hexagonal prism -> 12 tets. The cone is a valid split of any convex cell.
//
// Local vertex numbering is VTK's (VTK_HEXAHEDRON, VTK_WEDGE, VTK_PYRAMID, VTK_PENTAGONAL_PRISM,
// VTK_HEXAGONAL_PRISM, VTK_TETRA). A tet (a,b,c,d) is positive when (b-a)x(c-a) points towards d, VTK's
// convention. The face lists below are oriented outwards for a valid cell, so reversing a face
// triangle and appending the inner apex gives a positive tet without looking at coordinates.
#ifndef uvLinearCellSplit_h
#define uvLinearCellSplit_h

#include <array>
#include <cstdint>
#include <utility>

namespace uv
{

constexpr int MaxLocalFaceSize = 6;

struct LocalFace
{
  int Size; // 3 to MaxLocalFaceSize
  std::array<int, MaxLocalFaceSize> Vertices;
};

/// Fans a polygon of `size` vertices from the one whose key is smallest, calling
/// emit(i, j, k) with positions in the polygon for each triangle, in the polygon's own orientation.
/// Two cells sharing a face (same keys, either orientation) get the same triangles.
template <typename Key, typename Emit>
void FanFromLowest(int size, Key&& key, Emit&& emit)
{
  int lowest = 0;
  for (int i = 1; i < size; ++i)
  {
    if (key(i) < key(lowest))
    {
      lowest = i;
    }
  }
  for (int i = 1; i + 1 < size; ++i)
  {
    emit(lowest, (lowest + i) % size, (lowest + i + 1) % size);
  }
}

// Outward-oriented faces of VTK's linear cells.
inline constexpr std::array<LocalFace, 6> HexahedronFaces = { {
  { 4, { 0, 3, 2, 1 } },
  { 4, { 4, 5, 6, 7 } },
  { 4, { 0, 1, 5, 4 } },
  { 4, { 1, 2, 6, 5 } },
  { 4, { 2, 3, 7, 6 } },
  { 4, { 3, 0, 4, 7 } },
} };
inline constexpr std::array<LocalFace, 5> WedgeFaces = { {
  { 3, { 0, 1, 2, -1 } },
  { 3, { 3, 5, 4, -1 } },
  { 4, { 1, 0, 3, 4 } },
  { 4, { 2, 1, 4, 5 } },
  { 4, { 0, 2, 5, 3 } },
} };
inline constexpr std::array<LocalFace, 5> PyramidFaces = { {
  { 4, { 0, 3, 2, 1 } },
  { 3, { 0, 1, 4, -1 } },
  { 3, { 1, 2, 4, -1 } },
  { 3, { 2, 3, 4, -1 } },
  { 3, { 3, 0, 4, -1 } },
} };

/// Outward faces of an n-gonal prism numbered as VTK's prisms: the bottom polygon 0..n-1 turns
/// anticlockwise seen from the top polygon n..2n-1, vertex n+i above vertex i (as the hexahedron).
template <int N>
inline constexpr std::array<LocalFace, N + 2> PrismFaces()
{
  std::array<LocalFace, N + 2> faces{};
  faces[0].Size = N;
  faces[1].Size = N;
  for (int i = 0; i < N; ++i)
  {
    faces[0].Vertices[i] = (N - i) % N; // 0, n-1, ..., 1: reversed, so it faces down
    faces[1].Vertices[i] = N + i;
    LocalFace& side = faces[2 + i];
    side.Size = 4;
    side.Vertices = { i, (i + 1) % N, N + (i + 1) % N, N + i, -1, -1 };
  }
  return faces;
}
inline constexpr std::array<LocalFace, 7> PentagonalPrismFaces = PrismFaces<5>();
inline constexpr std::array<LocalFace, 8> HexagonalPrismFaces = PrismFaces<6>();

// VTK_VOXEL numbers its corners x-fastest; this maps hexahedron local index -> voxel local index.
inline constexpr std::array<int, 8> VoxelToHexahedronOrder = { 0, 1, 3, 2, 4, 5, 7, 6 };

constexpr int MaxTetsPerCell = 12; // the hexagonal prism

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
    // Outward fan triangles, each reversed towards the apex.
    const auto& f = face.Vertices;
    FanFromLowest(
      face.Size, [&](int i) { return globalIds[f[i]]; },
      [&](int i, int j, int k) {
        tets[count][0] = f[i];
        tets[count][1] = f[k];
        tets[count][2] = f[j];
        tets[count][3] = apex;
        ++count;
      });
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

template <typename IdType>
int SplitPentagonalPrism(const IdType globalIds[10], int tets[][4])
{
  return SplitByMinimumVertexCone(PentagonalPrismFaces, 10, globalIds, tets);
}

template <typename IdType>
int SplitHexagonalPrism(const IdType globalIds[12], int tets[][4])
{
  return SplitByMinimumVertexCone(HexagonalPrismFaces, 12, globalIds, tets);
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
