#pragma once
// Drafted descriptions: for each layout a coarse description (floors, footprint shape, the rooms) and a
// fine one (also which rooms are on which floor, the open kitchen and dining room, rooms reached through
// others, balconies with panoramic windows, which side of the house a room is on, furniture requests) in
// varied natural English, in several styles: a first-person request like the paper's example, a terse
// brief, a list-like spec and a conversational one.
//
// Every statement is true of the layout. The drafter returns the statements it made as structured facts
// beside the text, so tests (and a reviewer) can check each one against the geometry.
//
// Vocabulary (what the generator's brief parser reads): story/storey/floor/level; numbers in words or
// digits; living room/lounge, bedroom/master bedroom, kitchen/open-plan kitchen, bathroom, dining room,
// children's room/kids' room, office/study, meeting room, utility room, balcony; floors named "ground
// floor", "upstairs"/"upper floor" (two floors), "second floor"/"middle floor" and "top floor"/"third
// floor" (three floors): never "first floor", which readers take either way.
#include <cstdint>
#include <string>
#include <vector>

#include "layout/layout.h"

namespace villa::annotator {

enum class FactKind {
  kFloors,        // value floors
  kShape,         // text = footprint class ("L", "irregular", ...)
  kCount,         // `value` rooms of `category` in the whole building
  kCountOnLevel,  // `value` rooms of `category` on `level`
  kOpenLink,      // rooms a and b are joined by an open (kitchen open to the dining room)
  kDirectLink,    // rooms a and b are joined by a door or an open
  kEnSuite,       // room b is reached only through room a, by a door (an en-suite bathroom)
  kBalcony,       // room a reaches balcony b through a door; b has a panoramic window
  kSide,          // room a's centroid lies in the outer third of its floor's bounds towards `text`
                  // ("north" = +y, "south" = -y, "east" = +x, "west" = -x)
  kFurniture,     // `text` (an item) requested in room a; a request for the furnishing stage
};

struct Fact {
  FactKind kind = FactKind::kFloors;
  Category category = Category::kRoom;
  int level = -1;
  int value = 0;
  std::string a;     // room names
  std::string b;
  std::string text;  // shape class, side, furniture item
};

enum class DescriptionStyle { kRequest, kBrief, kSpec, kConversational };
inline constexpr int kDescriptionStyleCount = 4;

struct Drafts {
  std::string coarse;
  std::string fine;
  DescriptionStyle coarse_style = DescriptionStyle::kRequest;
  DescriptionStyle fine_style = DescriptionStyle::kRequest;
  std::vector<Fact> coarse_facts;
  std::vector<Fact> fine_facts;
};

// `shape` is the footprint class of the dataset record (ShapeClassName: "rectangle", "L", ..., "angled-wing").
// Deterministic in (layout, shape, seed); different seeds give different wordings and styles.
Drafts DraftDescriptions(const Layout& layout, const std::string& shape, std::uint64_t seed);

// One line for a person: "kCountOnLevel bedroom level 1 = 2".
std::string DescribeFact(const Fact& fact);

}  // namespace villa::annotator
