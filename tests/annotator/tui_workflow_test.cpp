// The workflow of a person verifying a large drafted set, through a real terminal (tmux): accept-and-next
// over --auto's drafts, resuming at the next layout to do, filters, go-to, who did what; text that
// survives kill -9 mid-edit; multi-line text and word editing; overturning another person's decision;
// all floors side by side with a north arrow on a wide terminal.
#include <signal.h>

#include <chrono>
#include <thread>

#include <catch2/catch.hpp>

#include "annotator/session.h"
#include "terminal.h"
#include "test_support.h"

using namespace villa;
using namespace villa::annotator;
using test::HaveTmux;
using test::Quote;
using test::Terminal;

namespace {

int RunVilla(const std::string& args) {
  int status = -1;
  test::RunShell(Quote(VILLA_BINARY) + " " + args + " >/dev/null 2>&1", &status);
  return status;
}

}  // namespace

TEST_CASE("verifying drafts: accept and next, resume, filters, go-to, who did what", "[tui][workflow]") {
  REQUIRE(HaveTmux());
  test::TempDataset ds;
  REQUIRE(RunVilla("annotate " + Quote(ds.dir().string()) + " --auto") == 0);  // 3 auto, villa-000003 rejected
  {
    Terminal term(ds.dir(), 80, 24, "", "--annotator alice");
    REQUIRE_SCREEN(term, "villa-000000");
    REQUIRE_SCREEN(term, "[auto]");
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));  // time spent looking at it
    term.Keys("a");                                                 // accept an auto layout, on to the next
    REQUIRE_SCREEN(term, "verified 1");
    REQUIRE_SCREEN(term, "villa-000001");
    term.Keys("Space");  // skip it: the next layout to do
    REQUIRE_SCREEN(term, "villa-000002");
    REQUIRE(term.Quit());
  }
  {
    auto s = test::OpenSession(ds.dir(), false);
    CHECK(s->state(0).status == AnnotationStatus::kVerified);
    CHECK(s->state(0).decided_by == "alice");
    CHECK(s->effort(0).seconds >= 1);
    CHECK(s->effort(0).annotators == std::vector<std::string>{"alice"});
  }
  Terminal term(ds.dir(), 80, 24, "", "--annotator alice");
  // Resumes at the first layout not verified (villa-000000 is done).
  REQUIRE_SCREEN(term, "villa-000001");
  // Filter: rejected ones only.
  term.Keys("F");
  REQUIRE_SCREEN(term, "show which layouts?");
  term.Keys("x");
  REQUIRE_SCREEN(term, "filter: rejected (1 layout)");
  REQUIRE_SCREEN(term, "villa-000003");
  term.Keys("n");
  REQUIRE_SCREEN(term, "villa-000003");  // the only one
  // Go to a layout by the end of its id.
  term.Keys("g");
  REQUIRE_SCREEN(term, "go to:");
  term.Type("2");
  term.Keys("Enter");
  REQUIRE_SCREEN(term, "villa-000002 (outside the filter rejected)");
  term.Keys("g");
  REQUIRE_SCREEN(term, "go to:");
  term.Type("#1");
  term.Keys("Enter");
  REQUIRE_SCREEN(term, "villa-000000");
  REQUIRE_SCREEN(term, "verified by alice");
  // Who did what.
  term.Keys("h");
  REQUIRE_SCREEN(term, "who did what on villa-000000");
  REQUIRE_SCREEN(term, "alice  accept villa-000000");
  term.Keys("Escape");
  REQUIRE(term.WaitGone("who did what"));
  REQUIRE(term.Quit());
}

TEST_CASE("text typed in the editor survives kill -9 and comes back", "[tui][workflow][drafts]") {
  REQUIRE(HaveTmux());
  test::TempDataset ds;
  {
    Terminal term(ds.dir());
    REQUIRE_SCREEN(term, "villa-000000");
    term.Keys("n");
    term.Keys("n");
    REQUIRE_SCREEN(term, "villa-000002");
    REQUIRE(term.EditCleared("E"));
    term.Type("A house for a family of five,");
    // The draft is kept within a second of a pause in the typing.
    std::this_thread::sleep_for(std::chrono::milliseconds(1600));
    REQUIRE(::kill(term.Pid(), SIGKILL) == 0);
    REQUIRE(term.WaitForExit());
  }
  CHECK(test::Slurp(DraftsPath(ds.dir())).find("A house for a family of five,") != std::string::npos);
  {
    Terminal term(ds.dir());
    // Opens on the layout with unsaved text and says so.
    REQUIRE_SCREEN(term, "recovered unsaved text of the fine description of villa-000002");
    REQUIRE_SCREEN(term, "villa-000002");
    term.Keys("E");
    REQUIRE_SCREEN(term, "A house for a family of five,");
    term.Type(" with a garden.");
    term.Keys("Enter");
    REQUIRE_SCREEN(term, "Fine (edited)");
    REQUIRE(term.Quit());
  }
  auto s = test::OpenSession(ds.dir(), false);
  CHECK(s->state(2).fine == "A house for a family of five, with a garden.");
  CHECK(s->OpenDrafts().empty());
}

TEST_CASE("multi-line text and word editing in the editor", "[tui][workflow][editor]") {
  REQUIRE(HaveTmux());
  test::TempDataset ds;
  {
    Terminal term(ds.dir());
    REQUIRE_SCREEN(term, "villa-000000");
    REQUIRE(term.EditCleared("e"));
    term.Type("Line one");
    term.Keys("M-Enter");  // a line break; Enter alone saves
    term.Type("Line two extra");
    term.Keys("C-w");  // the last word goes
    term.Keys("BSpace");
    term.Keys("C-j");
    term.Type("Three big floors");
    term.Keys("C-Left");  // a word back
    term.Keys("M-d");     // the word after the cursor goes
    term.Type("storeys");
    term.Keys("Home");  // the line's start
    term.Type("- ");
    term.Keys("Enter");
    REQUIRE_SCREEN(term, "Coarse (edited)");
    REQUIRE_SCREEN(term, "Line one");
    REQUIRE(term.Quit());
  }
  CHECK(test::OpenSession(ds.dir(), false)->state(0).coarse == "Line one\nLine two\n- Three big storeys");
}

TEST_CASE("overturning another person's rejection asks first, and review shows who did what", "[tui][workflow]") {
  REQUIRE(HaveTmux());
  test::TempDataset ds;
  {
    std::string msg;
    REQUIRE(test::OpenSession(ds.dir(), true, "bob")->Reject(1, "staircase badly placed", &msg).ok());
  }
  {
    Terminal term(ds.dir(), 80, 24, "", "--annotator alice --id villa-000001");
    REQUIRE_SCREEN(term, "villa-000001");
    REQUIRE_SCREEN(term, "rejected by bob");
    term.Keys("a");
    REQUIRE_SCREEN(term, "was rejected by bob: staircase badly placed");
    term.Keys("n");  // no: leave it
    REQUIRE_SCREEN(term, "left as bob decided");
    CHECK(test::OpenSession(ds.dir(), false)->state(1).status == AnnotationStatus::kRejected);
    term.Keys("a");
    REQUIRE_SCREEN(term, "was rejected by bob");
    term.Keys("y");
    REQUIRE_SCREEN(term, "accept villa-000001");
    REQUIRE(term.Quit());
  }
  auto s = test::OpenSession(ds.dir(), false);
  CHECK(s->state(1).status == AnnotationStatus::kVerified);
  CHECK(s->state(1).decided_by == "alice");
  // Review: starts on what two people decided differently, with their names.
  Terminal term(ds.dir(), 80, 24, "", "--annotator carol --review");
  REQUIRE_SCREEN(term, "[disagreements: 1]");
  REQUIRE_SCREEN(term, "villa-000001");
  REQUIRE_SCREEN(term, "verified by alice");
  REQUIRE_SCREEN(term, "they disagree");
  REQUIRE_SCREEN(term, "bob: rejected");
  REQUIRE_SCREEN(term, "alice: verified");
  REQUIRE(term.Quit());
}

TEST_CASE("a wide terminal shows all floors side by side, with a north arrow", "[tui][screen]") {
  REQUIRE(HaveTmux());
  test::TempDataset ds;
  Terminal term(ds.dir(), 160, 40, "", "--id villa-000001");
  REQUIRE_SCREEN(term, "villa-000001");
  auto lines = term.Lines();
  INFO(term.Screen());
  REQUIRE(lines.size() > 2);
  // The caption row: both floors named, the current one marked, and the arrow.
  CHECK(lines[1].find("▸ ground floor") != std::string::npos);
  CHECK(lines[1].find("top floor") != std::string::npos);
  CHECK(lines[1].find("N↑") != std::string::npos);
  // Both plans: two top-left corners on one row.
  int rows_with_two = 0;
  for (const std::string& l : lines) {
    std::size_t first = l.find("┌");
    if (first != std::string::npos && l.find("┌", first + 1) != std::string::npos) ++rows_with_two;
  }
  CHECK(rows_with_two >= 1);
  CHECK(term.Screen().find("balcony") != std::string::npos);  // a room of the top floor
  term.Keys("]");
  REQUIRE_SCREEN(term, "▸ top floor");
  REQUIRE(term.Quit());
}
