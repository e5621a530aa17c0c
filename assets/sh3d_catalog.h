#pragma once
// A Sweet Home 3D furniture library (.sh3f): its catalog (PluginFurnitureCatalog.properties) as pieces,
// and how a piece's words map onto our object vocabulary (assets/category.h).
//
// SH3D facts (catalog keys `<key>#<N>`): sizes and elevations in cm; the model is y-up with its front
// towards +z, shown stretched to width x depth x height; `modelRotation` (9 numbers, a 3x3 matrix by rows)
// turns the model before that; `dropOnTopElevation` is where things dropped on the piece land (default:
// its height; negative: nowhere).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "assets/asset.h"
#include "assets/java_properties.h"
#include "util/result.h"

namespace villa {

struct Sh3dPiece {
  int index = 0;              // N in `name#N`
  std::string id;             // "Blend Swap CC-0#couch"
  std::string name;           // "Couch" (the id's key when the catalog gives no name)
  std::string category;       // SH3D's ("Living room")
  std::vector<std::string> tags;
  std::string creator;
  std::string model;          // the OBJ's entry in the archive, no leading '/'
  double width = 0, depth = 0, height = 0;  // cm, > 0
  double elevation = 0;                     // cm above the floor
  std::optional<double> drop_on_top;        // cm; nullopt: not given (SH3D's default is the height)
  std::optional<std::array<double, 9>> model_rotation;  // rows of a 3x3 matrix
  bool door_or_window = false;
  bool staircase = false;     // has a staircaseCutOutShape
};

struct Sh3dCatalog {
  std::string library_id;     // the catalog's own `id`
  std::string license;        // SPDX id, from the catalog's `license` text or the archive's name
  std::vector<Sh3dPiece> pieces;
  // Pieces that could not be read: "<where>: width#12: expected a number of cm > 0, got \"x\"".
  std::vector<std::string> problems;
};

// `archive_name` is the .sh3f file's name ("BlendSwap-CC-0.sh3f"): the licence comes from the catalog's
// `license` text when it names one, else from the archive's name (Debian's copyright file: BlendSwap-CC-0
// is CC0; BlendSwap-CC-BY and Scopia CC-BY 3.0; KatorLegaz and Reallusion CC-BY 3.0 US).
Sh3dCatalog ReadSh3dCatalog(const JavaProperties& properties, const std::string& archive_name, const std::string& where);

// Our words for a piece: the vocabulary category its name names (head noun first: "Clothes rack" is a
// rack, not clothes), else a category of its own ("radiator") so search still finds it; where it goes;
// which room types it suits.
struct Sh3dMapping {
  std::string category;
  bool in_vocabulary = false;   // category is one of Categories()
  Placement placement = Placement::kFloor;
  std::vector<std::string> room_types;  // layout categories; empty = any room
};
Sh3dMapping MapSh3dPiece(const Sh3dPiece& piece);

// "Corner sofa" -> "corner-sofa": lowercase ASCII letters and digits, '-' between words.
std::string CategorySlug(const std::string& text);

}  // namespace villa
