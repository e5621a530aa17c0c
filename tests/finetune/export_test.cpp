// villa finetune export: what is left out and counted, each format's lines and dataset_info entries,
// the trainer configs, leak-free deterministic splits, and the output folder rules.
#include <catch2/catch.hpp>

#include <set>

#include "finetune/export.h"
#include "finetune/geometry_key.h"
#include "finetune/layout_schema.h"
#include "finetune/sample_format.h"
#include "finetune/system_prompt.h"
#include "finetune_test_util.h"
#include "layout/layout_io.h"
#include "layout/validate.h"

using namespace villa;
using namespace villa::testing;

namespace {

ExportSummary Export(const fs::path& input, const fs::path& out, ExportOptions options = {}) {
  auto summary = ExportDataset(input, out, options);
  INFO((summary.ok() ? std::string() : summary.error()));
  REQUIRE(summary.ok());
  return *summary;
}

fs::path WriteMany(const ScratchDir& dir, int count, const std::string& status = "auto") {
  fs::path input = dir / "annotated.jsonl";
  Spit(input, ManyRecords(count, status));
  return input;
}

// id -> split name, from sources.jsonl.
std::map<std::string, std::set<std::string>> SplitsById(const fs::path& out) {
  std::map<std::string, std::set<std::string>> splits;
  for (const auto& line : Lines(out / "sources.jsonl")) {
    Json j = Json::parse(line);
    splits[j["id"]].insert(j["split"].get<std::string>());
  }
  return splits;
}

}  // namespace

TEST_CASE("Rejected, pending, invalid and duplicate records are left out and counted", "[finetune][export]") {
  ScratchDir dir("counts");
  ExportSummary s = Export(FixtureDir() / "annotated.jsonl", dir / "out");
  CHECK(s.records == 9);
  CHECK(s.bad_lines == 1);
  CHECK(s.rejected == 1);
  CHECK(s.rejected_reasons.at("rooms too small") == 1);
  CHECK(Slurp(dir / "out" / "README.md").find("- rooms too small (1)") != std::string::npos);
  CHECK(s.pending == 1);
  CHECK(s.unreadable_layout == 1);
  CHECK(s.invalid_layout == 1);
  CHECK(s.invalid_by_rule.at(9) == 1);  // the kitchen without a window
  CHECK(s.no_description == 1);
  CHECK(s.duplicate_geometry == 1);     // villa-003: villa-002 relabelled
  CHECK(s.layouts == 3);
  CHECK(s.samples == 3);
  CHECK(s.layouts_by_floors.at(1) == 2);
  CHECK(s.layouts_by_floors.at(2) == 1);
  CHECK(s.layouts_by_status.at("verified") == 2);
  CHECK(s.layouts_by_shape.at("L") == 2);
  CHECK(s.layouts_by_shape.at("rectangle") == 1);
  const std::string report = s.BriefReport();
  CHECK(report.find("annotated.jsonl:7: house-006: rule 9: kitchen_0/0 has no window") != std::string::npos);

  // --include verified keeps only villa-002 and house-009; --include auto only house-001.
  ExportOptions verified;
  verified.include = IncludeStatus::kVerified;
  ExportSummary v = Export(FixtureDir() / "annotated.jsonl", dir / "verified", verified);
  CHECK(v.layouts == 2);
  CHECK(v.excluded_status == 5);  // the five auto records: house-001, villa-003, house-006, villa-007, house-008
}

TEST_CASE("Every format's lines carry the keys their trainers read, with valid answers", "[finetune][export]") {
  ScratchDir dir("formats");
  const fs::path input = WriteMany(dir, 40);
  for (ExportFormat format : {ExportFormat::kMessages, ExportFormat::kShareGpt, ExportFormat::kAlpaca}) {
    const std::string name(ExportFormatName(format));
    DYNAMIC_SECTION(name) {
      ExportOptions options;
      options.format = format;
      const fs::path out = dir / name;
      ExportSummary s = Export(input, out, options);
      REQUIRE(s.layouts == 40);
      const Json info = Json::parse(Slurp(out / "dataset_info.json"));
      std::size_t lines_seen = 0;
      for (int split = 0; split < kSplitCount; ++split) {
        const std::string file = std::string(kSplitNames[split]) + ".jsonl";
        const std::string entry = std::string("villa_") + kSplitNames[split];
        REQUIRE(info.contains(entry));
        CHECK(info[entry]["file_name"] == file);
        for (const auto& text : Lines(out / file)) {
          ++lines_seen;
          Json line = Json::parse(text);
          if (format == ExportFormat::kMessages) {
            REQUIRE(line.size() == 1);
            REQUIRE(line["messages"].size() == 3);
            CHECK(line["messages"][0]["role"] == "system");
            CHECK(line["messages"][1]["role"] == "user");
            CHECK(line["messages"][2]["role"] == "assistant");
            for (const auto& m : line["messages"]) CHECK(m.size() == 2);
          } else if (format == ExportFormat::kShareGpt) {
            REQUIRE(line["conversations"].size() == 2);
            CHECK(line["conversations"][0]["from"] == "human");
            CHECK(line["conversations"][1]["from"] == "gpt");
            CHECK(line["system"].is_string());
          } else {
            CHECK(line["instruction"].is_string());
            CHECK(line["input"] == "");
            CHECK(line["output"].is_string());
            CHECK(line["system"].is_string());
          }
          ExportFormat found;
          auto texts = ParseSampleLine(line, &found);
          REQUIRE(texts.ok());
          CHECK(found == format);
          CHECK(texts->system == SystemPrompt());
          CHECK(texts->user.rfind("description of layout-", texts->user.size()) != std::string::npos);
          // The answer round-trips through the reader and passes every rule and the schema.
          auto layout = ParseLayoutText(texts->assistant, file);
          REQUIRE(layout.ok());
          CHECK(LayoutToString(*layout, -1) == texts->assistant);
          CHECK(ValidateLayout(*layout).valid());
          CHECK(MatchLayoutJsonSchema(Json::parse(texts->assistant)).ok());
        }
      }
      CHECK(lines_seen == s.samples);
      // dataset_info.json: exactly the LLaMA-Factory keys for this format.
      const Json& e = info["villa_train"];
      if (format == ExportFormat::kMessages) {
        CHECK(e["formatting"] == "sharegpt");
        CHECK(e["columns"] == Json{{"messages", "messages"}});
        CHECK(e["tags"] == Json{{"role_tag", "role"}, {"content_tag", "content"}, {"user_tag", "user"},
                                {"assistant_tag", "assistant"}, {"system_tag", "system"}});
        CHECK(fs::exists(out / "axolotl.yaml"));
      } else if (format == ExportFormat::kShareGpt) {
        CHECK(e["formatting"] == "sharegpt");
        CHECK(e["columns"] == Json{{"messages", "conversations"}, {"system", "system"}});
        CHECK(e["tags"]["role_tag"] == "from");
        CHECK(e["tags"]["content_tag"] == "value");
        CHECK(e["tags"]["user_tag"] == "human");
        CHECK(e["tags"]["assistant_tag"] == "gpt");
        CHECK_FALSE(fs::exists(out / "axolotl.yaml"));
      } else {
        CHECK(e["formatting"] == "alpaca");
        CHECK(e["columns"] == Json{{"prompt", "instruction"}, {"query", "input"}, {"response", "output"}, {"system", "system"}});
        CHECK_FALSE(fs::exists(out / "axolotl.yaml"));
      }
    }
  }
}

TEST_CASE("The trainer configs carry the keys their trainers read", "[finetune][export]") {
  ScratchDir dir("configs");
  const fs::path input = WriteMany(dir, 40);
  ExportOptions options;
  options.base_model = "Qwen/Qwen3-8B";
  ExportSummary s = Export(input, dir / "out", options);
  const Json info = Json::parse(Slurp(dir / "out" / "dataset_info.json"));

  auto lf = YamlKeys(Slurp(dir / "out" / "llamafactory_lora_sft.yaml"));
  CHECK(lf["model_name_or_path"] == "Qwen/Qwen3-8B");
  CHECK(lf["stage"] == "sft");
  CHECK(lf["do_train"] == "true");
  CHECK(lf["finetuning_type"] == "lora");
  CHECK(lf["lora_target"] == "all");
  CHECK(lf["template"] == "qwen3_5_nothink");
  CHECK(lf["num_train_epochs"] == "15.0");
  CHECK(lf["learning_rate"] == "1.0e-4");
  CHECK(lf["per_device_train_batch_size"] == "4");
  CHECK(lf["optim"] == "adamw_torch");
  CHECK(lf["dataset_dir"] == ".");
  CHECK(info.contains(lf["dataset"]));
  CHECK(info.contains(lf["eval_dataset"]));
  CHECK(!lf["output_dir"].empty());
  CHECK(std::stoi(lf["cutoff_len"]) >= static_cast<int>(s.sample_tokens.max));
  CHECK(std::stoi(lf["cutoff_len"]) == s.cutoff_len);

  auto ax = YamlKeys(Slurp(dir / "out" / "axolotl.yaml"));
  CHECK(ax["base_model"] == "Qwen/Qwen3-8B");
  CHECK(ax["datasets.path"] == "train.jsonl");
  CHECK(ax["datasets.type"] == "chat_template");
  CHECK(ax["datasets.field_messages"] == "messages");
  CHECK(ax["datasets.message_property_mappings.role"] == "role");
  CHECK(ax["datasets.message_property_mappings.content"] == "content");
  CHECK(ax["datasets.roles_to_train"] == "[\"assistant\"]");
  CHECK(ax["test_datasets.path"] == "val.jsonl");
  CHECK(ax["test_datasets.roles_to_train"] == "[\"assistant\"]");
  CHECK(ax["adapter"] == "lora");
  CHECK(ax["num_epochs"] == "15");
  CHECK(ax["micro_batch_size"] == "4");
  CHECK(ax["optimizer"] == "adamw_torch");
  CHECK(ax["learning_rate"] == "1.0e-4");
  CHECK(std::stoi(ax["sequence_len"]) == s.cutoff_len);
  for (const auto& file : {ax["datasets.path"], ax["test_datasets.path"]}) CHECK(fs::exists(dir / "out" / file));

  // The data card names the counts and the ways to train and serve.
  const std::string card = Slurp(dir / "out" / "README.md");
  CHECK(card.find("No person verified this dataset") != std::string::npos);
  CHECK(card.find("| train | `train.jsonl` | " + std::to_string(s.layouts_per_split[0]) + " | ") != std::string::npos);
  CHECK(card.find("Floors (1 : 2 storeys): 20 : 20, ratio 5 : 5.") != std::string::npos);
  // The fixtures are an L and a rectangle: no slanted edge outside or between rooms.
  CHECK(card.find("A slanted outside edge (neither horizontal nor vertical) in 0 layouts (0.0%), a slanted wall, door or "
                  "open between two rooms in 0 (0.0%).") != std::string::npos);
  for (const char* needle : {"llamafactory-cli train llamafactory_lora_sft.yaml", "axolotl train axolotl.yaml", "SFTTrainer",
                             "--enable-lora --lora-modules villa-layout=", "\"model\": \"villa-layout\"", "--backend llm",
                             "coarse", "fine", "~tokens"}) {
    INFO(needle);
    CHECK(card.find(needle) != std::string::npos);
  }
}

TEST_CASE("Splits are leak-free, exact and deterministic", "[finetune][export][leak]") {
  ScratchDir dir("splits");
  // 60 layouts, then the same 60 geometries again under other ids: the copies must vanish.
  std::string jsonl = ManyRecords(60);
  std::string copies = ManyRecords(60);
  for (std::size_t at = copies.find("layout-"); at != std::string::npos; at = copies.find("layout-", at + 6)) copies.replace(at, 7, "copy---");
  const fs::path input = dir / "annotated.jsonl";
  Spit(input, jsonl + copies);

  ExportOptions options;
  options.split = {0.6, 0.2, 0.2};
  options.descriptions = DescriptionChoice::kBoth;
  ExportSummary s = Export(input, dir / "a", options);
  CHECK(s.duplicate_geometry == 60);
  CHECK(s.layouts == 60);
  CHECK(s.layouts_per_split == std::array<std::size_t, 3>{36, 12, 12});
  CHECK(s.samples_per_split == std::array<std::size_t, 3>{72, 24, 24});
  CHECK(s.coarse_samples == 60);
  CHECK(s.fine_samples == 60);

  // Both descriptions of a layout share its split, and no geometry is in two splits.
  for (const auto& [id, splits] : SplitsById(dir / "a")) {
    INFO(id);
    CHECK(splits.size() == 1);
    CHECK(id.rfind("layout-", 0) == 0);
  }
  std::map<std::string, std::set<int>> splits_of_geometry;
  for (int split = 0; split < kSplitCount; ++split) {
    for (const auto& line : Lines(dir / "a" / (std::string(kSplitNames[split]) + ".jsonl"))) {
      auto texts = ParseSampleLine(Json::parse(line));
      REQUIRE(texts.ok());
      auto layout = ParseLayoutText(texts->assistant, "answer");
      REQUIRE(layout.ok());
      splits_of_geometry[GeometryKey(*layout)].insert(split);
    }
  }
  CHECK(splits_of_geometry.size() == 60);
  for (const auto& [geometry, splits] : splits_of_geometry) CHECK(splits.size() == 1);

  // Same input and options: byte-identical files. Another seed: another split.
  Export(input, dir / "b", options);
  for (const char* file : {"train.jsonl", "val.jsonl", "test.jsonl", "dataset_info.json", "llamafactory_lora_sft.yaml",
                           "axolotl.yaml", "sources.jsonl", "README.md"}) {
    INFO(file);
    CHECK(Slurp(dir / "a" / file) == Slurp(dir / "b" / file));
  }
  options.seed = 7;
  Export(input, dir / "c", options);
  CHECK(Slurp(dir / "a" / "test.jsonl") != Slurp(dir / "c" / "test.jsonl"));
}

TEST_CASE("One description per layout, picked from seed and id", "[finetune][export]") {
  ScratchDir dir("one");
  const fs::path input = WriteMany(dir, 80);
  ExportSummary s = Export(input, dir / "a");
  CHECK(s.samples == 80);
  CHECK(s.coarse_samples + s.fine_samples == 80);
  CHECK(s.coarse_samples > 20);  // both kinds present, roughly half each
  CHECK(s.fine_samples > 20);
  ExportOptions other;
  other.seed = 3;
  Export(input, dir / "b", other);
  CHECK(Slurp(dir / "a" / "sources.jsonl") != Slurp(dir / "b" / "sources.jsonl"));
}

TEST_CASE("The output folder: never overwritten without --force, stale files removed with it", "[finetune][export]") {
  ScratchDir dir("folder");
  const fs::path input = WriteMany(dir, 40);
  const fs::path out = dir / "out";
  fs::create_directories(out);
  Spit(out / "notes.txt", "mine");
  auto refused = ExportDataset(input, out, {});
  REQUIRE_FALSE(refused.ok());
  CHECK(refused.error().find("--force") != std::string::npos);
  CHECK(Slurp(out / "notes.txt") == "mine");
  CHECK_FALSE(fs::exists(out / "train.jsonl"));

  ExportOptions force;
  force.force = true;
  Export(input, out, force);
  CHECK(fs::exists(out / "test.jsonl"));
  force.split = {1.0, 0.0, 0.0};
  force.format = ExportFormat::kAlpaca;
  ExportSummary s = Export(input, out, force);
  CHECK(s.samples_per_split[0] == 40);
  CHECK_FALSE(fs::exists(out / "test.jsonl"));   // stale split of the earlier export
  CHECK_FALSE(fs::exists(out / "val.jsonl"));
  CHECK_FALSE(fs::exists(out / "axolotl.yaml")); // messages only
  CHECK(Slurp(out / "notes.txt") == "mine");     // not ours: kept
  auto lf = YamlKeys(Slurp(out / "llamafactory_lora_sft.yaml"));
  CHECK(lf.count("eval_dataset") == 0);

  ExportOptions bad;
  bad.split = {0.5, 0.2, 0.2};
  auto invalid = ExportDataset(input, dir / "bad", bad);
  REQUIRE_FALSE(invalid.ok());
  CHECK(invalid.error().find("sum to 1") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "bad"));
}

TEST_CASE("The project's layout fixtures: valid ones exported as they are, broken ones counted", "[finetune][export]") {
  ScratchDir dir("fixtures");
  std::vector<fs::path> files;
  for (const auto& folder : {fs::path(VILLA_FIXTURE_DIR) / "layouts", fs::path(VILLA_SOURCE_DIR) / "examples"}) {
    for (const auto& item : fs::directory_iterator(folder))
      if (item.path().extension() == ".json") files.push_back(item.path());
  }
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 10);
  std::string jsonl;
  std::size_t valid = 0, invalid = 0;
  std::map<std::string, std::string> answers;  // id -> the canonical text of the layout
  std::map<int, std::size_t> first_rules;
  for (const auto& file : files) {
    auto layout = LoadLayout(file);
    REQUIRE(layout.ok());
    const std::string id = file.parent_path().filename().string() + "/" + file.stem().string();
    ValidationReport report = ValidateLayout(*layout);
    if (report.valid()) {
      ++valid;
      answers[id] = LayoutToString(*layout, -1);
    } else {
      ++invalid;
      ++first_rules[report.violations.front().rule];
    }
    jsonl += Record(id, "auto", *layout, "a building", "").dump() + "\n";
  }
  REQUIRE(valid >= 3);
  REQUIRE(invalid >= 10);
  Spit(dir / "annotated.jsonl", jsonl);
  ExportOptions options;
  options.split = {1.0, 0.0, 0.0};
  ExportSummary s = Export(dir / "annotated.jsonl", dir / "out", options);
  CHECK(s.layouts == valid);
  CHECK(s.invalid_layout == invalid);
  CHECK(s.invalid_by_rule == first_rules);
  CHECK(s.layouts_by_floors.count(3) == 1);  // the three-floor villa made it
  // Each answer is exactly the canonical text of its source layout.
  auto sources = Lines(dir / "out" / "sources.jsonl");
  auto lines = Lines(dir / "out" / "train.jsonl");
  REQUIRE(sources.size() == lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string id = Json::parse(sources[i])["id"];
    auto texts = ParseSampleLine(Json::parse(lines[i]));
    REQUIRE(texts.ok());
    INFO(id);
    CHECK(texts->assistant == answers.at(id));
    CHECK(texts->user == "a building");
  }
}
