// Vertex -> cell incidence in compressed rows, free of VTK so it can be tested alone.
#ifndef uvVertexCellLinks_h
#define uvVertexCellLinks_h

#include <cstdint>
#include <vector>

namespace uv
{

struct VertexCellLinks
{
  // Cells of vertex v are Cells[Offsets[v] .. Offsets[v+1]), in increasing cell order, so anything
  // gathered through them is summed in the same order on every run and thread count.
  std::vector<std::int64_t> Offsets;
  std::vector<std::int64_t> Cells;

  std::int64_t Degree(std::int64_t vertex) const { return Offsets[vertex + 1] - Offsets[vertex]; }
};

/// Cells given in compressed rows: cell c has vertices connectivity[cellOffsets[c] .. cellOffsets[c+1]).
/// A vertex listed twice in one cell is linked once per listing. Vertex ids must be < numVertices.
template <typename IdType>
VertexCellLinks BuildVertexCellLinks(std::int64_t numVertices, const std::vector<IdType>& cellOffsets,
  const std::vector<IdType>& connectivity)
{
  VertexCellLinks links;
  links.Offsets.assign(numVertices + 1, 0);
  for (const IdType vertex : connectivity)
  {
    ++links.Offsets[vertex + 1];
  }
  for (std::int64_t v = 0; v < numVertices; ++v)
  {
    links.Offsets[v + 1] += links.Offsets[v];
  }
  links.Cells.resize(connectivity.size());
  std::vector<std::int64_t> cursor(links.Offsets.begin(), links.Offsets.end() - 1);
  const std::int64_t numCells = cellOffsets.empty() ? 0 : static_cast<std::int64_t>(cellOffsets.size()) - 1;
  for (std::int64_t cell = 0; cell < numCells; ++cell)
  {
    for (IdType k = cellOffsets[cell]; k < cellOffsets[cell + 1]; ++k)
    {
      links.Cells[cursor[connectivity[k]]++] = cell;
    }
  }
  return links;
}

} // namespace uv

#endif
