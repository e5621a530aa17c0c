#pragma once
// The asset library on disk: a folder holding `assets.jsonl` (one asset record a line, SCENE.md),
// `meshes/**/*.vmesh` (each record's mesh, in the asset frame) and `import-report.json` (what the last
// import read, kept and skipped, and why). Where it is: `--library DIR`, else $VILLA_ASSETS, else
// $XDG_DATA_HOME/villa/assets, else ~/.local/share/villa/assets.
//
// Writing is all or nothing: an import builds the new library in a staging folder beside the old one and
// swaps the two folders in one step (renameat2 RENAME_EXCHANGE), so a failed or interrupted import leaves
// the old library as it was. Records of other kinds than the importer's (and their meshes), and any file
// the importer does not own, are carried over into the new library.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "assets/asset.h"
#include "assets/asset_mesh.h"
#include "util/result.h"

namespace villa {

inline constexpr std::string_view kLibraryRecordsFile = "assets.jsonl";
inline constexpr std::string_view kImportReportFile = "import-report.json";
inline constexpr std::string_view kLibraryMeshFolder = "meshes";

// $VILLA_ASSETS, else $XDG_DATA_HOME/villa/assets, else $HOME/.local/share/villa/assets (relative values
// of the XDG variable are ignored, as the XDG spec says).
std::filesystem::path DefaultLibraryDir();

// A new library being written beside `dir`; it replaces `dir` on Commit(), and is removed when dropped
// uncommitted. WriteMesh may be called from several threads at once.
class LibraryStaging {
 public:
  // Refuses a `dir` that exists, holds files and has no assets.jsonl: that is not a library to replace.
  static Result<LibraryStaging> Begin(const std::filesystem::path& dir);
  LibraryStaging(LibraryStaging&&) noexcept;
  LibraryStaging& operator=(LibraryStaging&&) = delete;
  ~LibraryStaging();

  const std::filesystem::path& dir() const { return dir_; }
  const std::filesystem::path& staging() const { return staging_; }
  // `relative` under the library folder ("meshes/BlendSwap-CC-0/couch.vmesh").
  Status WriteMesh(const std::string& relative, const AssetMesh& mesh) const;
  // Writes the records and the report, carries over what the old library holds that is not of
  // `replaced_kind` (records, their meshes, other files), then swaps the folders.
  Status Commit(const std::vector<AssetRecord>& records, const std::string& report, const std::string& replaced_kind);

 private:
  LibraryStaging(std::filesystem::path dir, std::filesystem::path staging) : dir_(std::move(dir)), staging_(std::move(staging)) {}
  std::filesystem::path dir_;
  std::filesystem::path staging_;
  bool done_ = false;
};

// Makes the mesh of a procedural asset from its id ("proc:bookcase?..."); see assets/procedural*.h.
using ProceduralMeshMaker = std::function<Result<AssetMesh>(std::string_view id)>;

// A library read from disk. Records are read at once; meshes on first use, then kept (shared, immutable).
// Const members are safe from several threads (rooms are furnished in parallel).
class AssetLibrary {
 public:
  // The error names the folder: "DIR: no asset library here (no assets.jsonl; run `villa assets import`)".
  static Result<AssetLibrary> Open(const std::filesystem::path& dir);
  // A library held in memory (tests, procedural-only runs); mesh files are looked up under `dir`.
  static AssetLibrary FromRecords(std::vector<AssetRecord> records, std::filesystem::path dir = {});

  const std::filesystem::path& dir() const { return dir_; }
  const std::vector<AssetRecord>& records() const { return *records_; }
  const AssetRecord* Find(std::string_view id) const;

  // How meshes of `proc:` ids are made; without one, asking for such a mesh is an error.
  void SetProceduralMeshMaker(ProceduralMeshMaker maker) { procedural_ = std::move(maker); }
  // The asset's mesh in the asset frame. Errors name the id and the file.
  Result<std::shared_ptr<const AssetMesh>> Mesh(std::string_view id) const;

 private:
  struct MeshCache;
  std::filesystem::path dir_;
  std::shared_ptr<const std::vector<AssetRecord>> records_;
  std::shared_ptr<MeshCache> cache_;
  ProceduralMeshMaker procedural_;
};

}  // namespace villa
