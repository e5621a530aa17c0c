// The pipelines behind `villa eval` and `villa generate` as library calls: results in prompt order and
// independent of the job count, files written, usage problems found before anything is written.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>

#include "generator/generate.h"
#include "generator/text/eval.h"
#include "layout/layout_io.h"

namespace villa {

TEST_CASE("eval plans every prompt in order, the same for any job count") {
  const auto dir = std::filesystem::temp_directory_path() / ("villa_eval_lib_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / "prompts.jsonl";
  {
    std::ofstream out(file);
    out << "{\"id\": \"p1\", \"text\": \"A one-story house with a living room, a kitchen and a bedroom.\"}\n"
        << "{\"text\": \"A two-story L-shaped villa with two bedrooms and a balcony.\"}\n"
        << "{\"id\": 3, \"text\": \"A rectangular house with a kitchen, a dining room and an office.\"}\n";
  }
  auto prompts = ReadEvalPrompts(file);
  REQUIRE(prompts.ok());
  REQUIRE(prompts->size() == 3);
  CHECK((*prompts)[0].id == "p1");
  CHECK((*prompts)[2].id == "3");
  CHECK((*prompts)[1].line == 2);
  CHECK(ReadEvalPrompts(file, 2)->size() == 2);

  EvalOptions options;
  options.plan.seed = 4;
  options.plan.time_budget_s = 2.0;
  std::string problem;
  REQUIRE(options.IsValid(&problem));
  options.jobs = 1;
  std::atomic<int> planned{0};
  options.on_planned = [&] { ++planned; };
  const EvalSummary one = EvaluatePrompts(*prompts, options);
  options.jobs = 3;
  const EvalSummary three = EvaluatePrompts(*prompts, options);
  CHECK(planned.load() == 6);
  CHECK(one.jobs == 1);
  CHECK(three.jobs == 3);
  REQUIRE(one.results.size() == 3);
  for (std::size_t i = 0; i < 3; ++i) {
    REQUIRE(one.results[i].layout.has_value());
    REQUIRE(three.results[i].layout.has_value());
    CHECK(LayoutToString(*one.results[i].layout, -1) == LayoutToString(*three.results[i].layout, -1));
  }
  CHECK(one.overall.outputs == 3);
  CHECK(one.requirements == three.requirements);
  CHECK(one.requirements_met == three.requirements_met);
  const auto json = EvalReportJson(one);
  CHECK(json["prompts"].size() == 3);
  CHECK(json["overall"]["count"] == 3);
  CHECK(json["overall"]["backend"] == "procedural");
  CHECK_THAT(EvalReportText(one), Catch::Contains("requirements met"));

  // A record without "text" names its line.
  {
    std::ofstream out(file, std::ios::app);
    out << "{\"id\": \"bad\"}\n";
  }
  auto bad = ReadEvalPrompts(file);
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.error() == file.string() + ":4: expected an object with a \"text\" string");
  std::filesystem::remove_all(dir);
}

TEST_CASE("generate without furnishing writes the layout, plans, building, preview and report, and refuses to overwrite") {
  const auto dir = std::filesystem::temp_directory_path() / ("villa_generate_lib_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  GenerateOptions options;
  options.plan.seed = 5;
  options.out = dir;
  options.furnish = false;
  std::string problem;
  REQUIRE(options.IsValid(&problem));
  REQUIRE(CheckGenerateOutput(options).ok());
  auto summary = GenerateVilla("A two-story house with a living room, a kitchen, two bedrooms and a balcony.", options);
  REQUIRE(summary.ok());
  INFO(summary->BriefReport());
  CHECK(summary->ok());
  CHECK(summary->built);
  CHECK(summary->files ==
        std::vector<std::string>{"layout.json", "plan.png", "building.glb", "preview.png", "report.json"});
  for (const auto& f : summary->files) CHECK(std::filesystem::file_size(dir / f) > 100);
  CHECK(summary->building["levels"] == 2);
  CHECK(summary->report["building"] == summary->building);
  CHECK_THAT(summary->BriefReport(), Catch::Contains("building: 2 level(s)"));
  const Status again = CheckGenerateOutput(options);
  REQUIRE_FALSE(again.ok());
  CHECK(again.error() == (dir / "layout.json").string() + " exists; pass --force to overwrite it");
  options.force = true;
  CHECK(CheckGenerateOutput(options).ok());
  options.build.exterior_wall_thickness = 0;
  CHECK_FALSE(options.IsValid(&problem));
  CHECK_THAT(problem, Catch::Contains("exterior_wall_thickness"));
  std::filesystem::remove_all(dir);
}

}  // namespace villa
