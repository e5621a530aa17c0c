// villa assets import|list|show|search end to end: exit codes, outputs, messages naming what is wrong.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <sstream>

#include <nlohmann/json.hpp>

#include "sh3f_fixture.h"

namespace villa {
namespace {

struct Run {
  int code = -1;
  std::string out;
  std::string err;
};

class Sandbox {
 public:
  Sandbox() : dir_(test::FreshDir("cli_" + std::to_string(::getpid()))) {}
  ~Sandbox() { std::filesystem::remove_all(dir_); }
  const std::filesystem::path& dir() const { return dir_; }
  std::string Quoted(const std::string& name) const {
    std::string quoted = (dir_ / name).string();
    quoted.insert(quoted.begin(), '\'');
    quoted.push_back('\'');
    return quoted;
  }

  // Runs villa with a clean library environment (no VILLA_ASSETS, HOME inside the sandbox).
  Run Villa(const std::string& args) const {
    const std::string command = "env -u VILLA_ASSETS -u XDG_DATA_HOME HOME='" + dir_.string() + "' CI=true '" + VILLA_BINARY +
                                "' " + args + " >'" + (dir_ / "stdout").string() + "' 2>'" + (dir_ / "stderr").string() + "'";
    const int status = std::system(command.c_str());
    Run run;
    run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = ReadFile(dir_ / "stdout").ok() ? *ReadFile(dir_ / "stdout") : "";
    run.err = ReadFile(dir_ / "stderr").ok() ? *ReadFile(dir_ / "stderr") : "";
    return run;
  }

 private:
  std::filesystem::path dir_;
};

TEST_CASE("villa assets import writes the library under HOME and prints its summary", "[assets][cli]") {
  Sandbox box;
  test::WriteFixtureLibrary(box.dir() / "from");
  Run run = box.Villa("assets import --from " + box.Quoted("from") + " -j 2");
  INFO(run.err);
  REQUIRE(run.code == 0);
  CHECK(run.out.find("archives: 1, models read: 12, imported: 8, skipped: 4 (2 unreadable), decimated: 1") != std::string::npos);
  CHECK(run.out.find("skipped, door or window: 1") != std::string::npos);
  CHECK(run.out.find("watertight: 5 of 8 (62.5%)") != std::string::npos);
  const auto library = box.dir() / ".local" / "share" / "villa" / "assets";
  CHECK(std::filesystem::exists(library / "assets.jsonl"));
  CHECK(std::filesystem::exists(library / "import-report.json"));

  Run list = box.Villa("assets list --category bookcase");
  REQUIRE(list.code == 0);
  CHECK(list.out.find("sh3d:TestLib#bookcase") != std::string::npos);
  CHECK(list.out.find("1 of 8 assets") != std::string::npos);
  Run json = box.Villa("assets list --room-type bathroom --json");
  REQUIRE(json.code == 0);
  // Assets for any room (lights, here) and none made for other rooms only.
  std::istringstream lines(json.out);
  std::string line;
  int count = 0;
  while (std::getline(lines, line)) {
    auto record = nlohmann::json::parse(line);
    CHECK(record["room_types"].empty());
    ++count;
  }
  CHECK(count == 2);

  Run show = box.Villa("assets show 'sh3d:TestLib#bookcase'");
  REQUIRE(show.code == 0);
  CHECK(show.out.find("creator           Jane Doe") != std::string::npos);
  CHECK(show.out.find("credit            Bookcase by Jane Doe (CC-BY-3.0)") != std::string::npos);
  CHECK(show.out.find("cavity 3") != std::string::npos);
  CHECK(show.out.find("size              w 0.80, d 0.30, h 1.20 m") != std::string::npos);

  Run search = box.Villa("assets search 'bookshelf' -k 2");
  REQUIRE(search.code == 0);
  CHECK(search.out.find("query: bookshelf [category bookcase]") != std::string::npos);
  CHECK(search.out.find("1  ") != std::string::npos);
  CHECK(search.out.find("sh3d:TestLib#bookcase") < search.out.find("sh3d:TestLib#"  "chest"));
  Run books = box.Villa("assets search 'books' --json");
  REQUIRE(books.code == 0);
  CHECK(books.err.find("the library has no books that meets the query; the procedural generator 'books' makes one") != std::string::npos);
}

TEST_CASE("villa assets: usage errors exit 2, failures exit 1 and name the folder or id", "[assets][cli]") {
  Sandbox box;
  Run nothing = box.Villa("assets list --library " + box.Quoted("none"));
  CHECK(nothing.code == 1);
  CHECK(nothing.err == "villa assets list: " + (box.dir() / "none").string() +
                           ": no asset library here (no assets.jsonl; run `villa assets import`)\n");
  Run from = box.Villa("assets import --from " + box.Quoted("missing"));
  CHECK(from.code == 2);
  CHECK(from.err.find("missing: no such folder") != std::string::npos);
  CHECK(box.Villa("assets import --max-triangles 0").code == 2);
  CHECK(box.Villa("assets search couch --size 1,2").code == 2);
  CHECK(box.Villa("assets search couch --placement roof").code == 2);
  CHECK(box.Villa("assets").code == 2);

  test::WriteFixtureLibrary(box.dir() / "from");
  REQUIRE(box.Villa("assets import --from " + box.Quoted("from") + " --library " + box.Quoted("lib")).code == 0);
  Run unknown = box.Villa("assets show nope --library " + box.Quoted("lib"));
  CHECK(unknown.code == 1);
  CHECK(unknown.err == "villa assets show: nope: no such asset in " + (box.dir() / "lib").string() + "\n");
  Run bad = box.Villa("assets show 'proc:wardrobe?h=9'");
  CHECK(bad.code == 1);
  CHECK(bad.err.find("villa assets show: proc:wardrobe?h=9: h = 9") == 0);
}

TEST_CASE("villa assets show makes a procedural asset from its id, with no library installed", "[assets][cli]") {
  Sandbox box;  // an empty home: no library
  Run show = box.Villa("assets show 'proc:wardrobe?cols=2&w=1.2&d=0.6&h=2.0&style=modern&seed=1' --render " + box.Quoted("w.png"));
  INFO(show.err);
  REQUIRE(show.code == 0);
  CHECK(show.out.find("category          wardrobe") != std::string::npos);
  CHECK(show.out.find("cavity 0          w 0.65, d 0.59, h 1.46 m, at z 0.098, open -y, on surface 0, hanging rail at z 1.586") !=
        std::string::npos);
  CHECK(std::filesystem::file_size(box.dir() / "w.png") > 1000);
}

}  // namespace
}  // namespace villa
