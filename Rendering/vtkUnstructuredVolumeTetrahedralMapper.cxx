#include "vtkUnstructuredVolumeTetrahedralMapper.h"

#include "vtkUnstructuredVolumeFrame.h"
#include "vtkUnstructuredVolumeFrameStatistics.h"
#include "vtkUnstructuredVolumeTetrahedralState.h"

#include "vtkUnstructuredGridBase.h"

vtkUnstructuredVolumeTetrahedralMapper::vtkUnstructuredVolumeTetrahedralMapper() = default;

vtkUnstructuredVolumeTetrahedralMapper::~vtkUnstructuredVolumeTetrahedralMapper() = default;

void vtkUnstructuredVolumeTetrahedralMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

bool vtkUnstructuredVolumeTetrahedralMapper::UpdateTetrahedralMesh(
  vtkUnstructuredGridBase* input, const vtkuv::RenderedScalar& scalar)
{
  vtkUnstructuredVolumeTetrahedralState& state = this->GetTetrahedralState();
  vtkuv::TetrahedralMesh::Change change;
  const std::string error =
    state.Mesh.Update(input, scalar, [this](double progress) { this->UpdateProgress(progress); }, change);
  this->MeshUpdates = { state.Mesh.Builds, state.Mesh.PointRefreshes, state.Mesh.ValueRefreshes };
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return false;
  }
  if (change == vtkuv::TetrahedralMesh::Change::All)
    state.Order.Invalidate(); // moved points it sees itself; new values change it only through the list
  if (change != vtkuv::TetrahedralMesh::Change::Nothing)
  {
    for (const auto& [key, warning] : vtkuv::MeshUpdateWarnings(state.Mesh, input->GetNumberOfCells()))
      this->WarnOnce(key, warning);
  }
  return state.Mesh.Size() > 0;
}

void vtkUnstructuredVolumeTetrahedralMapper::CommitIsosurfaces(bool cellScalar)
{
  vtkUnstructuredVolumeTetrahedralState& state = this->GetTetrahedralState();
  state.Isovalues.clear();
  for (const uv::Isosurface& surface : state.DrawnIsosurfaces)
    state.Isovalues.push_back(surface.Value);
  state.DrawCellSurfaces = cellScalar && !state.Isovalues.empty();
  if (state.DrawCellSurfaces)
    state.UpdateCellSurfaces();
}

void vtkUnstructuredVolumeTetrahedralMapper::UpdateGradients(bool needed)
{
  vtkUnstructuredVolumeTetrahedralState& state = this->GetTetrahedralState();
  state.NeedGradients = needed;
  if (needed)
    this->UpdateVertexGradients(state.Gradients, state.Mesh.Tetrahedra, state.Mesh.Scalar, state.Mesh.Version);
}

void vtkUnstructuredVolumeTetrahedralMapper::UpdateOrder(const vtkUnstructuredVolumeFrame& frame, bool frontToBack)
{
  vtkUnstructuredVolumeTetrahedralState& state = this->GetTetrahedralState();
  const glm::dvec3 center = state.Mesh.Center;
  state.Order.Update(state.Mesh, state.Lists.Drawn, frame.EyeInModel(center), frame.ViewInModel(center),
    frame.Parallel, frontToBack, this->VisibilityOrder == FACE_ORDER, frame.Pixels(center));
  this->NumberOfCyclesBroken = static_cast<vtkIdType>(state.Order.CyclesBroken);
  this->NumberOfGapConstraints = static_cast<vtkIdType>(state.Order.GapConstraints);
}

bool vtkUnstructuredVolumeTetrahedralMapper::ChooseLengthTable(const vtkUnstructuredVolumeFrame& frame, bool cutsNeeded)
{
  vtkUnstructuredVolumeTetrahedralState& state = this->GetTetrahedralState();
  if (this->SegmentIntegration == EXACT || cutsNeeded)
    return false;
  if (!state.LengthTable.Update({ state.Mesh.PointData, state.Mesh.TetrahedronPoints, state.Mesh.Version },
        state.TransferFunction.Nodes, frame.ModelToEye(state.Mesh.Center)))
    return false;
  return this->SegmentIntegration == TABLE || state.LengthTable.Error <= this->TransferFunctionTolerance;
}

void vtkUnstructuredVolumeTetrahedralMapper::GetDrawnBounds(double bounds[6])
{
  if (!this->GetTetrahedralState().Mesh.DrawnBounds(bounds))
    this->Superclass::GetDrawnBounds(bounds);
}

void vtkUnstructuredVolumeTetrahedralMapper::ReportStatistics(vtkUnstructuredVolumeFrameStatistics* statistics)
{
  this->Superclass::ReportStatistics(statistics);
  vtkUnstructuredVolumeTetrahedralState& state = this->GetTetrahedralState();
  statistics->SetValue("DrawnTetrahedra", static_cast<double>(state.DrawnTetrahedra));
  statistics->SetValue("Sorts", state.Order.Sorts);
  statistics->SetValue("GradientComputations", state.Gradients.Computations);
}
