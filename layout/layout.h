#pragma once
// The building model every part of villa speaks: the layout JSON of shared/design/FORMAT.md, as types.
// Units are metres; x, y in the plan; levels stack upward kLevelHeight apart (level 0 = ground floor).
// Polygons are counter-clockwise rings without a repeated closing point.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace villa {

inline constexpr double kLevelHeight = 2.8;    // m between floors

// The tolerance policy (docs/RULES.md, "Tolerances"). Every plan-geometry question is answered with one
// of these two, so the validator, the renderer, the annotator, the building and the furnishing agree:
//  - kTolerance: two lengths or distances within it are equal, an area (m2) within it is zero, a point
//    within it of a line lies on the line. Room geometry: every rule of FORMAT.md about rooms, shared
//    boundaries, footprints.
//  - kOnWallTolerance: how far a 1D element (door, open, window, entrance, interior wall) may be from a
//    room's boundary and still lie on it, and how short a stretch of a wall it may leave uncovered: rule 3,
//    rule 4's cover, which rooms hold an element (RoomsAlongSegment, RoomsHolding), which elements the
//    floor plan draws red, which windows the annotator counts, which doors the furnishing sees on a room's
//    edge. The format writes numbers with two decimals, so a point on a wall at an arbitrary angle is
//    written up to 0.005 m off in x and y (0.0071 m off the wall): 0.01 m accepts every such point and
//    nothing a person would call "off the wall".
// Consumers that turn a plan into something else keep their own, documented snaps on top (the building
// merges points within 1e-4 m; the layout text writes coordinates with two decimals).
inline constexpr double kTolerance = 1e-6;        // m
inline constexpr double kOnWallTolerance = 0.01;  // m

// The building extent (docs/RULES.md, "Extent"): what the reader accepts before any geometry work, so a
// hostile file cannot make a picture of 1e12 m or a grid of 1e-320 m cells. Far beyond any real villa.
inline constexpr double kMaxCoordinate = 10000.0;  // m, |x| and |y| of every point
inline constexpr double kMinRoomSize = 0.01;       // m, a room's bounding box is at least this wide and deep
inline constexpr int kMaxRooms = 1000;             // rooms in one layout (a valid one has at most 18)
inline constexpr int kMaxElements = 100000;        // 1D elements of all kinds together in one layout
inline constexpr int kMaxRingCorners = 1000;       // corners of one room polygon
inline constexpr double kStairRoomSize = 4.0;  // m, the utility room holding the staircase is 4 x 4
inline constexpr int kMaxFloors = 3;
inline constexpr int kMaxRoomsPerFloor = 6;

struct Point {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const Point&, const Point&) = default;
};

// A simple polygon: counter-clockwise, first vertex not repeated at the end.
using Ring = std::vector<Point>;

// A 1D element's straight segment.
struct Segment {
  Point a;
  Point b;
  friend bool operator==(const Segment&, const Segment&) = default;
};

// The ten functional areas, plus kRoom for an unlabelled room straight out of the partitioner.
enum class Category {
  kRoom,
  kLivingRoom,
  kBedroom,
  kKitchen,
  kBathroom,
  kDiningRoom,
  kChildrenRoom,
  kOffice,
  kMeetingRoom,
  kUtilityRoom,  // holds the staircase
  kBalcony,
};
inline constexpr int kCategoryCount = 11;

// "living-room", "utility-room", "room", ...
std::string_view CategoryName(Category category);
// "living", "children", "utility": the category in element names ("living0_kitchen0"), the format's name
// without "-room".
std::string_view CategoryToken(Category category);
// "Living room", "Children's room", "Utility room", "Room": the category as a person reads it.
std::string_view CategoryDisplayName(Category category);
// "Living", "Bed", "Child", "Bath": a short form for labels in small rooms and narrow terminal cells.
std::string_view CategoryShortName(Category category);
// Accepts every CategoryName and the alias "staircase-room" (= utility-room).
std::optional<Category> ParseCategory(std::string_view name);
// The ten labelled categories in a fixed order (without kRoom).
const std::vector<Category>& LabelledCategories();
// Rooms people live and work in: living, bedroom, children's, dining, office, meeting room and kitchen
// (not bathrooms, balconies, utility rooms). None of them should narrow under kHabitableWidth anywhere.
bool IsHabitable(Category category);
inline constexpr double kHabitableWidth = 1.8;  // m

// Room names are "category_L/i": category, level L (0 = ground), index i of that category on that level.
struct RoomName {
  Category category = Category::kRoom;
  int level = 0;
  int index = 0;
};
std::optional<RoomName> ParseRoomName(std::string_view name);
std::string FormatRoomName(const RoomName& name);

struct Room {
  Category category = Category::kRoom;
  int level = 0;
  int index = 0;
  Ring polygon;
  std::string name() const { return FormatRoomName({category, level, index}); }
};

enum class ElementKind { kEntrance, kDoor, kOpen, kWindow, kInterior };
// The JSON key of each kind: "entrance", "doors", "opens", "windows", "interiors".
std::string_view ElementKindKey(ElementKind kind);

inline constexpr int kAllLevels = -1;  // a 1D element without "level" belongs to every floor

struct Element {
  std::string name;     // free text, e.g. "living0_kitchen0"
  ElementKind kind = ElementKind::kDoor;
  Segment shape;
  int level = 0;        // or kAllLevels
  bool panoramic = false;  // windows only
  bool OnLevel(int l) const { return level == kAllLevels || level == l; }
};

// A whole building. Order is kept as read (JSON object order), so files round-trip unchanged.
struct Layout {
  std::vector<Room> rooms;
  std::vector<Element> entrances;
  std::vector<Element> doors;
  std::vector<Element> opens;
  std::vector<Element> windows;
  std::vector<Element> interiors;

  std::vector<Element>& elements(ElementKind kind);
  const std::vector<Element>& elements(ElementKind kind) const;

  // 1 + the highest room level; 0 for a layout without rooms.
  int LevelCount() const;
  // Indices into `rooms` of the rooms on `level`, in order.
  std::vector<int> RoomsOnLevel(int level) const;
  // Index into `rooms` of the room with this name, or -1.
  int FindRoom(std::string_view name) const;
};

inline constexpr ElementKind kAllElementKinds[] = {ElementKind::kEntrance, ElementKind::kDoor, ElementKind::kOpen,
                                                   ElementKind::kWindow, ElementKind::kInterior};

// Empty when every corner of `ring` lies within the building extent and its bounding box is at least
// kMinRoomSize wide and deep; otherwise what is wrong, with the value: "x = 1e+12 is outside the building
// extent (|x| and |y| at most 10000 m)", "zero width (every corner at x = 3)", "0.004 m deep (y from 2 to
// 2.004); a room is at least 0.01 m wide and deep". The reader refuses such a room; the validator reports
// it under rule 1 for layouts made in code.
std::string RoomExtentProblem(const Ring& ring);
// The same for a 1D element's two points (the extent only: a short element is rule 1's "zero length").
std::string SegmentExtentProblem(const Segment& segment);
// The extent alone, for one point: "y = -1e+12 is outside the building extent (...)", or empty.
std::string PointExtentProblem(const Point& point);

// Plain polygon measures used everywhere (shoelace; positive for counter-clockwise).
double SignedArea(const Ring& ring);
double Area(const Ring& ring);
double Length(const Segment& segment);

}  // namespace villa
