// What a mapper's input held when the mapper last read it, so that new arrays with the same content
// (a reader's next time step of a static mesh) are recognised as no change, and a time step tells
// which of cells, points and values changed. Same array and modification time: unchanged at no cost;
// otherwise its bytes are fingerprinted (uvContentFingerprint.h).
#ifndef vtkuvMeshContent_h
#define vtkuvMeshContent_h

#include "uvContentFingerprint.h"
#include "vtkuvRenderedScalar.h"
#include "vtkUnstructuredVolumeCompatibility.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <cstdint>
#include <string>

namespace vtkuv
{

class ArrayContent
{
public:
  /// Whether `array` (may be null) holds other content than the array last seen; remembers it.
  bool Update(vtkDataArray* array)
  {
    if (array == this->Array && array && array->GetMTime() == this->Time)
      return false;
    const std::uint64_t fingerprint = FingerprintOf(array);
    const bool changed = !this->Known || array == nullptr || this->Array == nullptr ||
      fingerprint != this->Fingerprint || FormatOf(array) != this->Format;
    this->Array = array;
    this->Time = array ? array->GetMTime() : 0;
    this->Fingerprint = fingerprint;
    this->Format = FormatOf(array);
    this->Known = true;
    return changed;
  }

  void Forget() { *this = ArrayContent(); }

private:
  /// Type, components and tuples: equal bytes in another layout are other content.
  static std::uint64_t FormatOf(vtkDataArray* array)
  {
    if (!array)
      return 0;
    return uv::MixBits(static_cast<std::uint64_t>(array->GetDataType()) ^
      (static_cast<std::uint64_t>(array->GetNumberOfComponents()) << 8) ^
      (static_cast<std::uint64_t>(array->GetNumberOfTuples()) << 24));
  }

  /// The fingerprint of an array's values. An array of another memory layout (VTK 9.6 gives a grid of
  /// one cell type a constant implicit array of types, which a deep copy turns into a plain one) is
  /// fingerprinted through a contiguous copy, so equal values give equal fingerprints either way.
  std::uint64_t FingerprintOf(vtkDataArray* array)
  {
    if (!array)
      return ++this->Unique;
    if (!array->HasStandardMemoryLayout())
    {
      vtkSmartPointer<vtkDataArray> contiguous =
        vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(array->GetDataType()));
      contiguous->DeepCopy(array);
      if (!contiguous->HasStandardMemoryLayout())
        return ++this->Unique;
      return this->FingerprintOf(contiguous);
    }
    const std::size_t bytes = static_cast<std::size_t>(array->GetDataSize()) * array->GetDataTypeSize();
    return uv::Fingerprint(array->GetVoidPointer(0), bytes, [](std::size_t count, const auto& run) {
      vtkSMPTools::For(0, static_cast<vtkIdType>(count), 1, [&](vtkIdType begin, vtkIdType end) {
        run(static_cast<std::size_t>(begin), static_cast<std::size_t>(end));
      });
    });
  }

  const vtkDataArray* Array = nullptr; // compared by address only, never dereferenced
  vtkMTimeType Time = 0;
  std::uint64_t Fingerprint = 0, Format = 0;
  std::uint64_t Unique = 0x8000000000000000ULL;
  bool Known = false;
};

/// What of a mapper's input differs from the input it saw before, by content.
struct MeshChanges
{
  bool Cells = false, Points = false, Values = false;
  bool Any() const { return this->Cells || this->Points || this->Values; }
};

/// The content of a mapper's input as of its last update: an unstructured grid's cells, points and
/// rendered scalar, array by array; any other dataset by address and modification time (any change
/// counts as new cells).
class MeshContent
{
public:
  MeshChanges Update(vtkDataSet* input, const RenderedScalar& scalar)
  {
    MeshChanges changed;
    auto* grid = vtkUnstructuredGrid::SafeDownCast(input);
    if (grid && grid->GetCells() && uvcompat::CellTypesArray(grid) && grid->GetPoints())
    {
      // Every array is looked at (no short cut), so that each is remembered.
      changed.Cells |= this->Connectivity.Update(grid->GetCells()->GetConnectivityArray());
      changed.Cells |= this->Offsets.Update(grid->GetCells()->GetOffsetsArray());
      changed.Cells |= this->Types.Update(uvcompat::CellTypesArray(grid));
      changed.Points = this->Points.Update(grid->GetPoints()->GetData());
    }
    else
    {
      changed.Cells = input != this->Other || input->GetMTime() != this->OtherTime;
      this->Other = input;
      this->OtherTime = input->GetMTime();
    }
    const std::string selection = Selection(input, scalar);
    changed.Cells |= selection != this->SelectionSeen;
    this->SelectionSeen = selection;
    changed.Values = this->Scalars.Update(scalar.Array);
    return changed;
  }
  void Forget() { *this = MeshContent(); }

private:
  /// What is rendered, apart from the values: a change of it counts as new cells.
  static std::string Selection(vtkDataSet* input, const RenderedScalar& scalar)
  {
    const char* name = scalar.Array->GetName();
    return std::string(scalar.OnCells ? "cells:" : "points:") + (name ? name : "") + ":" +
      std::to_string(scalar.Component) + ":" + std::to_string(scalar.Array->GetNumberOfComponents()) + ":" +
      std::to_string(input->GetNumberOfPoints()) + ":" + std::to_string(input->GetNumberOfCells());
  }

  ArrayContent Connectivity, Offsets, Types, Points, Scalars;
  std::string SelectionSeen;
  const void* Other = nullptr; // compared by address only
  vtkMTimeType OtherTime = 0;
};

} // namespace vtkuv

#endif
