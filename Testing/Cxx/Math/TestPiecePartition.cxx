// Whether the ranks' pieces already form a partition (uvPiecePartition.h): slabs and k-d blocks
// sharing faces do, interleaved or overlapping pieces do not, nor pieces far from balanced.
#include "uvPiecePartition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
uv::RankPiece Piece(double x0, double x1, double y0, double y1, double z0, double z1, double cells)
{
  uv::RankPiece piece;
  const double bounds[6] = { x0, x1, y0, y1, z0, z1 };
  std::copy(bounds, bounds + 6, piece.Bounds);
  piece.Cells = cells;
  return piece;
}
}

TEST(PiecePartition, SlabsSharingFacesArePartitions)
{
  // The wavelet on 4 ranks: z-slabs of 14 and 15 layers that meet on shared planes.
  EXPECT_TRUE(uv::PiecesFormPartition({ Piece(-10, 10, -10, 10, -10, 4, 14), Piece(-10, 10, -10, 10, 4, 10, 6) },
    { 2.0, 1e-6 }));
  EXPECT_TRUE(uv::PiecesFormPartition({ Piece(0, 1, 0, 1, 0, 14, 14), Piece(0, 1, 0, 1, 14, 29, 15),
    Piece(0, 1, 0, 1, 29, 43, 14), Piece(0, 1, 0, 1, 43, 58, 15) }));
}

TEST(PiecePartition, KdBlocksArePartitions)
{
  EXPECT_TRUE(uv::PiecesFormPartition({ Piece(0, 1, 0, 1, 0, 2, 10), Piece(1, 2, 0, 1, 0, 2, 10),
    Piece(0, 2, 1, 2, 0, 1, 10), Piece(0, 2, 1, 2, 1, 2, 10) }));
}

TEST(PiecePartition, RoundingOnASharedFaceIsTolerated)
{
  const double rounded = 1.0 + 1e-9;
  EXPECT_TRUE(uv::PiecesFormPartition({ Piece(0, rounded, 0, 1, 0, 1, 5), Piece(1, 2, 0, 1, 0, 1, 5) }));
  // A cell layer shared by both (ghost cells, or boundary cells assigned to both) is an overlap.
  EXPECT_FALSE(uv::PiecesFormPartition({ Piece(0, 1.05, 0, 1, 0, 1, 5), Piece(1, 2, 0, 1, 0, 1, 5) }));
}

TEST(PiecePartition, InterleavedPiecesAreNot)
{
  // Cells dealt out like cards: every piece spans the whole domain.
  EXPECT_FALSE(uv::PiecesFormPartition({ Piece(0, 2, 0, 2, 0, 2, 50), Piece(0, 2, 0, 2, 0, 2, 50) }));
  // Apart along no axis although no corner of one lies in the other.
  EXPECT_FALSE(uv::PiecesFormPartition({ Piece(0, 3, 1, 2, 0, 1, 5), Piece(1, 2, 0, 3, 0, 1, 5) }));
}

TEST(PiecePartition, UnbalancedPiecesAreNot)
{
  // A reader that gives every cell to the first rank.
  EXPECT_FALSE(uv::PiecesFormPartition({ Piece(0, 2, 0, 2, 0, 2, 100), uv::RankPiece() }));
  EXPECT_FALSE(uv::PiecesFormPartition({ Piece(0, 1, 0, 1, 0, 1, 80), Piece(1, 2, 0, 1, 0, 1, 20) }));
  EXPECT_TRUE(uv::PiecesFormPartition({ Piece(0, 1, 0, 1, 0, 1, 70), Piece(1, 2, 0, 1, 0, 1, 30) }));
  // Three full ranks and an empty one are within the default imbalance (largest 1.33x the average).
  EXPECT_TRUE(uv::PiecesFormPartition({ Piece(0, 1, 0, 1, 0, 1, 10), Piece(1, 2, 0, 1, 0, 1, 10),
    Piece(2, 3, 0, 1, 0, 1, 10), uv::RankPiece() }));
}

TEST(PiecePartition, OneRankOrNothingIsNot)
{
  EXPECT_FALSE(uv::PiecesFormPartition({ Piece(0, 1, 0, 1, 0, 1, 10) }));
  EXPECT_FALSE(uv::PiecesFormPartition({ uv::RankPiece(), uv::RankPiece() }));
  EXPECT_FALSE(uv::PiecesFormPartition({}));
  const double nan = std::nan("");
  EXPECT_FALSE(uv::PiecesFormPartition({ Piece(nan, 1, 0, 1, 0, 1, 10), Piece(0, 1, 0, 1, 0, 1, 10) }));
}

TEST(PiecePartition, PartitionsOfTwoDatasetsTogether)
{
  // The view orders each rank by the box around everything kept there: two datasets split along
  // different axes are each a partition, but not together.
  std::vector<uv::RankPiece> z = { Piece(0, 2, 0, 2, 0, 1, 10), Piece(0, 2, 0, 2, 1, 2, 10) };
  std::vector<uv::RankPiece> x = { Piece(0, 1, 0, 2, 0, 2, 10), Piece(1, 2, 0, 2, 0, 2, 10) };
  ASSERT_TRUE(uv::PiecesFormPartitionBeside(z, {}));
  ASSERT_TRUE(uv::PiecesFormPartitionBeside(x, {}));
  EXPECT_FALSE(uv::PiecesFormPartitionBeside(x, { z }));
  EXPECT_FALSE(uv::PiecesFormPartitionBeside(z, { x }));
  // A second dataset split like the first (a clip of it, say) keeps the ranks apart, however
  // unbalanced the two are together.
  std::vector<uv::RankPiece> clipped = { Piece(0.5, 1.5, 0, 2, 0, 0.8, 4), Piece(0.5, 1.5, 0, 2, 1.2, 2, 4) };
  std::vector<uv::RankPiece> heavy = { Piece(0, 2, 0, 2, 0, 1, 100), Piece(0, 2, 0, 2, 1, 2, 100) };
  EXPECT_TRUE(uv::PiecesFormPartitionBeside(clipped, { z, heavy }));
  // Its own pieces must still be a partition, beside anything.
  EXPECT_FALSE(uv::PiecesFormPartitionBeside({ Piece(0, 2, 0, 2, 0, 2, 50), Piece(0, 2, 0, 2, 0, 2, 50) }, {}));
}

TEST(PiecePartition, MergeTakesTheBoxAroundBoth)
{
  uv::RankPiece merged = Piece(0, 1, 0, 1, 0, 1, 10);
  merged.Merge(Piece(2, 3, -1, 0.5, 0, 1, 4));
  EXPECT_DOUBLE_EQ(merged.Cells, 14.0);
  EXPECT_DOUBLE_EQ(merged.Bounds[0], 0.0);
  EXPECT_DOUBLE_EQ(merged.Bounds[1], 3.0);
  EXPECT_DOUBLE_EQ(merged.Bounds[2], -1.0);
  EXPECT_DOUBLE_EQ(merged.Bounds[3], 1.0);
  // Merging an empty piece changes nothing; merging into one takes the other.
  uv::RankPiece empty;
  merged.Merge(empty);
  EXPECT_DOUBLE_EQ(merged.Cells, 14.0);
  empty.Merge(Piece(0, 2, 0, 2, 1, 2, 10));
  EXPECT_DOUBLE_EQ(empty.Bounds[4], 1.0);
  EXPECT_DOUBLE_EQ(empty.Cells, 10.0);
}
