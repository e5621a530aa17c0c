#pragma once
// The wall pieces of a plan: every room's outline cut where other rooms of its level begin or end along
// it, each piece either exterior (on the level's footprint boundary) or shared with one neighbour. The
// floor plan strokes them, the annotator places windows and doors on them, and the furnishing reads a
// room's walls from them, so all three see the same walls. Metres, plan frame.
#include <vector>

#include "layout/geometry.h"
#include "layout/layout.h"

namespace villa {

inline constexpr int kExterior = -1;  // WallPiece::neighbour of a piece on the footprint boundary

struct WallPiece {
  Segment segment;   // along the room's edge, in its ring's direction (a counter-clockwise room lies left)
  int room = -1;     // index into Layout::rooms
  int edge = 0;      // the room edge it lies on: polygon[edge] -> polygon[(edge + 1) % size]
  Interval along;    // the piece as metres along that edge from polygon[edge]
  int neighbour = kExterior;  // index of the room of the same level across the piece, or kExterior
  bool exterior() const { return neighbour == kExterior; }
};

// The outline of room `room` cut into wall pieces, edge by edge in ring order and along each edge from
// its first corner. A stretch another room of the level shares (collinear, overlapping by more than the
// tolerance: geometry.h's IntervalsOnBoundary) is one piece per neighbour, merged across that neighbour's
// collinear corners; what no room shares is exterior, gaps not longer than the tolerance dropped.
// Overlapping rooms (an invalid layout) may give two shared pieces over the same stretch.
std::vector<WallPiece> RoomWallPieces(const Layout& layout, int room, double tolerance = kTolerance);

// RoomWallPieces of every room of `level`, rooms in layout order: each shared stretch appears twice, once
// from each side.
std::vector<WallPiece> LevelWallPieces(const Layout& layout, int level, double tolerance = kTolerance);

}  // namespace villa
