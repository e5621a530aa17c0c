#pragma once
// Procedural assets: furniture, fixtures and small things built from an id alone, with exact support
// surfaces and cavities (what makes containment solvable: books inside a bookcase's compartments, dishes in
// a cabinet, clothes in a wardrobe). Every category of assets/category.cpp names the generator that makes
// it, so a whole room can be furnished with no model library imported.
//
// An id is `proc:<generator>?<key>=<value>&...`: keys sorted, numbers with at most 3 decimals, every
// parameter written out, so the id is canonical and the asset (record and mesh, byte for byte) is
// reproducible from it alone. Example: `proc:bookcase?cols=2&d=0.34&h=1.8&rows=5&seed=3&style=modern&w=0.9`.
//
// Frames as SCENE.md: metres, z up, origin at the bottom centre of the asset's box, front = -y (a chair's
// seat opens to -y, a bookcase's compartments open to -y, a bed's foot is at -y). The record's size is the
// mesh's exact bounding box, which is the requested w x d x h. Every piece of a mesh is a closed solid with
// outward normals; pieces of one object may touch or overlap (check them one at a time: the pieces of a part
// share no vertex index). Coordinates are multiples of 0.1 mm, so the record's 4-decimal JSON is exact.
// Every function here is safe to call from several threads at once (no shared mutable state).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "assets/asset.h"
#include "assets/asset_mesh.h"
#include "assets/retrieval.h"
#include "util/result.h"

namespace villa {

// One parameter of a generator.
struct ProceduralParam {
  enum class Kind { kReal, kInteger, kChoice };
  std::string name;  // the id's key: "w", "rows", "style"
  Kind kind = Kind::kReal;
  std::string meaning;  // what it sets, with its unit
  double min = 0.0;     // kReal / kInteger: inclusive range (m for sizes, a count otherwise)
  double max = 0.0;
  double default_value = 0.0;
  std::vector<std::string> choices;  // kChoice: the allowed words
  std::string default_choice;
  // Left out of an id: derived from the category's usual size (w, d, h: the middle of its range) or from
  // the size, style and seed (rows, cols, ...). The canonical id then records the value used.
  bool automatic = false;
};

struct ProceduralGenerator {
  std::string name;                     // "bookcase"
  std::string description;              // one line
  std::vector<std::string> categories;  // categories it makes (assets/category.cpp names); the first is the default
  std::vector<ProceduralParam> params;  // sorted by name, as the id writes them
};

// Every generator, sorted by name.
const std::vector<ProceduralGenerator>& ProceduralGenerators();
const ProceduralGenerator* FindProceduralGenerator(std::string_view name);
// "modern", "classic", "rustic", "scandinavian": colours, materials and some shapes (legs, tops).
const std::vector<std::string>& ProceduralStyles();

struct ProceduralAsset {
  AssetRecord record;  // id canonical; source.kind "procedural"; mesh.file "" (rebuilt from the id)
  AssetMesh mesh;      // one part per material
};

// The asset an id describes. Keys may come in any order and may be left out (defaults, see above); the
// record's id is the canonical form. Errors name the id, the bad key or value and the allowed range, e.g.
// `proc:bookcase?rows=12: rows = 12 is out of range [1, 8]`.
Result<ProceduralAsset> MakeProceduralAsset(std::string_view id);

// The pieces of a procedural mesh (part): triangles joined through shared vertex indices, each copied into
// a mesh of its own. Every piece of a procedural asset is a closed solid (CheckSolid), though pieces may
// touch or overlap one another.
std::vector<TriangleMesh> MeshPieces(const TriangleMesh& mesh);

// The canonical id for an object of `category` about `size` (m, w x d x h; each side clamped into the
// category's usual range and rounded to mm), in `style`, varied by `seed`. Errors: unknown category, a
// category no generator makes, unknown style, a size that is not finite.
Result<std::string> ProceduralAssetId(std::string_view category, Vec3 size, std::string_view style, std::uint32_t seed);

// ---- adapters for the library and retrieval (assets/asset_library.h, assets/retrieval.h)

// The mesh of a `proc:` id: AssetLibrary::SetProceduralMeshMaker(MakeProceduralMesh).
Result<AssetMesh> MakeProceduralMesh(std::string_view id);

// The style a phrase asks for ("a rustic oak table" -> "rustic"; "nordic", "scandi" -> scandinavian;
// "traditional", "antique", "victorian" -> classic; "farmhouse", "country", "cottage" -> rustic;
// "contemporary", "minimalist", "industrial" -> modern); `fallback` when it names none.
std::string ProceduralStyleIn(std::string_view phrase, std::string_view fallback = "modern");

// What procedural generators offer a retrieval query (AssetRetriever::SetOffer(ProceduralOffer)): the
// asset of the query's category (or the category its text names) at the wanted size (or the middle of
// the category's range), in the style its text names, the seed from the query's text (the same query gets
// the same asset, different ones vary). Empty when no category is known.
std::vector<AssetRecord> ProceduralOffer(const RetrievalQuery& query);

}  // namespace villa
