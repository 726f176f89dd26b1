// Whether the pieces the ranks of a parallel run hold already form a partition good for ordered
// compositing: each piece inside its own box, no two boxes overlapping, and no piece much larger
// than the average. Such pieces can be rendered where they are, in the order of their boxes;
// moving their cells (ParaView's redistribution, on every change of the data) would gain nothing.
// VTK-free; the ParaView representation gathers the boxes and asks.
#ifndef uvPiecePartition_h
#define uvPiecePartition_h

#include <algorithm>
#include <cmath>
#include <vector>

namespace uv
{

struct RankPiece
{
  double Bounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 }; ///< xmin xmax ymin ymax zmin zmax
  double Cells = 0.0;

  bool IsEmpty() const
  {
    return !(this->Cells > 0.0) || !(this->Bounds[0] <= this->Bounds[1]) ||
      !(this->Bounds[2] <= this->Bounds[3]) || !(this->Bounds[4] <= this->Bounds[5]);
  }

  /// This rank's piece together with another piece on the same rank: the box around both.
  void Merge(const RankPiece& other)
  {
    if (other.IsEmpty())
    {
      return;
    }
    if (this->IsEmpty())
    {
      *this = other;
      return;
    }
    for (int axis = 0; axis < 3; ++axis)
    {
      this->Bounds[2 * axis] = std::min(this->Bounds[2 * axis], other.Bounds[2 * axis]);
      this->Bounds[2 * axis + 1] = std::max(this->Bounds[2 * axis + 1], other.Bounds[2 * axis + 1]);
    }
    this->Cells += other.Cells;
  }
};

struct PiecePartitionLimits
{
  /// The largest piece may hold this many times the average piece's cells. Redistribution would
  /// balance them, but it moves cells on every change of the data, which costs about a frame.
  double MaximumImbalance = 1.5;
  /// Boxes may overlap by this fraction of the whole box's size along an axis (rounding of
  /// coordinates on a shared face), and still count as apart.
  double Tolerance = 1e-6;
};

/// Whether boxes a and b are apart: separated along at least one axis, within `slack` per axis.
inline bool BoxesApart(const double a[6], const double b[6], const double slack[3])
{
  for (int axis = 0; axis < 3; ++axis)
  {
    const double overlap = std::min(a[2 * axis + 1], b[2 * axis + 1]) - std::max(a[2 * axis], b[2 * axis]);
    if (overlap <= slack[axis])
    {
      return true;
    }
  }
  return false;
}

/// True when there are several pieces and the non-empty ones are apart and balanced. A rank with
/// an empty piece is a load not shared, so it counts in the average as zero.
inline bool PiecesFormPartition(const std::vector<RankPiece>& pieces, const PiecePartitionLimits& limits = {})
{
  if (pieces.size() < 2)
  {
    return false;
  }
  double whole[6] = { HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL };
  double total = 0.0;
  double largest = 0.0;
  for (const RankPiece& piece : pieces)
  {
    if (piece.IsEmpty())
    {
      continue;
    }
    for (int axis = 0; axis < 3; ++axis)
    {
      whole[2 * axis] = std::min(whole[2 * axis], piece.Bounds[2 * axis]);
      whole[2 * axis + 1] = std::max(whole[2 * axis + 1], piece.Bounds[2 * axis + 1]);
    }
    total += piece.Cells;
    largest = std::max(largest, piece.Cells);
  }
  const double average = total / static_cast<double>(pieces.size());
  if (!(total > 0.0) || largest > limits.MaximumImbalance * average)
  {
    return false;
  }
  double slack[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    slack[axis] = limits.Tolerance * (whole[2 * axis + 1] - whole[2 * axis]);
  }
  for (std::size_t i = 0; i < pieces.size(); ++i)
  {
    for (std::size_t j = i + 1; j < pieces.size(); ++j)
    {
      if (!pieces[i].IsEmpty() && !pieces[j].IsEmpty() &&
        !BoxesApart(pieces[i].Bounds, pieces[j].Bounds, slack))
      {
        return false;
      }
    }
  }
  return true;
}

/// Whether `pieces` (one dataset, one piece a rank) may be kept where they are beside the pieces of
/// other datasets already kept in the same view (`kept`, one piece a rank each): `pieces` form a
/// partition, and so do the boxes around everything kept on each rank, which is what the view
/// orders the ranks by (their load together is not the question).
inline bool PiecesFormPartitionBeside(const std::vector<RankPiece>& pieces,
  const std::vector<std::vector<RankPiece>>& kept, const PiecePartitionLimits& limits = {})
{
  if (!PiecesFormPartition(pieces, limits))
  {
    return false;
  }
  std::vector<RankPiece> together = pieces;
  for (const std::vector<RankPiece>& other : kept)
  {
    for (std::size_t rank = 0; rank < together.size() && rank < other.size(); ++rank)
    {
      together[rank].Merge(other[rank]);
    }
  }
  PiecePartitionLimits apartOnly = limits;
  apartOnly.MaximumImbalance = HUGE_VAL;
  return PiecesFormPartition(together, apartOnly);
}

} // namespace uv

#endif
