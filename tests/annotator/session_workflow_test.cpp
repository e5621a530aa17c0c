// The session's side of working through a large set: journal format 2 (annotator, seconds, a flag per
// description) and reading format-1 journals, filters and go-to, drafts that survive a crash, the
// warnings before accepting and before overturning another person's decision.
#include <catch2/catch.hpp>

#include "annotator/session.h"
#include "layout/layout_io.h"
#include "test_support.h"

using namespace villa;
using namespace villa::annotator;

namespace {

std::vector<JournalJson> JournalLines(const test::TempDataset& ds) {
  std::vector<JournalJson> out;
  std::istringstream in(test::Slurp(ds.journal()));
  for (std::string line; std::getline(in, line);) out.push_back(JournalJson::parse(line));
  return out;
}

int RoomIndex(const Session& s, int item, const std::string& name) { return s.state(item).layout.FindRoom(name); }

}  // namespace

TEST_CASE("a journal written by the previous version (format 1) replays to the same states", "[journal][compat]") {
  test::TempDataset ds;
  std::filesystem::copy_file(test::FixtureLayouts("journal-v1.jsonl"), ds.journal());
  auto s = test::OpenSession(ds.dir(), true, "alice");
  CHECK(s->warnings().empty());
  // The old export, key by key: the same statuses, reasons, descriptions and layouts.
  std::istringstream old_export(test::Slurp(test::FixtureLayouts("journal-v1.export.jsonl")));
  std::istringstream new_export(s->ExportJsonl());
  std::string a, b;
  int records = 0;
  while (std::getline(old_export, a) && std::getline(new_export, b)) {
    Json before = Json::parse(a), after = Json::parse(b);
    for (auto it = before.begin(); it != before.end(); ++it) CHECK(after[it.key()] == it.value());
    ++records;
  }
  CHECK(records == 4);
  // Format 1 had one "edited" flag: it counts for both descriptions.
  CHECK(s->state(2).edited(DescriptionField::kCoarse));
  CHECK(s->state(2).edited(DescriptionField::kFine));
  CHECK(!s->state(0).edited(DescriptionField::kCoarse));
  // No annotator was recorded then: no names, no decider to overturn.
  CHECK(s->effort(0).annotators.empty());
  CHECK(s->OverturnWarning(1).empty());
  // Undo still reaches into the old history (the last person's action: villa-000003's edit).
  int item = -1;
  std::string msg;
  REQUIRE(s->Undo(&item, &msg).ok());
  CHECK(item == 3);
  // New lines are appended in format 2, and the mixed journal reads back.
  REQUIRE(s->Accept(0, &msg).ok());  // already verified: nothing written
  REQUIRE(s->Reject(0, "duplicate of another layout", &msg).ok());
  auto lines = JournalLines(ds);
  CHECK(lines.back()["v"] == 2);
  CHECK(lines.back()["annotator"] == "alice");
  CHECK(lines[0].count("v") == 0);
  auto again = test::OpenSession(ds.dir(), false, "bob");
  CHECK(again->state(0).status == AnnotationStatus::kRejected);
  CHECK(again->state(0).decided_by == "alice");
}

TEST_CASE("format-2 lines stay readable by format-1 readers: the keys they need, the kinds they know", "[journal][compat]") {
  test::TempDataset ds;
  auto s = test::OpenSession(ds.dir(), true, "alice");
  std::string msg;
  REQUIRE(s->SetDescription(0, DescriptionField::kCoarse, "A small house with a kitchen.", &msg).ok());
  REQUIRE(s->Accept(0, &msg).ok());
  int item = -1;
  REQUIRE(s->Undo(&item, &msg).ok());
  REQUIRE(s->Redo(&item, &msg).ok());
  REQUIRE(s->AutoAnnotate().ok());
  for (const JournalJson& line : JournalLines(ds)) {
    INFO(line.dump().substr(0, 200));
    for (const char* key : {"seq", "time", "id", "kind", "action", "state"}) CHECK(line.contains(key));
    std::string kind = line["kind"];
    CHECK((kind == "do" || kind == "undo" || kind == "redo" || kind == "batch"));
    const JournalJson& state = line["state"];
    for (const char* key : {"status", "descriptions", "edited", "draft", "layout"}) CHECK(state.contains(key));
    CHECK(state["edited"].is_boolean());
    CHECK(state["edited"] == (state["origin"]["coarse"] != "drafted" || state["origin"]["fine"] != "drafted"));
  }
}

TEST_CASE("lines of a newer format are read as far as this version understands them", "[journal][compat]") {
  test::TempDataset ds;
  {
    auto s = test::OpenSession(ds.dir(), true, "alice");
    std::string msg;
    REQUIRE(s->Reject(1, "staircase badly placed", &msg).ok());
  }
  std::string line = test::Slurp(ds.journal());
  line.replace(line.find("\"v\":2"), 5, "\"v\":3");
  line.replace(line.find("\"kind\":\"do\""), 11, "\"kind\":\"comment\"");
  test::Spit(ds.journal(), line, true);
  auto s = test::OpenSession(ds.dir(), false, "alice");
  REQUIRE(s->warnings().size() == 1);
  CHECK(s->warnings()[0].find("newer villa (journal format 3)") != std::string::npos);
  CHECK(s->state(1).status == AnnotationStatus::kRejected);
}

TEST_CASE("each description has its own flag: a relabel redrafts the one nobody edited", "[session]") {
  test::TempDataset ds;
  auto s = test::OpenSession(ds.dir(), true, "alice");
  std::string msg;
  std::string fine = s->state(0).fine;
  REQUIRE(s->SetDescription(0, DescriptionField::kCoarse, "A one-storey house with a bedroom.", &msg).ok());
  CHECK(s->state(0).coarse_origin == TextOrigin::kWritten);  // few of the draft's words
  CHECK(s->state(0).fine_origin == TextOrigin::kDrafted);
  REQUIRE(s->Relabel(0, RoomIndex(*s, 0, "bedroom_0/0"), Category::kOffice, &msg).ok());
  CHECK(s->state(0).coarse == "A one-storey house with a bedroom.");
  CHECK(s->state(0).fine != fine);
  CHECK(s->state(0).fine.find("office") != std::string::npos);
  // The edited text names a bedroom the layout no longer has.
  auto warnings = s->AcceptWarnings(0);
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0] == "the coarse description names a bedroom, which the layout no longer has");
  // A small change to a draft is an edit, not a text of one's own.
  std::string edited = s->state(1).fine + " Please add a fireplace.";
  REQUIRE(s->SetDescription(1, DescriptionField::kFine, edited, &msg).ok());
  CHECK(s->state(1).fine_origin == TextOrigin::kEdited);
  auto exported = Json::parse(s->ExportJsonl().substr(0, s->ExportJsonl().find('\n')));
  CHECK(exported["annotation"]["origin"]["coarse"] == "written");
  CHECK(exported["annotation"]["origin"]["fine"] == "drafted");
}

TEST_CASE("who did what and how long: annotator and seconds in the journal and the export", "[session]") {
  test::TempDataset ds;
  std::string msg;
  {
    auto s = test::OpenSession(ds.dir(), true, "alice");
    s->Spend(0, 12.4);
    s->Spend(0, 30);
    REQUIRE(s->Accept(0, &msg).ok());
    auto lines = JournalLines(ds);
    REQUIRE(lines.size() == 1);
    CHECK(lines[0]["annotator"] == "alice");
    CHECK(lines[0]["seconds"] == 42);
    CHECK(lines[0]["state"]["decided_by"] == "alice");
    // Accepting again is nothing: no line, no undo step.
    REQUIRE(s->Accept(0, &msg).ok());
    CHECK(msg.find("already verified") != std::string::npos);
    CHECK(JournalLines(ds).size() == 1);
    int item = -1;
    REQUIRE(s->Undo(&item, &msg).ok());
    CHECK(s->state(0).status == AnnotationStatus::kPending);
    CHECK(!s->CanUndo());
    REQUIRE(s->Redo(&item, &msg).ok());
  }
  auto s = test::OpenSession(ds.dir(), true, "bob");
  s->Spend(0, 5);
  REQUIRE(s->SetDescription(0, DescriptionField::kFine, s->state(0).fine + " With a garden.", &msg).ok());
  CHECK(s->effort(0).seconds == 47);
  CHECK(s->effort(0).annotators == std::vector<std::string>{"alice", "bob"});
  auto record = Json::parse(s->ExportJsonl().substr(0, s->ExportJsonl().find('\n')));
  CHECK(record["annotation"]["decided_by"] == "alice");
  CHECK(record["annotation"]["annotators"] == Json::array({"alice", "bob"}));
  CHECK(record["annotation"]["seconds"] == 47);
  CHECK(record["annotation"]["origin"]["fine"] == "edited");
  // bob overturning alice's decision is flagged; alice changing her own is not.
  REQUIRE(s->Reject(1, "staircase badly placed", &msg).ok());
  CHECK(s->OverturnWarning(0) == "villa-000000 was verified by alice");
  CHECK(s->OverturnWarning(1).empty());
  auto alice = test::OpenSession(ds.dir(), false, "alice");
  CHECK(alice->OverturnWarning(1) == "villa-000001 was rejected by bob: staircase badly placed");
  REQUIRE(alice->history(0).size() == 4);  // accept, undo, redo, bob's edit
  CHECK(alice->history(0)[0].annotator == "alice");
  CHECK(alice->history(0)[0].seconds == 42);
  CHECK(alice->history(0)[1].kind == "undo");
  CHECK(alice->history(0)[3].annotator == "bob");
}

TEST_CASE("filters, the next layout to do, and go-to", "[session]") {
  test::TempDataset ds;
  auto s = test::OpenSession(ds.dir(), true, "alice");
  std::string msg;
  REQUIRE(s->AutoAnnotate().ok());  // 0 1 2 auto, 3 rejected by --auto
  REQUIRE(s->Accept(1, &msg).ok());
  CHECK(s->NextToDo(0) == 0);
  CHECK(s->Step(0, +1, Filter::kAll, true) == 2);  // 1 is verified, 3 rejected
  CHECK(s->Step(2, +1, Filter::kAll, true) == 0);  // wraps around
  CHECK(s->Step(0, -1, Filter::kAll, false) == 3);
  CHECK(s->CountMatching(Filter::kToDo) == 2);
  CHECK(s->CountMatching(Filter::kAuto) == 2);
  CHECK(s->CountMatching(Filter::kRejected) == 1);
  CHECK(s->CountMatching(Filter::kVerified) == 1);
  CHECK(s->CountMatching(Filter::kDecided) == 1);  // --auto's rejection is no person's decision
  CHECK(s->Step(3, +1, Filter::kRejected, false) == 3);
  CHECK(s->Step(0, +1, Filter::kPending, false) == -1);
  CHECK(*s->FindItem("villa-000002") == 2);
  CHECK(*s->FindItem("3") == 3);
  CHECK(*s->FindItem("#2") == 1);
  CHECK(*s->FindItem("0") == 0);
  CHECK(s->FindItem("#9").error().find("positions run from #1 to #4") != std::string::npos);
  CHECK(!s->FindItem("villa-9").ok());
  CHECK(ParseFilter("to-do") == Filter::kToDo);
  CHECK(!ParseFilter("finished"));
}

TEST_CASE("typed text kept as a draft survives the session, and goes when saved", "[session][drafts]") {
  test::TempDataset ds;
  {
    auto s = test::OpenSession(ds.dir(), true, "alice");
    REQUIRE(s->KeepDraft(2, DescriptionField::kFine, "half a descr").ok());
    REQUIRE(s->KeepDraft(2, DescriptionField::kFine, "half a description").ok());
    // The session "dies" here.
  }
  CHECK(std::filesystem::exists(DraftsPath(ds.dir())));
  {
    auto s = test::OpenSession(ds.dir(), true, "alice");
    auto draft = s->Draft(2, DescriptionField::kFine);
    REQUIRE(draft);
    CHECK(draft->text == "half a description");
    CHECK(draft->annotator == "alice");
    CHECK(!s->Draft(2, DescriptionField::kCoarse));
    CHECK(s->OpenDrafts().size() == 1);
    std::string msg;
    REQUIRE(s->SetDescription(2, DescriptionField::kFine, "half a description, finished.", &msg).ok());
    CHECK(!s->Draft(2, DescriptionField::kFine));
    REQUIRE(s->KeepDraft(3, DescriptionField::kCoarse, "thrown away").ok());
    REQUIRE(s->DropDraft(3, DescriptionField::kCoarse).ok());
  }
  // Every draft saved or dropped: the draft journal is emptied on the next start.
  auto s = test::OpenSession(ds.dir(), true, "alice");
  CHECK(s->OpenDrafts().empty());
  CHECK(!std::filesystem::exists(DraftsPath(ds.dir())));
  CHECK(s->state(2).fine == "half a description, finished.");
}

TEST_CASE("annotator names are checked", "[session]") {
  CHECK(CheckAnnotatorName("alice").ok());
  CHECK(CheckAnnotatorName("Zoë Müller").ok());
  CHECK(!CheckAnnotatorName("").ok());
  CHECK(!CheckAnnotatorName("auto").ok());
  CHECK(!CheckAnnotatorName("a\tb").ok());
  CHECK(!CheckAnnotatorName(std::string(65, 'a')).ok());
  CHECK(!LoginName().empty());
}
