#include "layout/walls.h"

#include <algorithm>

namespace villa {

std::vector<WallPiece> RoomWallPieces(const Layout& layout, int room, double tolerance) {
  std::vector<WallPiece> out;
  const Room& self = layout.rooms[room];
  const Ring& ring = self.polygon;
  std::vector<int> others;
  const Box2 box = BoundingBox(ring);
  for (int j : layout.RoomsOnLevel(self.level))
    if (j != room && BoundingBox(layout.rooms[j].polygon).Touches(box, tolerance)) others.push_back(j);

  std::vector<WallPiece> pieces;
  std::vector<Interval> covered;
  for (std::size_t e = 0; e < ring.size(); ++e) {
    const Segment edge{ring[e], ring[(e + 1) % ring.size()]};
    const double length = Length(edge);
    if (length <= tolerance) continue;
    auto piece = [&](const Interval& along, int neighbour) {
      return WallPiece{SubSegment(edge, along), room, static_cast<int>(e), along, neighbour};
    };
    pieces.clear();
    covered.clear();
    for (int j : others)
      for (const Interval& along : IntervalsOnBoundary(edge, layout.rooms[j].polygon, tolerance)) {
        pieces.push_back(piece(along, j));
        covered.push_back(along);
      }
    for (const Interval& along : ComplementIntervals(MergeIntervals(covered, tolerance), length, tolerance))
      pieces.push_back(piece(along, kExterior));
    std::stable_sort(pieces.begin(), pieces.end(),
                     [](const WallPiece& a, const WallPiece& b) { return a.along.first < b.along.first; });
    out.insert(out.end(), pieces.begin(), pieces.end());
  }
  return out;
}

std::vector<WallPiece> LevelWallPieces(const Layout& layout, int level, double tolerance) {
  std::vector<WallPiece> out;
  for (int room : layout.RoomsOnLevel(level)) {
    std::vector<WallPiece> pieces = RoomWallPieces(layout, room, tolerance);
    out.insert(out.end(), pieces.begin(), pieces.end());
  }
  return out;
}

}  // namespace villa
