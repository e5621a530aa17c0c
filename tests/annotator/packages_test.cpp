// Work packages: a dataset split among several people, an overlap sample labelled twice, the journals
// merged back (once), and the agreement figures that come out of it.
#include <catch2/catch.hpp>

#include "annotator/packages.h"
#include "annotator/status_report.h"
#include "layout/layout_io.h"
#include "layout/validate.h"
#include "test_support.h"

using namespace villa;
using namespace villa::annotator;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> Ids(const Session& s) {
  std::vector<std::string> ids;
  for (int i = 0; i < s.size(); ++i) ids.push_back(s.record(i).id);
  return ids;
}

}  // namespace

TEST_CASE("split into packages, label twice, merge back, agreement in --status", "[packages]") {
  test::TempDataset ds;
  std::string msg;
  {
    auto s = test::OpenSession(ds.dir(), true, "lead");
    REQUIRE(s->AutoAnnotate().ok());
    REQUIRE(s->Reopen(3, &msg).ok());  // --auto rejected it; the lead wants a person to look again
    REQUIRE(s->Accept(1, &msg).ok());  // decided by a person: not shared out
  }
  SplitSummary split;
  {
    auto s = test::OpenSession(ds.dir(), false, "lead");
    SplitOptions o;
    o.parts = 2;
    o.overlap = 0.5;
    auto made = SplitIntoPackages(*s, o);
    INFO((made ? std::string() : made.error()));
    REQUIRE(made.ok());
    split = *made;
    CHECK(split.layouts == 3);
    CHECK(split.left_out == 1);
    CHECK(split.overlap == 2);  // round(0.5 * 3)
    REQUIRE(split.packages == std::vector<std::string>{"part-1-of-2", "part-2-of-2"});
    CHECK(split.sizes[0] + split.sizes[1] == 3 + 2);
    // A second split would hide the first one's work: refused.
    auto again = SplitIntoPackages(*s, o);
    REQUIRE(!again.ok());
    CHECK(again.error().find("exists (a split was made before") != std::string::npos);
  }
  fs::path p1 = split.folder / "part-1-of-2", p2 = split.folder / "part-2-of-2";
  auto record = ReadSplitRecord(ds.dir());
  REQUIRE(record);
  CHECK(record->parts == 2);
  CHECK(record->overlap.size() == 2);

  // Each package is a dataset folder of its own, starting from the state in DIR (--auto's drafts).
  auto a = test::OpenSession(p1, true, "alice");
  auto b = test::OpenSession(p2, true, "bob");
  CHECK(a->size() == split.sizes[0]);
  CHECK(b->size() == split.sizes[1]);
  std::vector<std::string> shared;
  for (const std::string& id : Ids(*a))
    if (b->dataset().Find(id) >= 0) shared.push_back(id);
  CHECK(shared == record->overlap);
  for (int i = 0; i < a->size(); ++i) {
    CHECK(a->record(i).id != "villa-000001");
    if (a->record(i).id == "villa-000000") CHECK(a->state(i).status == AnnotationStatus::kAuto);
  }
  // Both label the overlap. alice accepts what she can; bob rejects the first shared layout that is
  // valid (a decision they disagree on) and relabels a room of any other valid one (a label).
  for (int i = 0; i < a->size(); ++i) {
    a->Spend(i, 20);
    if (!a->Accept(i, &msg).ok()) REQUIRE(a->Reject(i, "staircase badly placed", &msg).ok());
  }
  std::string disputed;
  for (int i = 0; i < b->size(); ++i) {
    const std::string& id = b->record(i).id;
    bool is_shared = std::find(shared.begin(), shared.end(), id) != shared.end();
    bool valid = ValidateLayout(b->state(i).layout).valid();
    if (is_shared && valid && disputed.empty()) {
      disputed = id;
      REQUIRE(b->Reject(i, "rooms too small or too narrow to use", &msg).ok());
      continue;
    }
    if (is_shared && valid) {
      for (std::size_t r = 0; r < b->state(i).layout.rooms.size(); ++r)
        if (b->state(i).layout.rooms[r].category == Category::kBedroom) {
          REQUIRE(b->Relabel(i, static_cast<int>(r), Category::kOffice, &msg).ok());
          break;
        }
    }
    if (!b->Accept(i, &msg).ok()) REQUIRE(b->Reject(i, "staircase badly placed", &msg).ok());
  }
  REQUIRE(!disputed.empty());
  a.reset();
  b.reset();

  int lines_in_packages = 0;
  for (const fs::path& p : {p1, p2}) {
    std::string text = test::Slurp(JournalPath(p));
    for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + 1)) ++lines_in_packages;
  }
  {
    auto s = test::OpenSession(ds.dir(), true, "lead");
    auto merged = MergePackages(*s, {p1, p2});
    INFO((merged ? std::string() : merged.error()));
    REQUIRE(merged.ok());
    CHECK(merged->packages == 2);
    // Less the packages' starting lines: one for each layout they hold (its state in DIR).
    CHECK(merged->lines == lines_in_packages - split.sizes[0] - split.sizes[1]);
    CHECK(merged->annotators == std::vector<std::string>{"alice", "bob"});
    // The same packages again: nothing new.
    auto twice = MergePackages(*s, {p1, p2});
    REQUIRE(twice.ok());
    CHECK(twice->lines == 0);
  }
  auto s = test::OpenSession(ds.dir(), false, "lead");
  // Every layout shared out was decided in a package; the last package merged decides the state.
  for (const char* id : {"villa-000000", "villa-000002", "villa-000003"}) {
    int item = s->dataset().Find(id);
    CHECK(s->state(item).status != AnnotationStatus::kAuto);
    CHECK(s->state(item).status != AnnotationStatus::kPending);
  }
  CHECK(s->state(1).decided_by == "lead");
  int first = s->dataset().Find(disputed);
  CHECK(s->Ratings(first).size() == 2);
  CHECK(s->Disagreement(first));
  CHECK(s->effort(first).annotators == std::vector<std::string>{"alice", "bob"});
  CHECK(s->effort(first).seconds == 20);
  Agreement g = s->AgreementFigures();
  REQUIRE(g.pairs.size() == 1);
  CHECK(g.pairs[0].who == "alice / bob");
  CHECK(g.pairs[0].layouts == 2);
  CHECK(g.pairs[0].decisions_agreed <= 1);
  // The history says where each line came from.
  bool from_package = false;
  for (const HistoryEntry& h : s->history(first)) from_package |= h.package.find("part-2-of-2") != std::string::npos;
  CHECK(from_package);

  std::string report = StatusReport(*s);
  INFO(report);
  CHECK(report.find("overlap sample of the split: 2 layouts, 2 decided twice so far") != std::string::npos);
  CHECK(report.find("alice / bob") != std::string::npos);
  CHECK(report.find("kappa") != std::string::npos);
  CHECK(report.find("--review") != std::string::npos);
  CHECK(report.find("alice ") != std::string::npos);
}

TEST_CASE("merging refuses what is not a package of this dataset", "[packages]") {
  test::TempDataset ds, other;
  auto s = test::OpenSession(ds.dir(), true, "lead");
  auto not_package = MergePackages(*s, {other.dir()});
  REQUIRE(!not_package.ok());
  CHECK(not_package.error().find("package.json: missing") != std::string::npos);
  // A package whose layout differs from the dataset's.
  test::Spit(other.dir() / "package.json", R"({"format": "villa annotate package", "split": "x", "package": "part-1-of-2"})");
  std::string layouts = test::Slurp(LayoutsPath(other.dir()));
  layouts.replace(layouts.find("shapely.box(0, 0, 6, 5)"), 23, "shapely.box(0, 0, 6, 4)");
  test::Spit(LayoutsPath(other.dir()), layouts);
  auto changed = MergePackages(*s, {other.dir()});
  REQUIRE(!changed.ok());
  CHECK(changed.error().find("layouts.jsonl:1: \"villa-000000\" differs from the layout in") != std::string::npos);
  SplitOptions o;
  o.parts = 1;
  CHECK(!o.Invalid().empty());
  o.parts = 2;
  o.overlap = 0.7;
  CHECK(o.Invalid().find("--overlap") == 0);
}
