#pragma once
// A second, independent reading of a request (issue 32: honesty by construction). The brief parser
// (brief.h) is a grammar with floors, scopes and synonyms; this is a plain counter written apart from it
// that looks at every room noun of the text and at the number written in front of it, so that a slip of
// the parser ("four bedrooms upstairs, each with an en-suite bathroom" read as one bathroom) does not pass
// as a met request. The plan is never "met" where the layout has fewer rooms of a kind than the recount
// reads; the report names the phrase that may have been misread.
//
// What it reads, and nothing more (it under-counts rather than over-counts: a disagreement turns a
// correct layout into a "partial" one):
//   - a room noun (bedroom, guest room, kids' room, en-suite, WC, lounge, study, terrace, ...) with a number
//     before it within a few words ("two large bedrooms", "3 baths", "a kitchen", "a couple of offices");
//     a bare singular in a list ("kitchen, lounge, 2 bedrooms") is one; a bare plural is not counted;
//   - "a second / third / another X": at least 2 / 3 / one more than read so far;
//   - "X on each floor / per floor / on every level / on both floors": times the layout's floors;
//     "X per bedroom / for each bedroom": times the bedrooms read; "N bedrooms, each with an en-suite":
//     the en-suites are N;
//   - "another one": one more of the kind just counted; "both bathrooms": two;
//   - nouns after "no", "without", "not", "instead of" are left out, and so are references ("the kitchen",
//     "one of the bedrooms", "its balcony", "each bedroom", "including a master bedroom").
// Within a sentence the rooms of a kind add up (a list names distinct rooms: "a lounge, a separate sitting
// room"); across sentences a kind counts as the most one sentence reads (a request names a room again when
// it says where it goes).
#include <string>
#include <string_view>
#include <vector>

#include "layout/layout.h"

namespace villa {

struct RoomRecount {
  Category category = Category::kRoom;
  int count = 0;       // at least this many rooms of the kind
  std::string phrase;  // the words it was read from ("four bedrooms", "a bathroom on each floor")
  // The kind is named once in the whole text, with a number of two or more ("four bedrooms") and nothing
  // that spreads it: exactly this many (a layout with more has misread it too).
  bool exact = false;
};

// The counts per room kind (one entry a kind, the largest reading), for a layout of `floors` floors.
std::vector<RoomRecount> RecountRooms(std::string_view text, int floors);

struct RecountDisagreement {
  Category category = Category::kRoom;
  int asked = 0;  // the recount's reading
  int has = 0;    // rooms of the kind in the layout
  std::string phrase;
  bool exact = false;  // the layout has more than the text's exact count
  // "the text may ask for 4 bathrooms ("each with an en-suite bathroom"); the layout has 1"
  std::string Message() const;
};

// The kinds of which the layout has fewer rooms than the recount of `text` reads, or more than a count the
// text names exactly.
std::vector<RecountDisagreement> CheckRecount(std::string_view text, const Layout& layout);

}  // namespace villa
