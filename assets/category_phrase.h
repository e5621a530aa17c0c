#pragma once
// The vocabulary category a short phrase names: a model's name ("Winchester armchair", "Clothes rack"),
// a search ("a big bookcase for the office"), an object in a request. English compounds put the head
// last, so phrases ending at the last word are tried first, longest first: "coffee table" is a
// coffee-table, "toilet brush" is a brush (no category), not a toilet.
#include <string_view>

#include "assets/category.h"

namespace villa {

// The phrase is read up to its first comma, joining word ("with", "and", "on", "for", "in", "of") or
// number ("Sofa 2 seats", "TV 16:9"); trailing capitalised words that name nothing ("Frame Chambord",
// "Convertible sofa BZ") are dropped one by one. The whole phrase, less leading articles, is tried first
// ("chest of drawers", "a stack of books").
// nullptr when no category is named.
const CategoryInfo* CategoryInPhrase(std::string_view phrase);

// The words of a phrase before its first comma, joining word or number ("Plate, glass and cutlery" ->
// "plate"), lowercase and space-separated: a name for something outside the vocabulary.
std::string HeadPhrase(std::string_view phrase);

}  // namespace villa
