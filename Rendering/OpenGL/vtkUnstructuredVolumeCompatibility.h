// The one place where this module meets the differences between the VTK versions it builds against
// (9.1 to 9.6, and the VTKs bundled with ParaView 5.11 to 6.1). Everything else includes this header
// instead of choosing by version itself.
#ifndef vtkUnstructuredVolumeCompatibility_h
#define vtkUnstructuredVolumeCompatibility_h

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVersionMacros.h"

// VTK 9.4 loads OpenGL with glad instead of GLEW (the CMake side links VTK::glad or VTK::opengl).
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 4, 0)
#include "vtk_glad.h"
#define UV_VTK_POLYHEDRON_FACES_AS_CELL_ARRAYS 1
#else
#include "vtk_glew.h"
#define UV_VTK_POLYHEDRON_FACES_AS_CELL_ARRAYS 0
#endif

// VTK 9.6 moves the cell-type queries to vtkCellTypeUtilities and hands the cell types out as a
// vtkDataArray (a constant array for a grid of one type).
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 6, 0)
#include "vtkCellTypeUtilities.h"
#define UV_VTK_CELL_TYPE_UTILITIES 1
#else
#include "vtkCellTypes.h"
#define UV_VTK_CELL_TYPE_UTILITIES 0
#endif

namespace uvcompat
{

/// VTK's class name for a cell type ("vtkHexahedron").
inline const char* CellTypeName(int type)
{
#if UV_VTK_CELL_TYPE_UTILITIES
  return vtkCellTypeUtilities::GetClassNameFromTypeId(type);
#else
  return vtkCellTypes::GetClassNameFromTypeId(type);
#endif
}

/// Whether a cell type is linear (its faces flat, its field of degree one along each edge).
inline bool IsLinearCellType(int type)
{
#if UV_VTK_CELL_TYPE_UTILITIES
  return vtkCellTypeUtilities::IsLinear(static_cast<unsigned char>(type)) != 0;
#else
  return vtkCellTypes::IsLinear(static_cast<unsigned char>(type)) != 0;
#endif
}

/// The grid's array of cell types, one per cell.
inline vtkDataArray* CellTypesArray(vtkUnstructuredGrid* grid)
{
#if UV_VTK_CELL_TYPE_UTILITIES
  return grid->GetCellTypes();
#else
  return grid->GetCellTypesArray();
#endif
}

/// A polyhedron's face stream (number of faces, then each face's point count and point ids) into
/// `stream`; empty where the cell has none. VTK 9.4 keeps polyhedron faces in vtkCellArrays and
/// deprecates the legacy face arrays, so the stream is assembled from those there.
inline void GetPolyhedronFaceStream(vtkUnstructuredGrid* grid, vtkIdType cell, vtkIdList* stream)
{
  stream->Reset();
#if UV_VTK_POLYHEDRON_FACES_AS_CELL_ARRAYS
  vtkCellArray* faces = grid->GetPolyhedronFaces();
  vtkCellArray* locations = grid->GetPolyhedronFaceLocations();
  if (!faces || !locations || cell >= locations->GetNumberOfCells())
  {
    return;
  }
  vtkIdType numFaces = 0;
  const vtkIdType* faceIds = nullptr;
  vtkNew<vtkIdList> scratch;
  locations->GetCellAtId(cell, numFaces, faceIds, scratch);
  if (numFaces == 0)
  {
    return;
  }
  stream->InsertNextId(numFaces);
  vtkNew<vtkIdList> facePoints;
  for (vtkIdType f = 0; f < numFaces; ++f)
  {
    faces->GetCellAtId(faceIds[f], facePoints);
    stream->InsertNextId(facePoints->GetNumberOfIds());
    for (vtkIdType p = 0; p < facePoints->GetNumberOfIds(); ++p)
    {
      stream->InsertNextId(facePoints->GetId(p));
    }
  }
#else
  // Read with bounds checks: a malformed stream is left short for the caller to reject, not read past.
  vtkIdTypeArray* faces = grid->GetFaces();
  vtkIdTypeArray* locations = grid->GetFaceLocations();
  if (!faces || !locations || cell >= locations->GetNumberOfValues())
  {
    return;
  }
  const vtkIdType end = faces->GetNumberOfValues();
  vtkIdType at = locations->GetValue(cell);
  if (at < 0 || at >= end)
  {
    return;
  }
  const vtkIdType numFaces = faces->GetValue(at++);
  stream->InsertNextId(numFaces);
  for (vtkIdType f = 0; f < numFaces && at < end; ++f)
  {
    const vtkIdType count = faces->GetValue(at++);
    stream->InsertNextId(count);
    for (vtkIdType p = 0; p < count && at < end; ++p)
    {
      stream->InsertNextId(faces->GetValue(at++));
    }
  }
#endif
}

} // namespace uvcompat

#endif
