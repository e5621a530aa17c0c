#pragma once
// Small realistic rooms for the solver's tests and bench, built in code: box furniture, a table with
// legs, a bookcase with real panels and boards (its cavities and surfaces exactly those of the mesh),
// rectangular, L-shaped and angled rooms with wall slabs around them.
#include <cstdint>
#include <memory>
#include <string>

#include "solver/problem.h"

namespace villa::solver::fixtures {

// A closed box mesh (12 triangles, outward) from min to max.
TriangleMesh BoxMesh(Vec3 min, Vec3 max);
// An asset record of a w x d x h box standing on its bottom centre; `top` adds its top as a support
// surface with `top_clear` m above it.
AssetRecord BoxRecord(const std::string& category, double w, double d, double h, bool top = false, double top_clear = 0.6);

// Objects. Ids are "<room>/<name>" with room "r".
// An object of `record` and `mesh` (its category the record's).
ProblemObject Make(const std::string& name, AssetRecord record, TriangleMesh mesh);
ProblemObject BoxObject(const std::string& name, double w, double d, double h, bool top = false);
// A table: a 4 cm top and four 5 cm legs; support surface = the top.
ProblemObject TableObject(const std::string& name, double w, double d, double h);
// A bookcase: 2 cm side panels, back and boards; `rows` compartments (cavities 0..rows-1 from the bottom,
// each open at the front, floor = the board below) and the top as support surface `rows`.
ProblemObject BookcaseObject(const std::string& name, double w, double d, double h, int rows);
// A small object (book, cup, vase) as a box.
ProblemObject SmallObject(const std::string& name, double w, double d, double h, const std::string& parent,
                          Relation relation);

// Rooms: free floor, walls along every edge, wall slabs (0.12 m thick, clear height) as building parts.
RoomProblem Rectangle(double w, double d);
RoomProblem LShape();   // 6 x 5 with a 3 x 2.5 corner cut away (reflex vertex at (3, 2.5))
RoomProblem Angled();   // a pentagon with a 45-degree wall
RoomProblem WithFloor(Ring free_floor);  // any CCW floor, with its walls and wall slabs

// A living room in `room`: sofa against a wall, coffee table in front of it, TV stand with a TV facing the
// sofa, bookcase with books inside and a vase on top, armchair facing the coffee table, side table with a
// lamp next to the sofa, plant, rug, painting on a wall, ceiling lamp.
void FurnishLivingRoom(RoomProblem& room);

// The ten room types of the layout (FORMAT.md categories).
enum class RoomType { kLiving, kBedroom, kKitchen, kBathroom, kDining, kChildren, kOffice, kMeeting, kBalcony, kUtility };
inline constexpr RoomType kRoomTypes[] = {RoomType::kLiving,   RoomType::kBedroom, RoomType::kKitchen, RoomType::kBathroom,
                                          RoomType::kDining,   RoomType::kChildren, RoomType::kOffice, RoomType::kMeeting,
                                          RoomType::kBalcony,  RoomType::kUtility};
const char* RoomTypeName(RoomType type);  // "living-room", ...
enum class RoomShape { kRectangle, kL, kAngled };
const char* RoomShapeName(RoomShape shape);  // "rectangle", "L", "angled"

// A room of that type and shape furnished as PRIORS.md describes (anchors against walls, relations,
// small objects on surfaces and in cavities), with a door (sweep keep-out, wall opening) and a window
// (opening, window zone); usual sizes for the type, an L or an angled corner cut from it. `scale` >= 1
// grows the room's sides and repeats the furniture groups (for the object-count benchmark). The seed
// varies counts and sizes a little.
RoomProblem SyntheticRoom(RoomType type, RoomShape shape, uint64_t seed, double scale = 1.0);

}  // namespace villa::solver::fixtures
