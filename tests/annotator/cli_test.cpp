// `villa annotate` in batch: --status, --auto, --export through the real binary; exit codes and messages.
#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>

#include <catch2/catch.hpp>

#include "test_support.h"

using namespace villa;
namespace test = villa::annotator::test;

namespace {

struct Output {
  int status = -1;
  std::string text;  // stdout and stderr together
};

Output Villa(const std::string& args) {
  Output out;
  std::string command = std::string("'") + VILLA_BINARY + "' " + args + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return out;
  char buffer[4096];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) out.text.append(buffer, n);
  int rc = ::pclose(pipe);
  out.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  return out;
}

std::string Q(const std::filesystem::path& p) {
  std::string quoted(1, '\'');
  return quoted.append(p.string()).append(1, '\'');
}

}  // namespace

TEST_CASE("villa annotate --auto --export is byte-identical for the same dataset", "[cli]") {
  test::TempDataset a, b;
  for (auto* ds : {&a, &b}) {
    Output o = Villa("annotate " + Q(ds->dir()) + " --auto --export " + Q(ds->dir() / "annotated.jsonl"));
    INFO(o.text);
    REQUIRE(o.status == 0);
    CHECK(o.text.find("3 auto, 1 rejected") != std::string::npos);
  }
  std::string ea = test::Slurp(a.dir() / "annotated.jsonl");
  CHECK(ea == test::Slurp(b.dir() / "annotated.jsonl"));
  CHECK(std::count(ea.begin(), ea.end(), '\n') == 4);
  CHECK(ea.find("\"status\":\"verified\"") == std::string::npos);

  // A second --auto changes nothing (nothing pending); export refuses to overwrite without --force.
  Output again = Villa("annotate " + Q(a.dir()) + " --auto --export " + Q(a.dir() / "annotated.jsonl"));
  CHECK(again.status == 1);
  CHECK(again.text.find("exists (use --force to overwrite)") != std::string::npos);
  Output forced = Villa("annotate " + Q(a.dir()) + " --export " + Q(a.dir() / "annotated.jsonl") + " --force");
  CHECK(forced.status == 0);
  CHECK(test::Slurp(a.dir() / "annotated.jsonl") == ea);

  Output status = Villa("annotate " + Q(a.dir()) + " --status");
  INFO(status.text);
  CHECK(status.status == 0);
  CHECK(status.text.find("4 of 4 layouts annotated") != std::string::npos);
  CHECK(status.text.find("auto            3") != std::string::npos);
  CHECK(status.text.find("rejected        1") != std::string::npos);
}

TEST_CASE("villa annotate reports bad input with the file and line, never a crash", "[cli]") {
  test::TempDataset ds;
  Output missing = Villa("annotate " + Q(ds.dir() / "nope") + " --status");
  CHECK(missing.status == 1);
  CHECK(missing.text.find("nope: no such dataset folder") != std::string::npos);

  test::Spit(ds.journal(), "{\"id\": \"villa-000000\"}\n");
  Output corrupt = Villa("annotate " + Q(ds.dir()) + " --status");
  INFO(corrupt.text);
  CHECK(corrupt.status == 1);
  CHECK(corrupt.text.find("annotations.journal.jsonl:1: corrupt journal line: \"state\" missing") != std::string::npos);
  test::Spit(ds.journal(), "{\"id\": \"villa-000000\"}\nnot json\n");
  Output not_json = Villa("annotate " + Q(ds.dir()) + " --status");
  CHECK(not_json.status == 1);
  CHECK(not_json.text.find("annotations.journal.jsonl:2: corrupt journal line") != std::string::npos);

  // An export never replaces what is not a plain file (a pipe here; /dev/null alike).
  std::filesystem::remove(ds.journal());
  std::filesystem::path fifo = ds.dir() / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  Output to_pipe = Villa("annotate " + Q(ds.dir()) + " --export " + Q(fifo) + " --force");
  CHECK(to_pipe.status == 1);
  CHECK(to_pipe.text.find("pipe: exists and is not a plain file") != std::string::npos);
  CHECK(std::filesystem::is_fifo(fifo));

  // Not a terminal: the interactive mode says what to use instead.
  std::filesystem::remove(ds.journal());
  Output piped = Villa("annotate " + Q(ds.dir()) + " < /dev/null");
  CHECK(piped.status == 1);
  CHECK(piped.text.find("needs a terminal") != std::string::npos);
}

TEST_CASE("villa annotate --split, --merge and --status with several annotators", "[cli][packages]") {
  test::TempDataset ds;
  Output split = Villa("annotate " + Q(ds.dir()) + " --split 2 --overlap 0.5");
  INFO(split.text);
  REQUIRE(split.status == 0);
  CHECK(split.text.find("split 4 layouts into 2 packages") != std::string::npos);
  CHECK(split.text.find("2 in two packages") != std::string::npos);
  std::filesystem::path p1 = ds.dir() / "packages" / "part-1-of-2", p2 = ds.dir() / "packages" / "part-2-of-2";
  // Each person works in their package; here in batch, as two annotators.
  for (auto [package, who] : {std::pair{p1, "alice"}, std::pair{p2, "bob"}}) {
    Output done = Villa("annotate " + Q(package) + " --auto --annotator " + who);
    INFO(done.text);
    CHECK(done.status == 0);
  }
  Output merged = Villa("annotate " + Q(ds.dir()) + " --merge " + Q(p1) + " " + Q(p2) + " --status");
  INFO(merged.text);
  REQUIRE(merged.status == 0);
  CHECK(merged.text.find("merged ") != std::string::npos);
  CHECK(merged.text.find("4 of 4 layouts annotated") != std::string::npos);
  CHECK(merged.text.find("overlap sample of the split: 2 layouts, 0 decided twice so far") != std::string::npos);
  Output again = Villa("annotate " + Q(ds.dir()) + " --merge " + Q(p1));
  CHECK(again.text.find("merged 0 journal lines") != std::string::npos);
  // A second split would hide the packages' work.
  Output resplit = Villa("annotate " + Q(ds.dir()) + " --split 2");
  CHECK(resplit.status == 1);
  CHECK(resplit.text.find("a split was made before") != std::string::npos);
}

TEST_CASE("villa annotate: bad --annotator, --filter, --split and --review combinations are usage errors", "[cli]") {
  test::TempDataset ds;
  for (const std::string& args : {std::string("--annotator auto --status"), std::string("--filter finished"),
                                  std::string("--split 1"), std::string("--overlap 0.9 --split 2"),
                                  std::string("--review --status")}) {
    Output o = Villa("annotate " + Q(ds.dir()) + " " + args + " < /dev/null");
    INFO(args << ": " << o.text);
    CHECK(o.status == 2);
  }
  Output o = Villa("annotate " + Q(ds.dir()) + " --filter finished");
  CHECK(o.text.find("--filter: \"finished\" is none of all, to-do, pending") != std::string::npos);
  CHECK(!std::filesystem::exists(ds.journal()));  // nothing written by a refused command
}
