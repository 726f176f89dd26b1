// Checks shared by the VTK-level tests: conformity of tet meshes, volumes, error counting, data files.
#ifndef uvTestMeshChecks_h
#define uvTestMeshChecks_h

#include "vtkCallbackCommand.h"
#include "vtkCell.h"
#include "vtkCellType.h"
#include "vtkCommand.h"
#include "vtkDataSet.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkObject.h"
#include "vtkSmartPointer.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkIntArray.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <array>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace uvtest
{

/// Path of a file under ../shared/data, or "" when it is not there.
inline std::string SharedData(const std::string& relative)
{
  const std::string path = std::string(UV_SHARED_DATA_DIR) + "/" + relative;
  std::ifstream probe(path);
  return probe.good() ? path : std::string();
}

struct FaceCensus
{
  long long Interior = 0;   // faces shared by exactly two cells
  long long Boundary = 0;   // faces of one cell
  long long Overshared = 0; // faces of three or more cells: overlap or a T-junction's mismatch
};

/// How many 3D cells share each face, faces keyed by their sorted point ids.
inline std::map<std::vector<vtkIdType>, int> FaceMultiplicity(vtkDataSet* mesh)
{
  std::map<std::vector<vtkIdType>, int> faces;
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCell(c, cell);
    if (cell->GetCellDimension() != 3)
    {
      continue;
    }
    for (int f = 0; f < cell->GetNumberOfFaces(); ++f)
    {
      vtkIdList* ids = cell->GetFace(f)->GetPointIds();
      std::vector<vtkIdType> key(ids->GetPointer(0), ids->GetPointer(0) + ids->GetNumberOfIds());
      std::sort(key.begin(), key.end());
      ++faces[key];
    }
  }
  return faces;
}

inline FaceCensus CountFaces(vtkDataSet* mesh)
{
  FaceCensus census;
  for (const auto& face : FaceMultiplicity(mesh))
  {
    census.Interior += face.second == 2 ? 1 : 0;
    census.Boundary += face.second == 1 ? 1 : 0;
    census.Overshared += face.second > 2 ? 1 : 0;
  }
  return census;
}

/// Boundary triangles a conforming tet split of `mesh` must have: n - 2 per boundary polygon of n points.
inline long long ExpectedBoundaryTriangles(vtkDataSet* mesh)
{
  long long triangles = 0;
  for (const auto& face : FaceMultiplicity(mesh))
  {
    if (face.second == 1)
    {
      triangles += static_cast<long long>(face.first.size()) - 2; // a fan of each polygon
    }
  }
  return triangles;
}

/// Signed volumes of the tets of a tetrahedral grid.
inline std::vector<double> TetVolumes(vtkUnstructuredGrid* tets)
{
  std::vector<double> volumes;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < tets->GetNumberOfCells(); ++c)
  {
    tets->GetCellPoints(c, ids);
    double p[4][3];
    for (int v = 0; v < 4; ++v)
    {
      tets->GetPoint(ids->GetId(v), p[v]);
    }
    double u[3], w[3], n[3];
    for (int d = 0; d < 3; ++d)
    {
      u[d] = p[1][d] - p[0][d];
      w[d] = p[2][d] - p[0][d];
    }
    n[0] = u[1] * w[2] - u[2] * w[1];
    n[1] = u[2] * w[0] - u[0] * w[2];
    n[2] = u[0] * w[1] - u[1] * w[0];
    volumes.push_back(
      (n[0] * (p[3][0] - p[0][0]) + n[1] * (p[3][1] - p[0][1]) + n[2] * (p[3][2] - p[0][2])) / 6.0);
  }
  return volumes;
}

/// Counts error and warning events of one VTK object (and keeps them off the console).
class EventCounter
{
public:
  explicit EventCounter(vtkObject* object)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback([](vtkObject*, unsigned long event, void* clientData, void* callData) {
      auto* self = static_cast<EventCounter*>(clientData);
      (event == vtkCommand::ErrorEvent ? self->Errors : self->Warnings)++;
      self->LastMessage = callData ? static_cast<const char*>(callData) : "";
    });
    object->AddObserver(vtkCommand::ErrorEvent, this->Callback);
    object->AddObserver(vtkCommand::WarningEvent, this->Callback);
  }
  int Errors = 0;
  int Warnings = 0;
  std::string LastMessage;

private:
  vtkNew<vtkCallbackCommand> Callback;
};

/// Watches `object` with a counter that outlives the helper that ran it (until the next call).
inline EventCounter* WatchEvents(vtkObject* object)
{
  static std::unique_ptr<EventCounter> last;
  last = std::make_unique<EventCounter>(object);
  return last.get();
}

/// A mesh of every supported linear 3D cell sharing faces: a hexahedron with a wedge, a pyramid and a
/// tet glued on, plus a quad and a line that must be dropped.
/// A hexahedron with a pyramid on its top, a wedge on its x = 1 face, a tet on the pyramid.
inline vtkSmartPointer<vtkUnstructuredGrid> MixedMesh()
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  const double xyz[][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
    { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 }, // hexahedron 0..7
    { 0.5, 0.5, 2 },                       // 8: pyramid apex above the top face
    { 2, 0, 0.5 }, { 2, 1, 0.5 },          // 9, 10: wedge ridge beyond x = 1
    { 0.5, -1, 1.5 } };                    // 11: tet apex beyond the pyramid's y = 0 side
  for (const auto& p : xyz)
  {
    points->InsertNextPoint(p);
  }
  grid->SetPoints(points);
  const vtkIdType hexahedron[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
  const vtkIdType pyramid[5] = { 4, 5, 6, 7, 8 };
  // Wedge on the x = 1 face: triangles (1,5,9) and (2,6,10); (1,5,9) must face away from (2,6,10).
  const vtkIdType wedge[6] = { 1, 9, 5, 2, 10, 6 };
  const vtkIdType tet[4] = { 4, 5, 8, 11 }; // on the pyramid's face (4,5,8)
  const vtkIdType quad[4] = { 0, 1, 2, 3 };
  const vtkIdType line[2] = { 0, 6 };
  grid->InsertNextCell(VTK_HEXAHEDRON, 8, hexahedron);
  grid->InsertNextCell(VTK_PYRAMID, 5, pyramid);
  grid->InsertNextCell(VTK_WEDGE, 6, wedge);
  grid->InsertNextCell(VTK_TETRA, 4, tet);
  grid->InsertNextCell(VTK_QUAD, 4, quad);
  grid->InsertNextCell(VTK_LINE, 2, line);
  vtkNew<vtkIntArray> label;
  label->SetName("label");
  for (int c = 0; c < 6; ++c)
  {
    label->InsertNextValue(10 + c);
  }
  grid->GetCellData()->AddArray(label);
  return grid;
}
/// Positions of a higher-order cell's nodes in a straight cell with the given corners. VTK 9.1's
/// vtkTriQuadraticPyramid lists parametric coordinates of its own kind, so its nodes are placed by
/// their definition (edge midpoints, face and cell centroids) instead.
inline std::vector<std::array<double, 3>> StraightNodes(int type, vtkCell* linear)
{
  std::vector<std::array<double, 3>> nodes;
  auto corner = [linear](int c) {
    std::array<double, 3> p;
    linear->GetPoints()->GetPoint(c, p.data());
    return p;
  };
  auto mean = [&](std::initializer_list<std::array<double, 3>> points) {
    std::array<double, 3> m = { 0, 0, 0 };
    for (const auto& p : points)
    {
      for (int d = 0; d < 3; ++d)
      {
        m[d] += p[d] / static_cast<double>(points.size());
      }
    }
    return m;
  };
  if (type == VTK_TRIQUADRATIC_PYRAMID)
  {
    const auto c0 = corner(0), c1 = corner(1), c2 = corner(2), c3 = corner(3), apex = corner(4);
    const auto base = mean({ c0, c1, c2, c3 });
    nodes = { c0, c1, c2, c3, apex, mean({ c0, c1 }), mean({ c1, c2 }), mean({ c2, c3 }), mean({ c3, c0 }),
      mean({ c0, apex }), mean({ c1, apex }), mean({ c2, apex }), mean({ c3, apex }), base,
      mean({ c0, c1, apex }), mean({ c1, c2, apex }), mean({ c2, c3, apex }), mean({ c3, c0, apex }),
      mean({ base, base, base, apex }) };
    return nodes;
  }
  vtkNew<vtkGenericCell> target;
  target->SetCellType(type);
  const double* pcoords = target->GetParametricCoords();
  std::vector<double> weights(static_cast<std::size_t>(linear->GetNumberOfPoints()));
  for (vtkIdType n = 0; n < target->GetNumberOfPoints(); ++n)
  {
    double pc[3] = { pcoords[3 * n], pcoords[3 * n + 1], pcoords[3 * n + 2] };
    std::array<double, 3> x;
    int subId = 0;
    linear->EvaluateLocation(subId, pc, x.data(), weights.data());
    nodes.push_back(x);
  }
  return nodes;
}

/// A higher-order copy of a linear mesh: every cell whose type is a key of `types` becomes the mapped
/// type with its nodes placed in the straight cell (nodes of neighbours shared), the other cells kept;
/// then `deform` moves every point, which curves the cells. Point arrays: "f" = x^2 + y z and an
/// integer "rank" (the point id); cell arrays kept.
inline vtkSmartPointer<vtkUnstructuredGrid> Elevate(
  vtkUnstructuredGrid* linear, const std::map<int, int>& types, void (*deform)(double*))
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  std::map<std::array<long long, 3>, vtkIdType> byPosition; // rounded, to share nodes exactly
  auto idOf = [&](const std::array<double, 3>& x) {
    const std::array<long long, 3> key = { std::llround(x[0] * 1e9), std::llround(x[1] * 1e9),
      std::llround(x[2] * 1e9) };
    auto found = byPosition.emplace(key, points->GetNumberOfPoints());
    if (found.second)
    {
      points->InsertNextPoint(x.data());
    }
    return found.first->second;
  };
  vtkNew<vtkGenericCell> cell;
  grid->GetCellData()->CopyAllocate(linear->GetCellData());
  for (vtkIdType c = 0; c < linear->GetNumberOfCells(); ++c)
  {
    linear->GetCell(c, cell);
    const auto mapped = types.find(cell->GetCellType());
    const int type = mapped == types.end() ? cell->GetCellType() : mapped->second;
    std::vector<std::array<double, 3>> nodes;
    if (mapped == types.end())
    {
      for (vtkIdType n = 0; n < cell->GetNumberOfPoints(); ++n)
      {
        nodes.push_back({ 0, 0, 0 });
        cell->GetPoints()->GetPoint(n, nodes.back().data());
      }
    }
    else
    {
      nodes = StraightNodes(type, cell);
    }
    std::vector<vtkIdType> ids;
    for (const auto& x : nodes)
    {
      ids.push_back(idOf(x));
    }
    const vtkIdType added = grid->InsertNextCell(type, static_cast<vtkIdType>(ids.size()), ids.data());
    grid->GetCellData()->CopyData(linear->GetCellData(), c, added);
  }
  vtkNew<vtkDoubleArray> f;
  f->SetName("f");
  vtkNew<vtkIntArray> rank;
  rank->SetName("rank");
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    double x[3];
    points->GetPoint(p, x);
    deform(x);
    points->SetPoint(p, x);
    f->InsertNextValue(x[0] * x[0] + x[1] * x[2]);
    rank->InsertNextValue(static_cast<int>(p));
  }
  grid->SetPoints(points);
  grid->GetPointData()->AddArray(f);
  grid->GetPointData()->AddArray(rank);
  return grid;
}

/// Boundary triangles a conforming tet split of the level-L subdivision of `mesh` must have: L^2 per
/// boundary triangle and 2 L^2 per boundary quadrilateral. Faces are keyed by their corners (listed
/// first), so neighbours whose higher-order faces have different nodes still share them.
inline long long ExpectedSubdividedBoundaryTriangles(vtkDataSet* mesh, int level)
{
  std::map<std::vector<vtkIdType>, std::pair<int, int>> faces; // count, edges
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCell(c, cell);
    if (cell->GetCellDimension() != 3)
    {
      continue;
    }
    for (int f = 0; f < cell->GetNumberOfFaces(); ++f)
    {
      vtkCell* face = cell->GetFace(f);
      vtkIdList* ids = face->GetPointIds();
      std::vector<vtkIdType> key(ids->GetPointer(0), ids->GetPointer(0) + face->GetNumberOfEdges());
      std::sort(key.begin(), key.end());
      auto& entry = faces[key];
      entry.first++;
      entry.second = face->GetNumberOfEdges();
    }
  }
  long long triangles = 0;
  for (const auto& face : faces)
  {
    triangles += face.second.first == 1 ? static_cast<long long>(face.second.second - 2) * level * level : 0;
  }
  return triangles;
}

/// One quadratic tetrahedron with a constant point scalar (flat corners and wild mid-edge nodes).
inline vtkSmartPointer<vtkUnstructuredGrid> QuadraticTetraMesh(int type = VTK_QUADRATIC_TETRA)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> values;
  for (int i = 0; i < 10; ++i)
  {
    points->InsertNextPoint(i % 2, (i / 2) % 2, i / 4);
    values->InsertNextValue(0.5);
  }
  grid->SetPoints(points);
  const vtkIdType ids[10] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9 };
  grid->InsertNextCell(type, 10, ids);
  grid->GetPointData()->SetScalars(values);
  return grid;
}

} // namespace uvtest

#endif
