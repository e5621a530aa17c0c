// The session: actions journaled and replayed, undo / redo, torn and corrupt journals, --auto
// determinism and the export's contents.
#include <catch2/catch.hpp>

#include "annotator/session.h"
#include "layout/layout_io.h"
#include "layout/validate.h"
#include "test_support.h"

using namespace villa;
using namespace villa::annotator;

namespace {

int RoomIndex(const Session& s, int item, const std::string& name) { return s.state(item).layout.FindRoom(name); }

}  // namespace

TEST_CASE("a fresh session: all pending, drafted labels and descriptions", "[session]") {
  test::TempDataset ds;
  auto s = test::OpenSession(ds.dir(), true);
  REQUIRE(s->size() == 4);
  CHECK(s->counts().pending == 4);
  CHECK(s->NextPending(0) == 0);
  // villa-000002's unlabelled room got a drafted label.
  for (const Room& r : s->state(2).layout.rooms) CHECK(r.category != Category::kRoom);
  for (int i = 0; i < 4; ++i) {
    CHECK(!s->state(i).coarse.empty());
    CHECK(!s->state(i).fine.empty());
  }
  // Opening writes nothing until an action.
  CHECK((!std::filesystem::exists(ds.journal()) || std::filesystem::file_size(ds.journal()) == 0));
}

TEST_CASE("actions are journaled and replayed after a restart", "[session][journal]") {
  test::TempDataset ds;
  std::string msg;
  {
    auto s = test::OpenSession(ds.dir(), true);
    int kitchen = RoomIndex(*s, 0, "kitchen_0/0");
    REQUIRE(kitchen >= 0);
    REQUIRE(s->Relabel(0, kitchen, Category::kBathroom, &msg).ok());
    CHECK(msg == "label kitchen_0/0 -> bathroom_0/1");
    // Now the layout breaks rule 10 (living room joins no kitchen): accept is refused.
    auto refused = s->Accept(0, &msg);
    REQUIRE(!refused.ok());
    CHECK(refused.error().find("cannot accept") != std::string::npos);
    CHECK(refused.error().find("rule 10") != std::string::npos);
    int item = -1;
    REQUIRE(s->Undo(&item, &msg).ok());
    CHECK(item == 0);
    CHECK(RoomIndex(*s, 0, "kitchen_0/0") == kitchen);
    REQUIRE(s->Redo(&item, &msg).ok());
    CHECK(RoomIndex(*s, 0, "bathroom_0/1") == kitchen);
    REQUIRE(s->Undo(&item, &msg).ok());
    REQUIRE(s->Accept(0, &msg).ok());
    REQUIRE(s->Reject(1, "staircase badly placed", &msg).ok());
    REQUIRE(s->SetDescriptions(3, "A one-storey house.", "A one-storey rectangular house with a kitchen.", &msg).ok());
    CHECK(s->counts().verified == 1);
    CHECK(s->counts().rejected == 1);
  }
  auto s = test::OpenSession(ds.dir(), true);
  CHECK(s->state(0).status == AnnotationStatus::kVerified);
  CHECK(s->state(0).layout.FindRoom("kitchen_0/0") >= 0);
  CHECK(s->state(1).status == AnnotationStatus::kRejected);
  CHECK(s->state(1).reason == "staircase badly placed");
  CHECK(s->state(3).coarse == "A one-storey house.");
  CHECK(s->state(3).edited(DescriptionField::kCoarse));
  CHECK(s->state(3).edited(DescriptionField::kFine));
  CHECK(s->NextPending(0) == 2);
  // The undo history came back with the journal: the last action (the edit) undoes first.
  int item = -1;
  REQUIRE(s->Undo(&item, &msg).ok());
  CHECK(item == 3);
  CHECK(!s->state(3).edited(DescriptionField::kCoarse));
  CHECK(!s->state(3).edited(DescriptionField::kFine));
}

TEST_CASE("a relabel redrafts descriptions unless a person wrote them", "[session]") {
  test::TempDataset ds;
  auto s = test::OpenSession(ds.dir(), true);
  std::string msg;
  int office = -1;
  for (int i = 0; i < static_cast<int>(s->state(2).layout.rooms.size()); ++i)
    if (s->state(2).layout.rooms[i].category == Category::kOffice) office = i;
  REQUIRE(office >= 0);
  REQUIRE(s->Relabel(2, office, Category::kMeetingRoom, &msg).ok());
  CHECK(s->state(2).fine.find("office") == std::string::npos);
  CHECK(s->state(2).fine.find("meeting room") != std::string::npos);
  REQUIRE(s->SetDescriptions(2, "mine", "mine too", &msg).ok());
  REQUIRE(s->Relabel(2, office, Category::kBedroom, &msg).ok());
  CHECK(s->state(2).coarse == "mine");
}

TEST_CASE("a torn last journal line is skipped with a warning and set aside", "[journal]") {
  test::TempDataset ds;
  std::string msg;
  {
    auto s = test::OpenSession(ds.dir(), true);
    REQUIRE(s->Reject(0, "duplicate of another layout", &msg).ok());
  }
  std::string complete = test::Slurp(ds.journal());
  test::Spit(ds.journal(), R"({"seq":2,"time":"2026-01-01T00:00:00Z","id":"villa-000001","kind":"do","act)", true);
  {
    auto s = test::OpenSession(ds.dir(), true);
    REQUIRE(s->warnings().size() == 1);
    CHECK(s->warnings()[0].find("annotations.journal.jsonl:2: torn last line") != std::string::npos);
    CHECK(s->state(0).status == AnnotationStatus::kRejected);
    CHECK(s->state(1).status == AnnotationStatus::kPending);
    // The journal is back to its complete lines; the torn bytes are kept beside it.
    CHECK(test::Slurp(ds.journal()) == complete);
    std::filesystem::path torn = ds.journal();
    torn += ".torn";
    CHECK(test::Slurp(torn).find("villa-000001") != std::string::npos);
    REQUIRE(s->Accept(1, &msg).ok());
  }
  auto s = test::OpenSession(ds.dir(), true);
  CHECK(s->warnings().empty());
  CHECK(s->state(1).status == AnnotationStatus::kVerified);
}

TEST_CASE("corrupt journal lines are named by file and line", "[journal]") {
  test::TempDataset ds;
  std::string msg;
  {
    auto s = test::OpenSession(ds.dir(), true);
    REQUIRE(s->Reject(0, "duplicate of another layout", &msg).ok());
    REQUIRE(s->Reject(1, "duplicate of another layout", &msg).ok());
  }
  std::string text = test::Slurp(ds.journal());
  std::string first = text.substr(0, text.find('\n') + 1);
  SECTION("not JSON in the middle") {
    test::Spit(ds.journal(), first + "{not json\n" + text.substr(first.size()));
    auto s = Session::Open(ds.dir());
    REQUIRE(!s.ok());
    CHECK(s.error().find("annotations.journal.jsonl:2: corrupt journal line") != std::string::npos);
  }
  SECTION("an id the dataset does not hold") {
    std::string bad = first;
    bad.replace(bad.find("villa-000000"), 12, "villa-999999");
    test::Spit(ds.journal(), text + bad);
    auto s = Session::Open(ds.dir());
    REQUIRE(!s.ok());
    CHECK(s.error().find("annotations.journal.jsonl:3: \"id\": \"villa-999999\" is not in layouts.jsonl") != std::string::npos);
  }
  SECTION("a state whose layout does not parse") {
    std::string bad = first;
    bad.replace(bad.find("shapely.box(0, 0, 6, 5)"), 23, "shapely.box(0, 0, 6)");
    test::Spit(ds.journal(), text + bad);
    auto s = Session::Open(ds.dir());
    REQUIRE(!s.ok());
    CHECK(s.error().find("annotations.journal.jsonl:3: state.layout") != std::string::npos);
    CHECK(s.error().find("living-room_0/0") != std::string::npos);
  }
}

TEST_CASE("bad datasets give messages naming the file and line", "[dataset]") {
  test::TempDataset ds;
  SECTION("missing folder") {
    auto s = Session::Open(ds.dir() / "nope");
    REQUIRE(!s.ok());
    CHECK(s.error().find("no such dataset folder") != std::string::npos);
  }
  SECTION("a layout that does not parse") {
    std::string text = test::Slurp(LayoutsPath(ds.dir()));
    text.replace(text.find("shapely.box(0, 6, 4, 10)"), 24, "shapely.box(0, 6, 4, x)");
    test::Spit(LayoutsPath(ds.dir()), text);
    auto s = Session::Open(ds.dir());
    REQUIRE(!s.ok());
    CHECK(s.error().find("layouts.jsonl:2") != std::string::npos);
    CHECK(s.error().find("utility-room_0/0") != std::string::npos);
  }
  SECTION("a repeated id") {
    std::string text = test::Slurp(LayoutsPath(ds.dir()));
    text += text.substr(0, text.find('\n') + 1);
    test::Spit(LayoutsPath(ds.dir()), text);
    auto s = Session::Open(ds.dir());
    REQUIRE(!s.ok());
    CHECK(s.error().find("layouts.jsonl:5: \"id\": \"villa-000000\" repeats line 1") != std::string::npos);
  }
}

TEST_CASE("auto mode applies drafted labels, fixes and descriptions, never verified, deterministic", "[auto]") {
  test::TempDataset a, b;
  std::string export_a, export_b;
  for (auto* ds : {&a, &b}) {
    auto s = test::OpenSession(ds->dir(), true);
    auto made = s->AutoAnnotate();
    REQUIRE(made.ok());
    CHECK(made->automatic == 3);
    CHECK(made->rejected == 1);
    (ds == &a ? export_a : export_b) = s->ExportJsonl();
  }
  CHECK(export_a == export_b);
  // Replayed from the journal, the export is the same bytes again.
  auto again = test::OpenSession(a.dir(), false);
  CHECK(again->ExportJsonl() == export_a);

  // Contents: keys, statuses, final room names, the fixed kitchen window, the rejection reason.
  std::istringstream lines(export_a);
  std::string line;
  std::vector<Json> records;
  while (std::getline(lines, line)) records.push_back(Json::parse(line));
  REQUIRE(records.size() == 4);
  for (const Json& r : records) {
    std::vector<std::string> keys;
    for (auto it = r.begin(); it != r.end(); ++it) keys.push_back(it.key());
    if (r["status"] == "rejected")
      CHECK(keys == std::vector<std::string>{"id", "status", "reason", "descriptions", "annotation", "layout"});
    else
      CHECK(keys == std::vector<std::string>{"id", "status", "descriptions", "annotation", "layout"});
    // Nobody looked at an auto layout: decided by --auto, no annotator, no time, drafted texts.
    CHECK(r["annotation"]["decided_by"] == "auto");
    CHECK(r["annotation"]["annotators"].empty());
    CHECK(r["annotation"]["seconds"] == 0);
    CHECK(r["annotation"]["origin"]["coarse"] == "drafted");
    CHECK(r["annotation"]["origin"]["fine"] == "drafted");
    CHECK(r["status"] != "verified");
    CHECK(r["descriptions"]["coarse"].get<std::string>().size() > 20);
    CHECK(r["descriptions"]["fine"].get<std::string>().size() > 20);
    auto layout = LayoutFromJson(r["layout"], "export");
    REQUIRE(layout.ok());
    if (r["status"] == "auto") CHECK(ValidateLayout(*layout).valid());
  }
  CHECK(records[0]["id"] == "villa-000000");
  CHECK(records[0]["status"] == "auto");
  CHECK(records[2]["status"] == "auto");
  CHECK(!records[2]["layout"]["rooms"].contains("room_0/0"));
  CHECK(records[2]["layout"]["windows"].contains("kitchen0_window"));
  CHECK(records[3]["status"] == "rejected");
  CHECK(records[3]["reason"].get<std::string>().find("auto: rule 8") == 0);
}

TEST_CASE("auto mode leaves what a person decided alone", "[auto]") {
  test::TempDataset ds;
  auto s = test::OpenSession(ds.dir(), true);
  std::string msg;
  REQUIRE(s->Reject(0, "rooms too small or too narrow to use", &msg).ok());
  REQUIRE(s->Accept(1, &msg).ok());
  auto made = s->AutoAnnotate();
  REQUIRE(made.ok());
  CHECK(made->total() == 2);
  CHECK(s->state(0).status == AnnotationStatus::kRejected);
  CHECK(s->state(0).reason == "rooms too small or too narrow to use");
  CHECK(s->state(1).status == AnnotationStatus::kVerified);
}

TEST_CASE("one writing session a dataset at a time", "[journal]") {
  test::TempDataset ds;
  auto first = test::OpenSession(ds.dir(), true);
  auto second = Session::Open(ds.dir());
  REQUIRE(!second.ok());
  CHECK(second.error().find("in use by another `villa annotate`") != std::string::npos);
  // Reading (--status, --export) still works.
  CHECK(Session::Open(ds.dir(), false).ok());
}
