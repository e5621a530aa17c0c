// The real `villa annotate` driven through a terminal (tmux: send-keys, capture-pane): label, accept,
// reject, fix, edit, quit, restart and find the state; kill -9 mid-session and find the journal replayed.
#include <signal.h>

#include <catch2/catch.hpp>

#include "annotator/session.h"
#include "terminal.h"
#include "test_support.h"

using namespace villa;
using namespace villa::annotator;
using test::HaveTmux;
using test::Quote;
using test::Terminal;

TEST_CASE("label, accept, reject, fix, edit, quit, and the restart finds it all", "[tui]") {
  // tmux is a declared dependency (scripts/install-deps.sh): without it the test fails, never skips.
  REQUIRE(HaveTmux());
  test::TempDataset ds;
  {
    Terminal term(ds.dir());
    REQUIRE_SCREEN(term, "villa-000000");
    REQUIRE_SCREEN(term, "pending 4");
    REQUIRE_SCREEN(term, "passes all ten rules");
    // Select room 4 (the bedroom) and make it an office.
    term.Keys("4");
    REQUIRE_SCREEN(term, ">4 bedroom_0/0");
    term.Keys("o");
    REQUIRE_SCREEN(term, "label bedroom_0/0 -> office_0/0");
    // Shown as done, so already in the journal.
    CHECK(test::Slurp(ds.journal()).find("label bedroom_0/0 -> office_0/0") != std::string::npos);
    term.Keys("a");
    REQUIRE_SCREEN(term, "verified 1");
    REQUIRE_SCREEN(term, "villa-000001");  // on to the next pending layout
    term.Keys("x");
    REQUIRE_SCREEN(term, "why?");
    term.Keys("3");
    REQUIRE_SCREEN(term, "rejected 1");
    REQUIRE_SCREEN(term, "villa-000002");
    // villa-000002's kitchen has no window: accept is refused, the fix repairs it.
    term.Keys("a");
    REQUIRE_SCREEN(term, "cannot accept");
    term.Keys("f");
    REQUIRE_SCREEN(term, "mechanical fixes");
    term.Keys("a");
    REQUIRE_SCREEN(term, "passes all ten rules");
    // Edit the coarse description in place.
    term.Keys("e");
    REQUIRE_SCREEN(term, "Enter: save");
    term.Keys("C-u");
    term.Type("A one-storey rectangular house with a kitchen.");
    term.Keys("Enter");
    REQUIRE_SCREEN(term, "(edited)");
    REQUIRE(term.Quit());
  }
  auto s = Session::Open(ds.dir(), false);
  REQUIRE(s.ok());
  const Session& session = **s;
  CHECK(session.state(0).status == AnnotationStatus::kVerified);
  CHECK(session.state(0).layout.FindRoom("office_0/0") >= 0);
  CHECK(session.state(1).status == AnnotationStatus::kRejected);
  CHECK(session.state(1).reason == PresetRejectReasons()[2]);
  CHECK(session.state(2).status == AnnotationStatus::kPending);
  CHECK(session.state(2).coarse == "A one-storey rectangular house with a kitchen.");
  CHECK(session.state(2).layout.windows.size() == 5);

  // Restart: resumes at the first pending layout with the counts as left.
  Terminal term(ds.dir());
  REQUIRE_SCREEN(term, "villa-000002");
  REQUIRE_SCREEN(term, "verified 1  rejected 1");
  REQUIRE_SCREEN(term, "A one-storey rectangular house");
  term.Keys("p");
  term.Keys("p");
  REQUIRE_SCREEN(term, "villa-000000");
  REQUIRE_SCREEN(term, "[verified]");
  REQUIRE_SCREEN(term, "office_0/0");
  REQUIRE(term.Quit());
}

TEST_CASE("kill -9 mid-session loses nothing that was shown as done", "[tui]") {
  // tmux is a declared dependency (scripts/install-deps.sh): without it the test fails, never skips.
  REQUIRE(HaveTmux());
  test::TempDataset ds;
  {
    Terminal term(ds.dir());
    REQUIRE_SCREEN(term, "villa-000000");
    term.Keys("3");
    term.Keys("m");
    REQUIRE_SCREEN(term, "label dining-room_0/0 -> meeting-room_0/0");
    term.Keys("r");
    REQUIRE_SCREEN(term, "redraft descriptions of villa-000000 (#1)");
    int pid = term.Pid();
    REQUIRE(pid > 0);
    REQUIRE(::kill(pid, SIGKILL) == 0);
    REQUIRE(term.WaitForExit());
  }
  auto s = Session::Open(ds.dir(), false);
  REQUIRE(s.ok());
  CHECK((*s)->warnings().empty());
  CHECK((*s)->state(0).layout.FindRoom("meeting-room_0/0") >= 0);
  CHECK((*s)->state(0).draft == 1);
  // And the tool itself shows it after the crash.
  Terminal term(ds.dir());
  REQUIRE_SCREEN(term, "meeting-room_0/0");
  term.Keys("u");
  REQUIRE_SCREEN(term, "undone: redraft");
  REQUIRE(term.Quit());
}

TEST_CASE("the screen is usable at 80x24 and uses 160x48", "[tui]") {
  // tmux is a declared dependency (scripts/install-deps.sh): without it the test fails, never skips.
  REQUIRE(HaveTmux());
  test::TempDataset ds;
  for (auto [w, h] : {std::pair{80, 24}, std::pair{160, 48}}) {
    Terminal term(ds.dir(), w, h);
    REQUIRE_SCREEN(term, "villa-000000");
    std::string screen = term.Screen();
    INFO(screen);
    // Plan, room list, rule status, both descriptions and the status line are all on screen.
    CHECK(screen.find("┌") != std::string::npos);
    CHECK(screen.find("1 living") != std::string::npos);
    CHECK(screen.find("5 bathroom_0/0") != std::string::npos);
    CHECK(screen.find("passes all ten rules") != std::string::npos);
    CHECK(screen.find("Coarse") != std::string::npos);
    CHECK(screen.find("Fine") != std::string::npos);
    CHECK(screen.find("pending 4") != std::string::npos);
    term.Keys("?");
    REQUIRE_SCREEN(term, "villa annotate: keys");
    // Esc and a key within the escape delay read as Alt-key, as in every terminal program: wait for
    // the help to close, as a person sees it close, before the next key.
    term.Keys("Escape");
    REQUIRE(term.WaitGone("villa annotate: keys"));
    REQUIRE(term.Quit());
  }
}

TEST_CASE("both descriptions edited in $EDITOR", "[tui]") {
  // tmux is a declared dependency (scripts/install-deps.sh): without it the test fails, never skips.
  REQUIRE(HaveTmux());
  test::TempDataset ds;
  // An "editor" that rewrites the file: a new coarse text and a new fine text under the marker lines
  // (kept), the fine one over two lines of one paragraph.
  std::filesystem::path editor = ds.dir() / "editor.sh";
  test::Spit(editor,
             "#!/bin/sh\n"
             "coarse=$(grep '^# ---- coarse' \"$1\")\n"
             "fine=$(grep '^# ---- fine' \"$1\")\n"
             "printf '# a comment\\n%s\\nA small house.\\n%s\\nOne floor, with a kitchen\\nopen to the dining room.\\n' "
             "\"$coarse\" \"$fine\" > \"$1\"\n");
  std::filesystem::permissions(editor, std::filesystem::perms::owner_all);
  {
    Terminal term(ds.dir(), 80, 24, "VISUAL= EDITOR=" + Quote(editor.string()));
    REQUIRE_SCREEN(term, "villa-000000");
    term.Keys("v");
    REQUIRE_SCREEN(term, "edit descriptions of villa-000000");
    REQUIRE(term.Quit());
  }
  auto s = Session::Open(ds.dir(), false);
  REQUIRE(s.ok());
  CHECK((*s)->state(0).coarse == "A small house.");
  CHECK((*s)->state(0).fine == "One floor, with a kitchen open to the dining room.");
  CHECK((*s)->state(0).edited(DescriptionField::kCoarse));
  CHECK((*s)->state(0).edited(DescriptionField::kFine));
}
