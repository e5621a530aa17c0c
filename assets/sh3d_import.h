#pragma once
// Sweet Home 3D furniture libraries (.sh3f) -> asset records and meshes (SCENE.md "Asset record").
//
// One piece of a catalog becomes one record: its OBJ/MTL model read from the archive, each material a
// mesh part coloured by its Kd (or the mean colour of its texture), converted to the asset frame by
// `to_asset` (cm -> m, modelRotation, (x, y, z) -> (x, -z, y), each axis stretched to the declared size as
// SH3D shows it, bottom centre to the origin), its support surfaces and cavities read off the geometry
// (assets/mesh_affordances.h), its words mapped to our vocabulary (assets/sh3d_catalog.h). Doors, windows
// and staircases are skipped (the building makes those); meshes over the triangle budget are decimated
// or skipped; every skip has its reason in the import report.
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "assets/asset.h"
#include "assets/asset_mesh.h"
#include "assets/mesh_affordances.h"
#include "assets/sh3d_catalog.h"
#include "assets/zip_archive.h"
#include "util/result.h"

namespace villa {

struct Sh3dImportOptions {
  // The paper's complexity filter: a model with more triangles than this is decimated (vertex
  // clustering) down to it, or skipped when `decimate` is false. > 0; the Debian models' median is about
  // 4,300 triangles, the largest about 200,000.
  int max_triangles = 50000;
  bool decimate = true;
  // Issue 31: a model over its category's budget (CategoryTriangleBudget) is decimated to it too, and its
  // source mesh kept beside it (the record's mesh.full), so that a furnished villa stays near 300,000
  // triangles. Off: only max_triangles applies.
  bool category_budgets = true;
  // Worker threads for the models of all archives; 0 = the hardware's count. Output does not depend on it.
  int threads = 0;
  // "sweethome3d-furniture <version>" in every record's source; empty: read from dpkg's status when
  // the archives are the installed package's, else "<catalog id> <catalog version>".
  std::string package;
  AffordanceOptions affordances;

  std::string Check() const;  // empty when usable
};

// One piece's result.
struct Sh3dPieceImport {
  enum class Outcome { kImported, kSkipped, kFailed };
  Outcome outcome = Outcome::kFailed;
  std::string reason;             // why it was skipped or failed; for a decimated model, what was done
  std::optional<AssetRecord> record;
  AssetMesh mesh;                 // asset frame; empty unless imported
  AssetMesh full_mesh;            // the source's mesh when `mesh` is it decimated (record->mesh.full_file); else empty
  int source_triangles = 0;       // triangles in the OBJ (after triangulating its polygons)
  bool decimated = false;
};

// Reads one piece of `catalog` from `archive` (`archive_name` as in SCENE.md's source.library). The
// record's mesh.file is "meshes/<archive stem>/<key>.vmesh" (the caller writes the mesh there).
Sh3dPieceImport ImportSh3dPiece(const ZipArchive& archive, const std::string& archive_name, const Sh3dCatalog& catalog,
                                const Sh3dPiece& piece, const Sh3dImportOptions& options);

struct Sh3dImportSummary {
  std::filesystem::path library;        // the folder written
  int archives = 0;
  int models_read = 0;                  // catalog pieces seen (readable or not)
  int imported = 0;
  int skipped = 0;                      // doors, windows, staircases, over budget, unreadable
  int failed = 0;                       // of the skipped: the model could not be read
  int decimated = 0;
  int watertight = 0;                   // of the imported
  int carried_over = 0;                 // records of other kinds kept from the old library
  std::map<std::string, int> skip_reasons;  // reason kind -> count ("door or window": 35)
  double seconds = 0.0;
  std::string BriefReport() const;      // a few lines for a terminal
};

// Every *.sh3f in `from` (a folder, or one .sh3f file), in name order, into the library at `library`,
// replacing its sh3d records only when the whole import succeeds. `progress(done, total)` is called
// from worker threads as models finish. The error names the archive or folder at fault.
Result<Sh3dImportSummary> ImportSh3dLibraries(const std::filesystem::path& from, const std::filesystem::path& library,
                                              const Sh3dImportOptions& options,
                                              const std::function<void(int done, int total)>& progress = {});

// Debian's folder of the sweethome3d-furniture package.
std::filesystem::path DefaultSh3dFurnitureDir();

}  // namespace villa
