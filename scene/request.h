#pragma once
// What a request text asks of one room's furnishing: the objects it names with their counts ("a TV",
// "two armchairs", "no rug"), what goes in or on what ("bookshelves full of books", "a lamp on the desk"),
// where ("a desk by the window", "the bed far from the door") and relations between the named objects
// ("an armchair facing the sofa"). Object words come from the shared vocabulary (assets/category.h).
//
// A text may speak of several rooms ("a TV in the meeting room and an island in the kitchen"): objects
// are bound to the room named around them (a following "in/for the <room>", else the nearest room named
// before them in the sentence, else the room the previous sentences spoke of). Objects named before any
// room is named are for the room being planned (the planner is given the text meant for its room).
// Hand-written tokeniser, no regular expressions.
#include <string>
#include <string_view>
#include <vector>

#include "assets/category.h"
#include "layout/layout.h"
#include "scene/scene.h"

namespace villa::scene {

struct Wish {
  const CategoryInfo* category = nullptr;
  int count = 1;                 // 0: "no rug", "without a TV" (the priors must not add one either); < 0: "-3
                                 // armchairs", not a count (the planner notes it and adds none)
  bool explicit_count = false;   // a number or article was given; false for a bare plural (2 assumed)
  int container = -1;            // index of the wish it goes on / in ("books" in "bookcase full of books")
  Relation relation = Relation::kOnTop;  // with a container: kOnTop or kInside
  bool fill = false;             // "full of": as many as the container holds
  int seats = 0;                 // a table's: the people it is to seat ("a dining room that can seat eight")
  std::vector<std::string> hints;  // kHint* words
  std::string phrase;            // the words of the request that named it
};

struct WishEdge {
  int source = -1;  // wish indices
  SemanticRelation relation = SemanticRelation::kNear;
  int target = -1;
};

struct RoomRequest {
  std::vector<Wish> wishes;        // in the order the text names them
  std::vector<WishEdge> edges;
  std::vector<std::string> other_rooms;  // "tv (meeting-room)": objects the text gives other rooms
};

// The wishes of `text` for a room of category `room`, the `ordinal`-th of its category in the layout (0:
// the first). A wish bound to one room of several ("a TV in one of the bedrooms", "a desk in a bedroom",
// "one bedroom needs a TV", "the master bedroom") goes to the first of them only; the others note it in
// other_rooms. A second thought ("a desk in the bedroom - actually, the desk in the study", "two sofas, but
// one sofa is plenty") replaces the earlier mentions of the piece. A wish for
// "each" / "every" / "both" / "all" the rooms, or for "the bedroom(s)", goes to every one of them.
// Seats asked of a room or its table ("a dining room that can seat eight people", "seating for ten", "a
// table for six", "an eight-seat table", "a meeting room for twelve") give that room's table (a
// conference table in a meeting room or an office, else a dining table) `seats` and as many chairs, unless
// the text counts the chairs itself.
RoomRequest ParseRoomRequest(std::string_view text, Category room, int ordinal = 0);

}  // namespace villa::scene
