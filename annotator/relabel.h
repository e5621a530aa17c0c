#pragma once
// Changing a room's category, the annotator's main edit. A room's name is `category_L/i` (FORMAT.md), so a
// relabel renames it (a fresh index on its level), closes the gap it leaves among the old category's
// indices, and renames the elements that sit on the renamed rooms (`living0_kitchen0`, `kitchen0_window`,
// `wall_living0_kitchen0`) so element names keep saying what they join.
#include <string>
#include <vector>

#include "layout/layout.h"

namespace villa::annotator {

// The short token of a room in element names: "kitchen0" for kitchen_0/0, "bedroom1.2" for bedroom_1/2,
// "living0" for living-room_0/0 (the "-room" suffix dropped, as in the paper's example).
std::string RoomToken(const Room& room);

// Sets room `room`'s category. Returns the renames made, old name -> new name (rooms first, then
// elements), empty when the category is unchanged.
struct Rename {
  std::string from;
  std::string to;
};
std::vector<Rename> RelabelRoom(Layout& layout, int room, Category category);

// Renames the elements that lie on any room in `rooms` after the scheme above; names stay unique
// within their kind. Entrances keep their names. Returns the renames made.
std::vector<Rename> RenameElementsOf(Layout& layout, const std::vector<int>& rooms);

// The scheme name for `element` (of kind element.kind) in `layout`, unique among the other elements of
// its kind: "living0_kitchen0", "wall_living0_kitchen0", "kitchen0_window", "balcony1_pano". Empty when
// the element does not lie on the rooms its kind needs (two for doors, opens, walls; one for windows).
std::string SchemeElementName(const Layout& layout, const Element& element);

// Labels for rooms still marked `room` (unlabelled), from the paper's priors: the largest room of the
// ground floor becomes the living room, a windowed room beside it the kitchen, its neighbour the dining
// room, the smallest windowed room a bathroom; upper floors get bedrooms, a bathroom, a children's room,
// an office. Kitchens and bathrooms are only given to rooms with a window (FORMAT.md rule 9); balconies are
// never drafted. Labelled rooms are left as they are. Returns the number of rooms labelled.
int DraftLabels(Layout& layout);

}  // namespace villa::annotator
