// The four families of 3D cells by parametric domain, shared by the higher-order subdivision
// (uvIsoparametricLattice.h) and the reference's curved cells (uvCurvedCell.h).
#ifndef uvCellFamily_h
#define uvCellFamily_h

namespace uv
{
/// VTK's parametric domains: the unit simplex, the unit cube, the triangle times [0, 1], and the
/// pyramid.
enum class CellFamily
{
  Tetrahedron,
  Hexahedron,
  Wedge,
  Pyramid
};
} // namespace uv

#endif
