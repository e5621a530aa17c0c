// villa finetune check: a clean export passes; planted leaks, invalid answers, foreign system prompts and
// bad lines are caught, and the command exits 1 on them.
#include <catch2/catch.hpp>

#include "finetune/check.h"
#include "finetune/export.h"
#include "finetune/sample_format.h"
#include "finetune_test_util.h"
#include "layout/layout_io.h"

using namespace villa;
using namespace villa::testing;

namespace {

struct Exported {
  ScratchDir dir{"check"};
  fs::path out;
  Exported() {
    Spit(dir / "annotated.jsonl", ManyRecords(40));
    out = dir / "out";
    auto s = ExportDataset(dir / "annotated.jsonl", out, {});
    REQUIRE(s.ok());
  }
  void Append(const std::string& file, const std::string& line) {
    std::string text = Slurp(out / file);
    Spit(out / file, text + line + "\n");
  }
  void ReplaceFirstLine(const std::string& file, const std::string& line) {
    auto lines = Lines(out / file);
    lines[0] = line;
    std::string text;
    for (const auto& l : lines) text += l + "\n";
    Spit(out / file, text);
  }
};

CheckReport Check(const fs::path& dir) {
  auto report = CheckExport(dir);
  REQUIRE(report.ok());
  return *report;
}

}  // namespace

TEST_CASE("check passes a clean export of every format", "[finetune][check]") {
  for (ExportFormat format : {ExportFormat::kMessages, ExportFormat::kShareGpt, ExportFormat::kAlpaca}) {
    ScratchDir dir("clean");
    Spit(dir / "annotated.jsonl", ManyRecords(30));
    ExportOptions options;
    options.format = format;
    REQUIRE(ExportDataset(dir / "annotated.jsonl", dir / "out", options).ok());
    CheckReport report = Check(dir / "out");
    INFO(report.BriefReport());
    CHECK(report.ok());
    CHECK(report.files == 3);
    CHECK(report.samples == 30);
  }
  Exported e;
  std::string output;
  CHECK(RunVilla("finetune check \"" + e.out.string() + "\"", &output) == 0);
  CHECK(output.find("ok") != std::string::npos);
}

TEST_CASE("check catches a layout leaked from train into test", "[finetune][check][leak]") {
  Exported e;
  e.Append("test.jsonl", Lines(e.out / "train.jsonl").front());
  CheckReport report = Check(e.out);
  CHECK(report.leaked_layouts == 1);
  CHECK(report.invalid_answers == 0);
  CHECK_FALSE(report.ok());
  CHECK(report.BriefReport().find("is also in split \"test\"") != std::string::npos);

  // The same geometry under other names and labels is still the same layout.
  auto texts = ParseSampleLine(Json::parse(Lines(e.out / "train.jsonl")[1]));
  REQUIRE(texts.ok());
  Layout layout = *ParseLayoutText(texts->assistant, "answer");
  for (auto& door : layout.doors) door.name += "_renamed";
  texts->assistant = LayoutToString(layout, -1);
  texts->user = "a different description";
  e.Append("val.jsonl", SampleLine(ExportFormat::kMessages, *texts).dump());
  CHECK(Check(e.out).leaked_layouts == 2);

  std::string output;
  CHECK(RunVilla("finetune check \"" + e.out.string() + "\"", &output) == 1);
  CHECK(output.find("FAILED") != std::string::npos);
}

TEST_CASE("check catches an invalid answer", "[finetune][check]") {
  Exported e;
  auto texts = ParseSampleLine(Json::parse(Lines(e.out / "val.jsonl").front()));
  REQUIRE(texts.ok());
  Json answer = Json::parse(texts->assistant);
  // Drop every window: kitchens and bathrooms without one break rule 9.
  answer["windows"] = Json::object();
  texts->assistant = answer.dump();
  e.ReplaceFirstLine("val.jsonl", SampleLine(ExportFormat::kMessages, *texts).dump());
  CheckReport report = Check(e.out);
  CHECK(report.invalid_answers == 1);
  CHECK(report.BriefReport().find("val.jsonl:1: answer breaks rule 9") != std::string::npos);
  CHECK_FALSE(report.ok());
  CHECK(RunVilla("finetune check \"" + e.out.string() + "\"") == 1);

  // An answer that is not JSON at all.
  texts->assistant = "Here is your layout: {";
  e.ReplaceFirstLine("test.jsonl", SampleLine(ExportFormat::kMessages, *texts).dump());
  CHECK(Check(e.out).invalid_answers == 2);
}

TEST_CASE("check catches foreign system prompts, bad lines and a wrong dataset_info entry", "[finetune][check]") {
  Exported e;
  auto texts = ParseSampleLine(Json::parse(Lines(e.out / "train.jsonl").front()));
  REQUIRE(texts.ok());
  texts->system = "You are a helpful assistant.";
  e.ReplaceFirstLine("train.jsonl", SampleLine(ExportFormat::kMessages, *texts).dump());
  CheckReport report = Check(e.out);
  CHECK(report.prompt_mismatches == 1);
  CHECK_FALSE(report.ok());

  Exported bad;
  bad.Append("train.jsonl", "{\"messages\": [");
  bad.Append("train.jsonl", "{\"text\": \"pretraining?\"}");
  CHECK(Check(bad.out).bad_lines == 2);

  Exported info;
  Json entries = Json::parse(Slurp(info.out / "dataset_info.json"));
  entries["villa_train"].erase("tags");  // LLaMA-Factory would skip every sample
  Spit(info.out / "dataset_info.json", entries.dump(2));
  CheckReport r = Check(info.out);
  CHECK(r.dataset_info_problems == 1);
  CHECK_FALSE(r.ok());
}

TEST_CASE("villa finetune export: exit codes and summary", "[finetune][cli]") {
  ScratchDir dir("cli");
  const std::string input = (FixtureDir() / "annotated.jsonl").string();
  const std::string out = (dir / "out").string();
  std::string output;
  CHECK(RunVilla("finetune export \"" + input + "\" --out \"" + out + "\" --format sharegpt --seed 5", &output) == 0);
  CHECK(output.find("exported 3 layouts as 3 samples") != std::string::npos);
  CHECK(output.find("first broken rule 9") != std::string::npos);
  CHECK(fs::exists(dir / "out" / "train.jsonl"));
  CHECK(RunVilla("finetune export \"" + input + "\" --out \"" + out + "\"", &output) == 1);  // not empty
  CHECK(output.find("--force") != std::string::npos);
  CHECK(RunVilla("finetune export \"" + input + "\" --out \"" + out + "\" --force --descriptions both") == 0);
  CHECK(RunVilla("finetune export \"" + input + "\" --out \"" + out + "\" --force --split 0.9:0.2", &output) == 2);
  CHECK(RunVilla("finetune export \"" + input + "\" --out \"" + out + "\" --force --split 0.5:0.2:0.2", &output) == 2);
  CHECK(output.find("sum to 1") != std::string::npos);
  CHECK(RunVilla("finetune export \"" + input + "\" --out \"" + out + "\" --format csv") == 2);
  CHECK(RunVilla("finetune export /no/such/file.jsonl --out \"" + out + "\"") == 2);
  CHECK(RunVilla("finetune check /no/such/folder") == 1);
}
