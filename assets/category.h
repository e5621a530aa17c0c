#pragma once
// The object vocabulary of the furnishing stage: every category a room's scene graph may hold (PRIORS.md),
// with what the planner, the asset sources and the solver need to know about it before an asset is chosen:
// words that name it, where it stands, its usual size, its affordances and the zone it keeps free.
// One table serves the graph planner (counts, capacity), retrieval (synonyms, size fit) and the procedural
// generators (which generator makes it). Sizes are metres in the asset frame: width (x) x depth (y) x
// height (z), front = -y.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "assets/asset.h"

namespace villa {

struct CategoryInfo {
  std::string_view name;                    // "sofa": lowercase, '-' separated (SCENE.md `category`)
  std::vector<std::string_view> words;      // other names a request or a model library uses ("couch")
  Placement placement = Placement::kFloor;  // where it goes: floor, wall (hung), ceiling, surface (on a parent)
  Vec3 size_min;                            // usual size range, m (w, d, h)
  Vec3 size_max;
  unsigned affordances = kConsumer;         // kProvider when it offers a surface or cavity to others
  bool has_surface = false;                 // V_pro with a top (or seat) surface others stand on
  bool has_cavity = false;                  // V_pro with compartments others go inside
  std::optional<InteractionZoneSpec> zone;  // V_int: the zone kept free (PRIORS.md clearances)
  bool against_wall = false;                // stands with its back to a wall when on the floor
  std::string_view generator;               // procedural generator that makes it ("" when none)
};

// A rug is a decal on the floor (issue 28): this thin, furniture stands on the floor through it (a solid
// rug of 1-2 cm under half a sofa rocks it in a physics engine, and a real rug's pile gives under a leg).
inline constexpr double kRugThickness = 0.002;

// Every category, in a fixed order (the order of the table in category.cpp).
const std::vector<CategoryInfo>& Categories();
// By exact name; nullptr when unknown.
// Issue 31: the most triangles an imported model of `category` keeps (the importer decimates it to this,
// keeping the source's mesh beside it; not for a category others stand on or in), by the category's
// largest size: 8,000 for pieces 1.5 m or more, 4,000 from 0.6 m (chairs, toilets, appliances), 1,500 for
// small things (a teapot, a toilet-roll holder); 4,000 for a category the vocabulary lacks.
int CategoryTriangleBudget(std::string_view category);
const CategoryInfo* FindCategory(std::string_view name);
// The category a free-text noun names ("couch" -> sofa, "bookshelves" -> bookcase, "TV" -> tv): exact
// names first, then words, singular or plural, case-insensitive; nullptr when nothing matches.
const CategoryInfo* CategoryForWord(std::string_view word);

}  // namespace villa
