#pragma once
// Which room categories a description names, so that an edited description can be checked against the
// layout it describes: after a relabel, a person's text may still promise a bedroom the layout no longer
// has. The vocabulary is the drafter's and the brief parser's ("lounge" is a living room, "kids' room" a
// children's room, "study" an office, "WC" a bathroom); "no balcony" and "without an office" name nothing.
#include <string_view>
#include <vector>

#include "layout/layout.h"

namespace villa::annotator {

// The categories `text` names, each once, in the order of Category.
std::vector<Category> CategoriesNamed(std::string_view text);

// The categories `text` names of which `layout` has no room.
std::vector<Category> CategoriesNamedButMissing(std::string_view text, const Layout& layout);

// "bedroom", "children's room": how a person calls a category in a message.
std::string_view CategoryWords(Category category);

}  // namespace villa::annotator
