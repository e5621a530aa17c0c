// `villa validate` end to end: exit codes, the per-layout lines, the summary, and --json.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "test_support.h"

using namespace villa;
using namespace villa::test;

namespace {
struct Run {
  int code = -1;
  std::string output;
};

Run Villa(const std::string& args, bool with_stderr = true) {
  std::string command = std::string(VILLA_BINARY) + " " + args + (with_stderr ? " 2>&1" : " 2>/dev/null");
  Run run;
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe);
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) run.output.append(buffer, n);
  int status = pclose(pipe);
  run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

std::string OneLine(const std::string& file) {
  std::ifstream in(FixturePath(file));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return Json::parse(text).dump();
}

// A folder of its own per test case and process: ctest runs test cases in parallel.
std::filesystem::path WriteStream(const std::string& tag) {
  auto dir = std::filesystem::temp_directory_path() / ("villa_validate_cli_" + tag + "_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  auto path = dir / "stream.jsonl";
  std::ofstream out(path);
  out << "{\"id\": \"a\", \"layout\": " << OneLine("house_one_floor.json") << "}\n"
      << "{\"id\": \"b\", \"layout\": {\"rooms\": \n"
      << "{\"id\": \"c\", \"layout\": " << OneLine("rule9_kitchen_without_window.json") << "}\n";
  return path;
}
}  // namespace

TEST_CASE("villa validate: a valid layout exits 0 with the summary", "[cli]") {
  Run run = Villa("validate " + FixturePath("villa_three_floors.json"));
  INFO(run.output);
  CHECK(run.code == 0);
  CHECK_THAT(run.output, Catch::StartsWith("1 layout: 1 valid, 0 invalid (0 unparsable)\n"));
  CHECK_THAT(run.output, Catch::Contains("FSR 100.0%  RR 100.0% (per floor)  RR 100.0% (from the entrance)  VCR 100.0% (2 floor pairs)"));
}

TEST_CASE("villa validate: an invalid layout exits 1 with its violations on one line", "[cli]") {
  std::string file = FixturePath("rule9_kitchen_without_window.json");
  Run run = Villa("validate " + file);
  INFO(run.output);
  CHECK(run.code == 1);
  CHECK_THAT(run.output, Catch::StartsWith(file + ": rule 9: kitchen_0/0 has no window\n"));
  CHECK_THAT(run.output, Catch::Contains("1 layout: 0 valid, 1 invalid (0 unparsable)"));
  // The per-rule table lists rule 9 with one layout and one violation.
  CHECK_THAT(run.output, Catch::Contains("9     windows in kitchens/bathrooms; balconies"));
  Run quiet = Villa("validate --quiet " + file);
  CHECK(quiet.code == 1);
  CHECK_THAT(quiet.output, Catch::StartsWith("1 layout: 0 valid"));
}

TEST_CASE("villa validate: JSONL with ids, a broken line and an invalid layout", "[cli]") {
  auto path = WriteStream("text");
  Run run = Villa("validate " + path.string());
  INFO(run.output);
  CHECK(run.code == 1);
  CHECK_THAT(run.output, Catch::Contains(path.string() + ":2: cannot parse: not valid JSON"));
  CHECK_THAT(run.output, Catch::Contains(path.string() + ":3 c: rule 9: kitchen_0/0 has no window\n"));
  CHECK_THAT(run.output, Catch::Contains("3 layouts: 1 valid, 2 invalid (1 unparsable)"));
  CHECK_THAT(run.output, Catch::Contains("FSR 66.7%"));
  std::filesystem::remove_all(path.parent_path());
}

TEST_CASE("villa validate --json is machine-readable", "[cli]") {
  auto path = WriteStream("json");
  Run run = Villa("validate --json " + path.string(), /*with_stderr=*/false);
  CHECK(run.code == 1);
  Json report;
  REQUIRE_NOTHROW(report = Json::parse(run.output));
  const Json& summary = report.at("summary");
  CHECK(summary.at("count") == 3);
  CHECK(summary.at("valid") == 1);
  CHECK(summary.at("unparsable") == 1);
  CHECK(summary.at("fsr").get<double>() == Approx(2.0 / 3));
  CHECK(summary.at("vcr").is_null());  // one-floor layouts only
  CHECK(summary.at("rules").at("9").at("layouts") == 1);
  const Json& layouts = report.at("layouts");
  REQUIRE(layouts.size() == 3);
  CHECK(layouts[0].at("id") == "a");
  CHECK(layouts[0].at("valid") == true);
  CHECK(layouts[1].at("parsed") == false);
  CHECK(layouts[1].at("error").get<std::string>().rfind(path.string() + ":2: not valid JSON", 0) == 0);
  const Json& violation = layouts[2].at("violations").at(0);
  CHECK(violation.at("rule") == 9);
  CHECK(violation.at("elements") == Json::array({"kitchen_0/0"}));
  CHECK(violation.at("message") == "kitchen_0/0 has no window");
  CHECK(layouts[2].at("metrics").at("rooms") == 6);
  std::filesystem::remove_all(path.parent_path());
}

TEST_CASE("villa validate: usage errors exit 2", "[cli]") {
  CHECK(Villa("validate").code == 2);
  Run missing = Villa("validate " + FixturePath("no_such_layout.json"));
  CHECK(missing.code == 2);
  CHECK_THAT(missing.output, Catch::Contains("no such file"));
  Run help = Villa("validate --help");
  CHECK(help.code == 0);
  CHECK_THAT(help.output, Catch::Contains("--json"));
  CHECK_THAT(help.output, Catch::Contains("--quiet"));
}

TEST_CASE("villa validate reads fine-tuning samples: messages, ShareGPT, Alpaca", "[cli]") {
  auto dir = std::filesystem::temp_directory_path() / ("villa_validate_cli_samples_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  auto path = dir / "samples.jsonl";
  {
    std::string answer = OneLine("house_one_floor.json");
    std::string bad_answer = OneLine("rule9_kitchen_without_window.json");
    std::ofstream out(path);
    out << Json{{"messages", Json::array({Json{{"role", "system"}, {"content", "s"}}, Json{{"role", "user"}, {"content", "u"}},
                                          Json{{"role", "assistant"}, {"content", answer}}})}}.dump()
        << "\n"
        << Json{{"conversations", Json::array({Json{{"from", "human"}, {"value", "u"}}, Json{{"from", "gpt"}, {"value", bad_answer}}})}}.dump()
        << "\n"
        << Json{{"instruction", "u"}, {"input", ""}, {"output", answer}}.dump() << "\n"
        << Json{{"messages", Json::array({Json{{"role", "user"}, {"content", "u"}}})}}.dump() << "\n";
  }
  Run run = Villa("validate " + path.string());
  INFO(run.output);
  CHECK(run.code == 1);
  CHECK_THAT(run.output, Catch::Contains(path.string() + ":2: rule 9: kitchen_0/0 has no window"));
  CHECK_THAT(run.output, Catch::Contains(path.string() + ":4: cannot parse: messages: no assistant answer"));
  CHECK_THAT(run.output, Catch::Contains("4 layouts: 2 valid, 2 invalid (1 unparsable)"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("villa validate: an empty or blank JSONL stream fails, since nothing was checked", "[cli][hostile]") {
  auto dir = std::filesystem::temp_directory_path() / ("villa_validate_cli_empty_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "empty.jsonl").close();
  std::ofstream(dir / "blank.jsonl") << "\n   \n\t\n";
  for (const char* name : {"empty.jsonl", "blank.jsonl"}) {
    const std::string file = (dir / name).string();
    Run run = Villa("validate " + file);
    INFO(run.output);
    CHECK(run.code == 1);
    CHECK_THAT(run.output, Catch::Contains("villa validate: no layouts in " + file + "\n"));
    Run json = Villa("validate --json " + file, /*with_stderr=*/false);
    CHECK(json.code == 1);
    CHECK(Json::parse(json.output).at("summary").at("empty_files") == Json::array({file}));
  }
  // Beside a file with layouts the empty one still fails the run.
  Run both = Villa("validate " + FixturePath("house_one_floor.json") + " " + (dir / "empty.jsonl").string());
  CHECK(both.code == 1);
  std::filesystem::remove_all(dir);
}

TEST_CASE("villa validate: JSON nested 100,000 deep is an unparsable layout, not a crash", "[cli][hostile]") {
  auto dir = std::filesystem::temp_directory_path() / ("villa_validate_cli_deep_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "brackets.json") << std::string(100000, '[');
  std::ofstream(dir / "room.json") << R"J({"rooms": {"kitchen_0/0": )J" << std::string(200000, '[') << std::string(200000, ']')
                                   << R"J(}, "entrance": {}, "doors": {}, "opens": {}, "windows": {}, "interiors": {}})J";
  Run run = Villa("validate " + (dir / "brackets.json").string() + " " + (dir / "room.json").string());
  INFO(run.output);
  CHECK(run.code == 1);
  CHECK_THAT(run.output, Catch::Contains((dir / "brackets.json").string() + ": cannot parse: line 1, column 65: nested deeper than 64 levels"));
  CHECK_THAT(run.output, Catch::Contains((dir / "room.json").string() + ": cannot parse: line 1, column 89: nested deeper than 64 levels"));
  CHECK_THAT(run.output, Catch::Contains("2 layouts: 0 valid, 2 invalid (2 unparsable)"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("villa validate: numbers with more than two decimals are read and noted, not violations", "[cli][tolerance]") {
  auto dir = std::filesystem::temp_directory_path() / ("villa_validate_cli_notes_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::string text = OneLine("house_one_floor.json");
  // The kitchen window, 3 mm off its wall and with three decimals: on the wall, with a note.
  const std::string from = "shapely.LineString([(7, 0), (8, 0)])", to = "shapely.LineString([(7.001, 0.003), (8, 0.003)])";
  REQUIRE(text.find(from) != std::string::npos);
  text.replace(text.find(from), from.size(), to);
  std::ofstream(dir / "decimals.json") << text;
  const std::string file = (dir / "decimals.json").string();
  Run run = Villa("validate " + file);
  INFO(run.output);
  CHECK(run.code == 0);
  CHECK_THAT(run.output, Catch::Contains(file + ": note: 3 numbers have more than two decimals (the first: windows[\"kitchen0_window\"] x = 7.001)"));
  CHECK_THAT(run.output, Catch::Contains("1 layout: 1 valid, 0 invalid (0 unparsable)"));
  Run json = Villa("validate --json " + file, /*with_stderr=*/false);
  CHECK(Json::parse(json.output).at("layouts").at(0).at("notes").size() == 1);
  std::filesystem::remove_all(dir);
}
