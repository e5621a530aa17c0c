#pragma once
// Triangulation of a plane polygon with holes (ear clipping, holes bridged into the outer ring).
// Used for slabs (room floors with stair holes), wall faces (a wall's elevation with its openings) and caps.
#include <array>
#include <vector>

#include "layout/layout.h"

namespace villa {

// `outer` counter-clockwise, each hole clockwise or counter-clockwise (reoriented as needed), none
// repeating its first point. Returns triangles as indices into the concatenation outer + holes[0] +
// holes[1] + ..., each triangle counter-clockwise. Every input vertex is used: a vertex on a straight
// stretch of boundary is a corner of proper triangles (a zero-area triangle only where ear clipping would
// otherwise get stuck), so faces sharing that edge meet vertex to vertex.
// Degenerate (zero-area) input gives no triangles.
std::vector<std::array<int, 3>> TriangulatePolygon(const Ring& outer, const std::vector<Ring>& holes = {});

}  // namespace villa
