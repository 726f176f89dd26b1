/**
 * @class vtkPreIntegratedTetrahedraSegmentTable
 * @brief vtkPreIntegratedTetrahedraMapper's table of whole segments by front scalar, back scalar and
 * length, on the CPU.
 *
 * uvTetrahedronSegmentTable.h's table of the current nodes for lengths up to the longest edge of the
 * mesh as drawn, built in parallel only when either changes (compared exactly), with what reading it
 * trilinearly costs in accuracy measured against the exact segments: the AUTOMATIC integration uses
 * it where that error is within the transfer-function tolerance. Version tells the GPU copy when to
 * upload. (CPU layer of the tetrahedra mapper; not wrapped.)
 */
#ifndef vtkPreIntegratedTetrahedraSegmentTable_h
#define vtkPreIntegratedTetrahedraSegmentTable_h

#include "uvTetrahedronSegmentTable.h"

#include "vtkSMPTools.h"

#include <cstdint>
#include <vector>

class vtkPreIntegratedTetrahedraSegmentTable
{
public:
  static constexpr int ScalarSize = 128;    // texels per scalar axis
  static constexpr int LengthSize = 32;     // texels along the length
  static constexpr int ErrorSamples = 4096; // segments the error is measured on

  uv::TetrahedronSegmentTable Table;
  double Error = 0.0;        ///< largest difference from the exact segments, any channel
  std::uint64_t Version = 0; ///< bumped on every build
  int Builds = 0;            ///< since creation

  void Update(const std::vector<uv::TransferFunction::Node>& nodes, double maxLength, const uv::PsiTable& psi)
  {
    if (this->Version > 0 && maxLength == this->Table.MaxLength && nodes == this->Nodes)
      return;
    const uv::TransferFunction function(nodes);
    this->Table =
      uv::MakeTetrahedronSegmentTable(function, maxLength, ScalarSize, LengthSize, psi, [](int count, const auto& build) {
        vtkSMPTools::For(0, count, 64, [&](vtkIdType begin, vtkIdType end) {
          for (vtkIdType row = begin; row < end; ++row)
            build(static_cast<int>(row));
        });
      });
    this->Error = uv::TetrahedronSegmentTableError(function, this->Table, ErrorSamples);
    this->Nodes = nodes;
    ++this->Version;
    ++this->Builds;
  }

private:
  std::vector<uv::TransferFunction::Node> Nodes;
};

#endif
