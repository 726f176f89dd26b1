/**
 * @class vtkUnstructuredVolumeSegmentLengthTable
 * @brief The table of whole segments by front scalar, back scalar and length that the tetrahedra
 * mapper and the shells' cell projection read instead of cutting segments at every node.
 *
 * uvTetrahedronSegmentTable.h's table of the current nodes for lengths up to the longest edge of the
 * mesh as drawn (its longest model-space edge, found once per mesh change, times the most the
 * model-to-eye matrix stretches), built in parallel only when the nodes change or that length leaves
 * [half the table's, the table's], with what reading it
 * trilinearly costs in accuracy measured against the exact segments: the AUTOMATIC integration reads
 * it where that error is within the transfer-function tolerance. Its GPU copy (a 3D texture) is
 * uploaded when the build's version changes; Bind sets uvSegmentLengthTableLib.glsl's uniforms.
 * (Layer shared by the mappers; not wrapped.)
 */
#ifndef vtkUnstructuredVolumeSegmentLengthTable_h
#define vtkUnstructuredVolumeSegmentLengthTable_h

#include "uvTetrahedronSegmentTable.h"
#include "vtkUnstructuredVolumeTexture3D.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"

#include <cmath>
#include <cstdint>
#include <vector>

class vtkUnstructuredVolumeSegmentLengthTable
{
public:
  static constexpr int ScalarSize = 128;    // texels per scalar axis
  static constexpr int LengthSize = 32;     // texels along the length
  static constexpr int ErrorSamples = 4096; // segments the error is measured on

  double Error = 0.0;        ///< largest difference from the exact segments, any channel
  int Builds = 0;            ///< since creation

  /// The tetrahedra the table must cover: 4 point ids each into `PointData`'s 4 floats a point
  /// (position, scalar), and the version of the mesh they come from (edges are measured once a
  /// version).
  struct Tetrahedra
  {
    const std::vector<float>& PointData;
    const std::vector<std::uint32_t>& TetrahedronPoints;
    std::uint64_t Version;
  };

  /// Brings the table up to date with `nodes` and the longest segment the tetrahedra can hold in eye
  /// space; false (nothing built) for a mesh without extent.
  bool Update(const Tetrahedra& mesh, const std::vector<uv::TransferFunction::Node>& nodes,
    const glm::dmat4& modelToEye)
  {
    this->UpdateLongestEdge(mesh);
    const double longest = this->LongestEdge * uv::LargestStretch(glm::dmat3(modelToEye));
    if (!(longest > 0.0))
      return false;
    // A table of somewhat longer segments than the mesh now holds still covers it (moving points
    // of a time series shorten and lengthen edges): kept down to half its length.
    const bool covers = longest <= this->Table.MaxLength && 2.0 * longest >= this->Table.MaxLength;
    if (this->Version > 0 && covers && nodes == this->Nodes)
      return true;
    const uv::TransferFunction function(nodes);
    this->Table = uv::MakeTetrahedronSegmentTable(function, longest, ScalarSize, LengthSize, uv::SharedPsiTable(),
      [](int count, const auto& build) {
        vtkSMPTools::For(0, count, 64, [&](vtkIdType begin, vtkIdType end) {
          for (vtkIdType row = begin; row < end; ++row)
            build(static_cast<int>(row));
        });
      });
    this->Error = uv::TetrahedronSegmentTableError(function, this->Table, ErrorSamples);
    this->Nodes = nodes;
    ++this->Version;
    ++this->Builds;
    return true;
  }

  void Sync(vtkOpenGLRenderWindow* window)
  {
    this->Texture.Sync(
      window, this->Table.ScalarSize, this->Table.ScalarSize, this->Table.LengthSize, this->Table.Texels, this->Version);
  }

  /// The texture and how scalars and lengths map onto it (texel centres at the ends).
  void Bind(vtkShaderProgram* program)
  {
    this->Texture.Bind(program, "segmentLengthTable");
    const uv::TetrahedronSegmentTable& table = this->Table;
    const float scalar[2] = { static_cast<float>(table.ScalarSize - 1) / table.ScalarSize, 0.5f / table.ScalarSize };
    const float length[3] = { static_cast<float>(1.0 / table.LengthScale),
      static_cast<float>((table.LengthSize - 1) / (table.LengthSize * table.LengthWarp())), 0.5f / table.LengthSize };
    program->SetUniform2f("scalarToTexture", scalar);
    program->SetUniform3f("lengthToTexture", length);
  }
  void Unbind() { this->Texture.Unbind(); }
  void Release() { this->Texture.Release(); }

private:
  void UpdateLongestEdge(const Tetrahedra& mesh)
  {
    if (this->LongestEdgeFor == mesh.Version)
      return;
    vtkSMPThreadLocal<double> longest(0.0);
    const auto count = static_cast<vtkIdType>(mesh.TetrahedronPoints.size() / 4);
    vtkSMPTools::For(0, count, [&](vtkIdType begin, vtkIdType end) {
      double& mine = longest.Local();
      mine = std::max(mine, uv::LongestSquaredEdge(mesh.PointData, mesh.TetrahedronPoints,
                              static_cast<std::size_t>(begin), static_cast<std::size_t>(end)));
    });
    double squared = 0.0;
    for (double value : longest)
      squared = std::max(squared, value);
    this->LongestEdge = std::sqrt(squared);
    this->LongestEdgeFor = mesh.Version;
  }

  uv::TetrahedronSegmentTable Table;
  std::vector<uv::TransferFunction::Node> Nodes;
  std::uint64_t Version = 0; // bumped on every build
  double LongestEdge = 0.0;  // model space
  std::uint64_t LongestEdgeFor = 0;
  vtkUnstructuredVolumeTexture3D Texture;
};

#endif
