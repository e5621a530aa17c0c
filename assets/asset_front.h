#pragma once
// An asset's front, found by a multimodal model (paper Sec. 3.3: four renders, the MLLM picks the front)
// and written into the library: `villa assets front ID --mllm URL --model NAME`.
//
// The model sees the four views of assets/asset_views.h without overlays (from -y, the recorded front,
// then +x, +y, -x: the camera walking round counter-clockwise seen from above) and answers which picture
// shows the front. When it is picture k+1 (k > 0) the asset is turned by -90 k degrees about z so that
// side faces -y: the mesh, the size (width and depth swap for quarter turns), to_asset, the support
// surfaces and cavities turn with it, front_yaw_offset adds the turn, and front_decided_by says who
// decided it. Procedural assets are refused: their front is -y by construction.
#include <filesystem>
#include <string>

#include "assets/asset.h"
#include "assets/asset_mesh.h"
#include "assets/asset_views.h"
#include "llm/client.h"
#include "llm/json_chat.h"
#include "util/result.h"

namespace villa {

struct FrontPickOptions {
  LlmOptions llm;
  JsonChatOptions chat;      // corrective turns, answer cache
  AssetViewOptions views;    // overlays are turned off for the model
  bool json_schema = true;   // send response_format json_schema (strict)
};

struct FrontPick {
  int view = 0;               // 0..3: the view that shows the front (0: the recorded front is right)
  double confidence = 0.0;    // the model's, [0, 1]
  std::string reason;         // the model's words
  int turn_deg = 0;           // the turn that makes that side the front: -90 x view, in (-180, 180]
  JsonChatResult chat;        // the conversation (requests, cache hits, tokens)
};

// The system prompt and the answer's schema (exposed for tests).
std::string FrontSystemPrompt();
nlohmann::ordered_json FrontResponseFormat();

// Asks the model. Errors: unusable options, views that cannot be drawn, no usable answer.
Result<FrontPick> PickAssetFront(const AssetRecord& record, const AssetMesh& mesh, const FrontPickOptions& options);

struct TurnedAsset {
  AssetRecord record;
  AssetMesh mesh;
};
// The asset turned so the side seen in view `view` (0..3) faces -y; `view` 0 changes nothing.
TurnedAsset TurnAsset(const AssetRecord& record, const AssetMesh& mesh, int view);

// Writes a decision into the library at `dir`: the turned mesh as a new file beside the old one (written
// atomically), then assets.jsonl with the record updated (written atomically; the old mesh file stays, so
// the library is whole at every moment). `decided_by` goes into the record's front_decided_by.
// Returns the updated record. Errors name the library, the id and what is wrong.
Result<AssetRecord> WriteAssetFront(const std::filesystem::path& dir, const std::string& id, int view, const std::string& decided_by);

}  // namespace villa
