/**
 * @class vtkBarycentricShellSegmentTable
 * @brief vtkBarycentricShellMapper's table of whole segments of the sample distance, on the CPU.
 *
 * uvPreIntegration.h's SegmentTable of the current nodes and sample distance, built in parallel only
 * when either changes (compared exactly), with what reading it bilinearly costs in accuracy
 * measured against the exact segments (uv::SegmentTableError): the AUTOMATIC integration uses the
 * table where that error is within the transfer-function tolerance, whatever the nodes' spacing (a
 * sampled colour map has narrow gaps and is still smooth). Version tells the GPU copy when to
 * upload. (CPU layer of the barycentric shell mapper; not wrapped.)
 */
#ifndef vtkBarycentricShellSegmentTable_h
#define vtkBarycentricShellSegmentTable_h

#include "uvOpticalModel.h"
#include "uvPreIntegration.h"

#include "vtkSMPTools.h"

#include <cstdint>
#include <vector>

class vtkBarycentricShellSegmentTable
{
public:
  static constexpr int Size = 256;           // texels per side
  static constexpr int ErrorSamples = 4096;  // segments the error is measured on

  std::vector<float> Texels;
  double Error = 0.0;        ///< largest difference from the exact segments, any channel
  std::uint64_t Version = 0; ///< bumped on every build
  int Builds = 0;            ///< since creation

  void Update(const std::vector<uv::TransferFunction::Node>& nodes, double length)
  {
    if (this->Version > 0 && length == this->Length && nodes == this->Nodes)
      return;
    const uv::TransferFunction function(nodes);
    this->Texels = uv::SegmentTable(function, length, Size, [](int count, const auto& build) {
      vtkSMPTools::For(0, count, 1, [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType row = begin; row < end; ++row)
          build(static_cast<int>(row));
      });
    });
    this->Error = uv::SegmentTableError(function, length, this->Texels, Size, ErrorSamples);
    this->Nodes = nodes;
    this->Length = length;
    ++this->Version;
    ++this->Builds;
  }

private:
  std::vector<uv::TransferFunction::Node> Nodes;
  double Length = 0.0;
};

#endif
