#include "annotator/tui.h"

#ifndef NCURSES_WIDECHAR
#define NCURSES_WIDECHAR 1
#endif
#include <curses.h>
#include <langinfo.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <clocale>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "annotator/fixes.h"
#include "annotator/floorplan_canvas.h"
#include "annotator/key_input.h"
#include "annotator/screen_text.h"
#include "annotator/text_edit.h"
#include "annotator/utf8.h"
#include "layout/layout_io.h"
#include "layout/topology.h"
#include "layout/validate.h"
#include "render/palette.h"
#include "util/atomic_file.h"

namespace villa::annotator {
namespace {

using Clock = std::chrono::steady_clock;

// ---------------------------------------------------------------- keys and words

struct CategoryKey {
  int key;
  Category category;
};
const CategoryKey kCategoryKeys[] = {
    {'l', Category::kLivingRoom}, {'b', Category::kBedroom},      {'k', Category::kKitchen},
    {'w', Category::kBathroom},   {'d', Category::kDiningRoom},   {'c', Category::kChildrenRoom},
    {'o', Category::kOffice},     {'m', Category::kMeetingRoom},  {'s', Category::kUtilityRoom},
    {'y', Category::kBalcony},
};

// The filters offered by F, with their keys.
struct FilterKey {
  int key;
  Filter filter;
  const char* words;
};
const FilterKey kFilterKeys[] = {
    {'a', Filter::kAll, "all layouts"},
    {'t', Filter::kToDo, "to do: pending or auto (not yet looked at by a person)"},
    {'p', Filter::kPending, "pending"},
    {'u', Filter::kAuto, "auto (drafted by --auto)"},
    {'x', Filter::kRejected, "rejected"},
    {'v', Filter::kVerified, "verified"},
    {'d', Filter::kDecided, "decided by a person (verified or rejected)"},
    {'D', Filter::kDisagreements, "disagreements: two people decided differently"},
};

// layout.h's short name in lower case, for the legend and tight labels ("bed", "child", "utility").
std::string ShortName(Category c) {
  std::string name(CategoryShortName(c));
  for (char& ch : name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return name;
}

std::string Seconds(int seconds) {
  if (seconds < 60) return std::to_string(seconds) + " s";
  if (seconds < 3600) return std::to_string(seconds / 60) + " min " + std::to_string(seconds % 60) + " s";
  return std::to_string(seconds / 3600) + " h " + std::to_string(seconds % 3600 / 60) + " min";
}

// What a wait status says, for a person: "exited with code 1", "was killed by signal 9".
std::string ExitWords(int status) {
  if (status == -1) return "could not be started";
  if (WIFEXITED(status)) {
    int code = WEXITSTATUS(status);
    return "exited with code " + std::to_string(code) + (code == 127 ? " (command not found)" : "");
  }
  if (WIFSIGNALED(status)) return "was killed by signal " + std::to_string(WTERMSIG(status));
  return "stopped (wait status " + std::to_string(status) + ")";
}

// The descriptions in the $EDITOR file: paragraphs separated by a blank line (a description's line
// breaks), the lines of one paragraph joined by a space. Only the tool's marker lines are special:
// a line starting with '#' between them is text.
const char* kCoarseMarker = "# ---- coarse description ----";
const char* kFineMarker = "# ---- fine description ----";

std::string ToParagraphs(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '\n' ? std::string("\n\n") : std::string(1, c);
  return out;
}

std::string FromParagraphs(const std::vector<std::string>& lines) {
  std::string out, paragraph;
  auto flush = [&] {
    if (paragraph.empty()) return;
    out += (out.empty() ? "" : "\n") + paragraph;
    paragraph.clear();
  };
  for (std::string line : lines) {
    while (!line.empty() && (line.back() == ' ' || line.back() == '\t' || line.back() == '\r')) line.pop_back();
    std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos) {
      flush();
      continue;
    }
    if (!paragraph.empty()) paragraph += ' ';
    paragraph.append(line, start, std::string::npos);
  }
  flush();
  return out;
}

// ---------------------------------------------------------------- colours

enum Pair : short {
  kPairText = 1,
  kPairDim,
  kPairTitle,
  kPairGood,
  kPairBad,
  kPairWall,
  kPairDoor,
  kPairWindow,
  kPairEntrance,
  kPairSelected,
  kPairStatus,
  kPairKey,
  kPairCategory0,  // + category index: room fills
};

short CategoryPair(Category c) { return static_cast<short>(kPairCategory0 + static_cast<int>(c)); }

// The nearest xterm-256 colour of an sRGB colour (the 6x6x6 cube and the grey ramp).
[[maybe_unused]] short Xterm256(double r, double g, double b) {
  auto level = [](double v) {
    int x = static_cast<int>(std::lround(v * 255));
    return x < 48 ? 0 : x < 115 ? 1 : (x - 35) / 40;
  };
  int ri = level(r), gi = level(g), bi = level(b);
  static const int steps[] = {0, 95, 135, 175, 215, 255};
  double dr = steps[ri] - r * 255, dg = steps[gi] - g * 255, db = steps[bi] - b * 255;
  double cube_err = dr * dr + dg * dg + db * db;
  double grey = (r + g + b) / 3 * 255;
  int gi2 = std::clamp(static_cast<int>(std::lround((grey - 8) / 10)), 0, 23);
  double gv = 8 + gi2 * 10;
  double grey_err = (gv - r * 255) * (gv - r * 255) + (gv - g * 255) * (gv - g * 255) + (gv - b * 255) * (gv - b * 255);
  if (grey_err < cube_err) return static_cast<short>(232 + gi2);
  return static_cast<short>(16 + 36 * ri + 6 * gi + bi);
}

void InitColours() {
  if (!has_colors()) return;
  start_color();
  use_default_colors();
  bool rich = COLORS >= 256;
  init_pair(kPairText, -1, -1);
  init_pair(kPairDim, rich ? 244 : COLOR_WHITE, -1);
  init_pair(kPairTitle, COLOR_CYAN, -1);
  init_pair(kPairGood, COLOR_GREEN, -1);
  init_pair(kPairBad, COLOR_RED, -1);
  init_pair(kPairWall, -1, -1);
  init_pair(kPairDoor, rich ? 130 : COLOR_YELLOW, -1);
  init_pair(kPairWindow, rich ? 33 : COLOR_CYAN, -1);
  init_pair(kPairEntrance, rich ? 160 : COLOR_RED, -1);
  init_pair(kPairSelected, COLOR_BLACK, COLOR_YELLOW);
  init_pair(kPairStatus, COLOR_BLACK, rich ? 250 : COLOR_WHITE);
  init_pair(kPairKey, rich ? 25 : COLOR_BLUE, rich ? 250 : COLOR_WHITE);
  for (int i = 0; i < kCategoryCount; ++i) {
    Category c = static_cast<Category>(i);
    short bg = COLOR_WHITE;
    if (rich) {
      Rgb rgb = CategoryColor(c);
      bg = Xterm256(rgb.r, rgb.g, rgb.b);
    } else {
      static const short basic[] = {COLOR_WHITE, COLOR_YELLOW, COLOR_BLUE,  COLOR_RED,   COLOR_CYAN, COLOR_MAGENTA,
                                    COLOR_MAGENTA, COLOR_GREEN, COLOR_BLUE, COLOR_WHITE, COLOR_GREEN};
      bg = basic[i];
    }
    init_pair(CategoryPair(c), COLOR_BLACK, bg);
  }
}

// Bracketed paste: the terminal wraps a paste in ESC[200~ ... ESC[201~, so it arrives as one paste.
void BracketedPaste(bool on) {
  std::fputs(on ? "\033[?2004h" : "\033[?2004l", stdout);
  std::fflush(stdout);
}

// A line of a panel: text, colour, attributes.
struct Line {
  std::string text;
  short pair = kPairText;
  attr_t attr = A_NORMAL;
  bool starts_item = false;  // the first line of a wrapped item (a violation): counted when cut off
};

// ---------------------------------------------------------------- the app

class App {
 public:
  App(Session& session, const TuiOptions& options) : s_(session), options_(options), filter_(options.filter) {}
  int Run();

 private:
  // Input.
  bool ReadEvent(KeyEvent* event, int timeout_ms = -1);
  KeyEvent ReadKey();  // blocks

  // Drawing.
  void Draw();   // paints and refreshes
  void Paint();  // paints without refreshing (under a dialog)
  void Put(int y, int x, const std::string& text, short pair = kPairText, attr_t attr = A_NORMAL);
  std::string Shown(const std::string& text) const { return unicode_ ? text : AsciiOnly(text); }
  void DrawHeader(int w);
  void DrawPlans(int top, int left, int width, int height);
  void DrawPanel(int top, int left, int width, int height);
  void DrawStatus(int h, int w);
  void Modal(const std::string& title, const std::vector<std::string>& lines, int width);
  // A dialog's background, with the rows it stands on blanked a column either side, so that no
  // stray character of the screen below shows at its edges.
  void ClearBox(int top, int left, int width, int height);
  // A modal question; returns the key that answered it.
  KeyEvent Ask(const std::string& title, const std::vector<std::string>& lines, int width = 76);
  bool Confirm(const std::string& title, const std::vector<std::string>& lines);

  // Actions.
  bool Handle(const KeyEvent& event);
  bool HandleCommand(int ch);
  void Go(int item);
  void SelectRoom(int delta);
  void ChangeLevel(int delta);
  void Advance();  // after accept / reject: on to the next layout still to do in the filter
  void Act(const Status& status, const std::string& message);
  void Note(const std::string& message, bool bad = false);
  void Accept();
  void Reopen();
  void EditDescription(DescriptionField field);
  void Help();
  void RejectDialog();
  void FixDialog();
  void FilterDialog();
  void GoToDialog();
  void HistoryDialog();
  void EditInEditor();
  // The in-place editor. With `field` set, the text is a description of the current layout: multi-line,
  // journalled as a draft while typed, `recovered` its text from a draft. Returns the text, or nothing
  // when the person cancelled.
  std::optional<std::string> EditText(const std::string& title, const std::string& saved,
                                      std::optional<DescriptionField> field, const std::string* recovered = nullptr);

  const AnnotationState& state() const { return s_.state(item_); }
  const Layout& layout() const { return state().layout; }
  std::vector<int> LevelRooms() const { return layout().RoomsOnLevel(level_); }
  const ValidationReport& Report();

  Session& s_;
  TuiOptions options_;
  Filter filter_;
  int item_ = 0;
  int level_ = 0;
  int room_ = -1;  // index into layout().rooms, on level_
  std::string message_;
  bool message_bad_ = false;
  bool unicode_ = true;
  KeyDecoder decoder_;
  Clock::time_point last_input_ = Clock::now();
  int idle_errors_ = 0;
  // Validation cache: recomputed when the layout shown changes.
  int cached_item_ = -1;
  std::string cached_key_;
  ValidationReport report_;
  std::vector<Fix> fixes_;
};

// Time between keys counts for the layout on screen, up to this much (a person who walked away is not
// labelling).
constexpr double kIdleCapSeconds = 120;

bool App::ReadEvent(KeyEvent* event, int timeout_ms) {
  while (true) {
    if (decoder_.Next(event)) {
      auto now = Clock::now();
      double gap = std::chrono::duration<double>(now - last_input_).count();
      s_.Spend(item_, std::min(gap, kIdleCapSeconds));
      last_input_ = now;
      return true;
    }
    int held = decoder_.WaitMs();
    wtimeout(stdscr, held >= 0 ? held : timeout_ms);
    int c = wgetch(stdscr);
    if (c == ERR) {
      if (held >= 0) {
        decoder_.Timeout();
        continue;
      }
      if (timeout_ms >= 0) return false;
      // A blocking read that keeps failing: the terminal is gone. Leave as if q was pressed.
      if (++idle_errors_ > 100) {
        event->kind = KeyKind::kChar;
        event->ch = 'q';
        return true;
      }
      continue;
    }
    idle_errors_ = 0;
    if (c == KEY_RESIZE) {
      event->kind = KeyKind::kKey;
      event->key = Key::kNone;
      event->text = "resize";
      return true;
    }
    if (c < 0 || c > 255) continue;  // keypad is off: no other key codes come
    decoder_.Feed(static_cast<unsigned char>(c));
  }
}

KeyEvent App::ReadKey() {
  KeyEvent e;
  while (!ReadEvent(&e)) {
  }
  return e;
}

const ValidationReport& App::Report() {
  std::string key = LayoutToString(layout(), -1);
  if (cached_item_ != item_ || cached_key_ != key) {
    report_ = ValidateLayout(layout());
    fixes_ = FindFixes(layout());
    cached_item_ = item_;
    cached_key_ = std::move(key);
  }
  return report_;
}

void App::Put(int y, int x, const std::string& text, short pair, attr_t attr) {
  attr_set(attr, pair, nullptr);
  mvaddstr(y, x, text.c_str());
  attr_set(A_NORMAL, kPairText, nullptr);
}

void App::Go(int item) {
  if (item < 0 || item >= s_.size()) return;
  item_ = item;
  level_ = 0;
  auto rooms = LevelRooms();
  room_ = rooms.empty() ? -1 : rooms[0];
}

void App::Advance() {
  int next = s_.Step(item_, +1, filter_, true);
  if (next < 0 || next == item_) {
    message_ += filter_ == Filter::kAll ? "; nothing left to do" : "; nothing left to do in filter " + std::string(FilterName(filter_));
    return;
  }
  message_ += "; next: " + s_.record(next).id;
  Go(next);
}

void App::SelectRoom(int delta) {
  auto rooms = LevelRooms();
  if (rooms.empty()) return;
  auto it = std::find(rooms.begin(), rooms.end(), room_);
  int pos = it == rooms.end() ? 0 : static_cast<int>(it - rooms.begin());
  pos = (pos + delta + static_cast<int>(rooms.size())) % static_cast<int>(rooms.size());
  room_ = rooms[pos];
}

void App::ChangeLevel(int delta) {
  int floors = layout().LevelCount();
  level_ = std::clamp(level_ + delta, 0, std::max(0, floors - 1));
  auto rooms = LevelRooms();
  room_ = rooms.empty() ? -1 : rooms[0];
}

void App::Act(const Status& status, const std::string& message) {
  if (status)
    Note(message);
  else
    Note(status.error(), true);
}

void App::Note(const std::string& message, bool bad) {
  message_ = message;
  message_bad_ = bad;
}

// ---------------------------------------------------------------- drawing

void App::DrawHeader(int w) {
  const DatasetRecord& rec = s_.record(item_);
  int floors = layout().LevelCount();
  std::string shape = (rec.shape == "rectangle" ? "rectangular" : rec.shape == "irregular" ? "irregular" : rec.shape + "-shaped") +
                      std::string(", ") + std::to_string(floors) + (floors == 1 ? " floor" : " floors");
  std::string status(StatusName(state().status));
  std::string level = "level " + std::to_string(level_) + ": " + LevelName(level_, floors);
  std::string extra = filter_ == Filter::kAll ? "" : "filter: " + std::string(FilterName(filter_));
  std::string text = HeaderText(Shown(rec.id), std::to_string(item_ + 1) + "/" + std::to_string(s_.size()), shape, status,
                                level, extra, w);
  Put(0, 0, PadToWidth(text, w), kPairTitle, A_BOLD);
  // The status in its colour, where HeaderText put it.
  std::string tag = "[" + status + "]";
  std::size_t at = text.find(tag);
  if (at != std::string::npos) {
    short pair = state().status == AnnotationStatus::kVerified   ? kPairGood
                 : state().status == AnnotationStatus::kRejected ? kPairBad
                                                                  : kPairDim;
    Put(0, TextWidth(text.substr(0, at)), tag, pair, A_BOLD);
  }
}

void App::DrawPlans(int top, int left, int width, int height) {
  const Layout& l = layout();
  int floors = std::max(1, l.LevelCount());
  // All floors side by side when each still gets a legible plan: 30 columns or more, and a metre at
  // least one row (two columns), so a 4 m room is 8 cells wide.
  // The building's extent (m), all floors: the canvas scales every floor alike.
  double min_x = 1e300, max_x = -1e300, min_y = 1e300, max_y = -1e300;
  for (const Room& r : l.rooms)
    for (const Point& p : r.polygon) {
      min_x = std::min(min_x, p.x);
      max_x = std::max(max_x, p.x);
      min_y = std::min(min_y, p.y);
      max_y = std::max(max_y, p.y);
    }
  double extent_x = max_x - min_x, extent_y = max_y - min_y;
  int canvas_h = height - 1;  // the caption row above the plans
  int gap = 3;
  auto scale = [&](int w) {
    if (!(extent_x > 0) || !(extent_y > 0)) return 0.0;
    return std::min((canvas_h - 1) / extent_y, (w - 1) / (2.0 * extent_x));
  };
  int per = floors > 1 ? (width - gap * (floors - 1)) / floors : width;
  bool side = floors > 1 && per >= 30 && scale(per) >= 1.0;
  std::vector<int> shown;
  if (side)
    for (int f = 0; f < floors; ++f) shown.push_back(f);
  else
    shown.push_back(level_);
  int panel_w = side ? per : width;

  // The north arrow, top right: descriptions speak of the north, south, east and west of the house.
  std::string arrow = unicode_ ? "N↑" : "N^";
  for (std::size_t k = 0; k < shown.size(); ++k) {
    int f = shown[k];
    int x0 = left + static_cast<int>(k) * (panel_w + gap);
    std::string caption = LevelName(f, floors);
    bool current = f == level_;
    if (side) caption = (current ? (unicode_ ? "▸ " : "> ") : "  ") + caption;
    Put(top, x0, PadToWidth(caption, panel_w - (k + 1 == shown.size() ? 3 : 0)), current ? kPairTitle : kPairDim,
        current ? A_BOLD : A_NORMAL);

    CanvasOptions o;
    o.width = panel_w;
    o.height = canvas_h;
    o.unicode = unicode_;
    o.labels.resize(l.rooms.size());
    auto rooms = l.RoomsOnLevel(f);
    for (std::size_t i = 0; i < rooms.size(); ++i) {
      const Room& r = l.rooms[rooms[i]];
      std::string name(CategoryName(r.category));
      std::string s = ShortName(r.category);
      if (current) {
        std::string n = std::to_string(i + 1);
        o.labels[rooms[i]] = {n + " " + name, n + " " + s, n + " " + s.substr(0, 3), n};
      } else {
        o.labels[rooms[i]] = {name, s, s.substr(0, 3)};
      }
    }
    Canvas canvas = DrawFloorPlan(l, f, o);
    for (int y = 0; y < canvas.height; ++y) {
      for (int x = 0; x < canvas.width; ++x) {
        const CanvasCell& cell = canvas.at(x, y);
        short pair = kPairText;
        attr_t attr = A_NORMAL;
        std::string glyph = cell.glyph;
        switch (cell.kind) {
          case CellKind::kEmpty: break;
          case CellKind::kFloor:
          case CellKind::kStair:
          case CellKind::kLabel:
            pair = CategoryPair(l.rooms[cell.room].category);
            if (cell.room == room_ && current) {
              if (cell.kind == CellKind::kLabel)
                attr = A_BOLD | A_UNDERLINE;
              else if (cell.kind == CellKind::kFloor)
                glyph = unicode_ ? "·" : ".";
            }
            if (cell.kind == CellKind::kStair) attr |= A_DIM;
            if (!current) attr |= A_DIM;
            break;
          case CellKind::kWall: pair = kPairWall; attr = A_BOLD; break;
          case CellKind::kDoor: pair = kPairDoor; attr = A_BOLD; break;
          case CellKind::kOpen: break;
          case CellKind::kWindow: pair = kPairWindow; break;
          case CellKind::kPanoramic: pair = kPairWindow; attr = A_BOLD; break;
          case CellKind::kEntrance: pair = kPairEntrance; attr = A_BOLD; break;
        }
        Put(top + 1 + y, x0 + x, glyph, pair, attr);
      }
    }
  }
  Put(top, left + width - 2, arrow, kPairTitle, A_BOLD);
}

void App::DrawPanel(int top, int left, int width, int height) {
  const Layout& l = layout();
  auto rooms = LevelRooms();
  // Blocks, most important first; the descriptions get what is left.
  std::vector<Line> list;
  list.push_back({"Rooms on " + LevelName(level_, l.LevelCount()) + "  (Tab, 1-" + std::to_string(rooms.size()) + ")",
                  kPairTitle, A_BOLD});
  auto list_lines = RoomListLines(l, level_, room_, width, unicode_);

  // Who decided, and why a rejection: shown before the rules, so never cut off by them.
  std::vector<Line> who;
  const AnnotationState& st = state();
  bool decided = st.status == AnnotationStatus::kVerified || st.status == AnnotationStatus::kRejected;
  if (decided && (!st.decided_by.empty() || !st.reason.empty())) {
    std::string text = std::string(StatusName(st.status));
    std::string reason = st.reason;
    if (st.decided_by == kAutoAnnotator) {
      text += " by --auto";
      if (reason.rfind("auto: ", 0) == 0) reason = reason.substr(6);
    } else if (!st.decided_by.empty()) {
      text += " by " + st.decided_by;
    }
    int seconds = s_.effort(item_).seconds;
    if (seconds > 0) text += " (" + Seconds(seconds) + " on it in all)";
    if (st.status == AnnotationStatus::kRejected && !reason.empty()) text += ": " + reason;
    for (const std::string& w : WrapText(Shown(text), width))
      who.push_back({w, st.status == AnnotationStatus::kVerified ? kPairGood : kPairBad});
  }
  auto ratings = s_.Ratings(item_);
  if (ratings.size() >= 2 || options_.review) {
    for (const Rating& r : ratings)
      who.push_back({Shown("  " + r.annotator + ": " + (r.accepted ? "verified" : "rejected")),
                     r.accepted ? kPairGood : kPairBad});
    if (s_.Disagreement(item_)) who.push_back({"  they disagree", kPairBad, A_BOLD});
  }

  // The rules block as whole items: the verdict, then each violation (wrapped).
  std::vector<std::vector<Line>> rules;
  const ValidationReport& report = Report();
  if (report.valid()) {
    rules.push_back({{unicode_ ? "✓ passes all ten rules" : "OK passes all ten rules", kPairGood, A_BOLD}});
  } else {
    rules.push_back({{std::to_string(report.violations.size()) + " rule violation" + (report.violations.size() == 1 ? "" : "s") +
                          (fixes_.empty() ? "" : "   f: " + std::to_string(fixes_.size()) + " fix" + (fixes_.size() == 1 ? "" : "es")),
                      kPairBad, A_BOLD}});
    for (const Violation& v : report.violations) {
      auto wrapped = WrapText(Shown(std::to_string(v.rule) + ": " + v.message), width - 3);
      std::vector<Line> item;
      for (std::size_t i = 0; i < wrapped.size(); ++i)
        item.push_back({(i == 0 ? (unicode_ ? " ✗ " : " x ") : "   ") + wrapped[i], kPairBad, A_NORMAL, true});
      rules.push_back(std::move(item));
    }
  }

  // Room for each block: the list and who did what in full, the rules as far as they leave at least
  // four rows to the descriptions, then the descriptions.
  int y = top;
  int bottom = top + height;
  auto line = [&](const Line& ln) {
    if (y >= bottom) return;
    Put(y++, left, PadToWidth(ln.text, width), ln.pair, ln.attr);
  };
  line(list[0]);
  int room_rows = std::min<int>(static_cast<int>(list_lines.size()), std::max(1, bottom - y - 6));
  for (int i = 0; i < room_rows; ++i) {
    const RoomListLine& rl = list_lines[i];
    bool selected = rl.room == room_;
    bool last_row = i == room_rows - 1 && room_rows < static_cast<int>(list_lines.size());
    std::string text = last_row ? PadToWidth("  ... " + std::to_string(list_lines.size() - i) + " more lines", width) : rl.text;
    Put(y, left, Shown(text), selected ? kPairSelected : kPairText, selected ? A_BOLD : A_NORMAL);
    if (rl.first && !last_row) Put(y, left + rl.swatch, " ", CategoryPair(l.rooms[rl.room].category));
    ++y;
  }
  for (const Line& ln : who) line(ln);
  // Whole items only, as many as leave four rows to the descriptions; then how many violations are left.
  int rule_room = std::max(1, bottom - y - 4);
  int used = 0;
  std::size_t shown = 0;
  for (; shown < rules.size(); ++shown) {
    int need = static_cast<int>(rules[shown].size());
    int reserve = shown + 1 < rules.size() ? 1 : 0;  // the "... more" line
    if (shown > 0 && used + need + reserve > rule_room) break;
    for (const Line& ln : rules[shown]) line(ln);
    used += need;
  }
  int hidden = 0;
  for (std::size_t k = shown; k < rules.size(); ++k) hidden += !rules[k].empty() && rules[k][0].starts_item;
  if (hidden > 0)
    line({"  ... " + std::to_string(hidden) + " more violation" + (hidden == 1 ? "" : "s") + (fixes_.empty() ? "" : " (f: fixes)"),
          kPairBad});

  // Descriptions share what is left.
  int left_rows = bottom - y;
  int spare = left_rows;
  if (left_rows >= 4) {
    int inner = width - 2;
    auto coarse = WrapText(Shown(st.coarse), inner);
    auto fine = WrapText(Shown(st.fine), inner);
    int avail = left_rows - 2;
    int coarse_rows = std::min<int>(static_cast<int>(coarse.size()), std::max(1, avail / 3));
    int fine_rows = std::min<int>(static_cast<int>(fine.size()), avail - coarse_rows);
    spare = avail - coarse_rows - fine_rows;
    // Joins of the selected room, by full name, when there is room for them.
    if (room_ >= 0 && spare >= 3) {
      std::vector<std::string> joins;
      for (const Connection& c : RoomConnections(l)) {
        if (c.room_a != room_ && c.room_b != room_) continue;
        int other = c.room_a == room_ ? c.room_b : c.room_a;
        joins.push_back(l.rooms[other].name() + (c.via == Via::kDoor ? " (door)" : c.via == Via::kOpen ? " (open)" : " (stairs)"));
      }
      std::string text = l.rooms[room_].name() + " joins ";
      for (std::size_t i = 0; i < joins.size(); ++i) text += (i ? ", " : "") + joins[i];
      if (joins.empty()) text += "nothing";
      auto wrapped = WrapText(text, width - 2);
      if (static_cast<int>(wrapped.size()) + 1 <= spare) {
        for (const std::string& w : wrapped) line({"  " + w, kPairDim});
        spare -= static_cast<int>(wrapped.size());
      }
    }
    auto tag = [&](DescriptionField f) {
      std::string t = st.edited(f) ? " (edited)" : " (draft)";
      if (s_.Draft(item_, f)) t += unicode_ ? " · unsaved text kept" : " - unsaved text kept";
      return t;
    };
    line({"Coarse" + tag(DescriptionField::kCoarse) + "  e: edit", kPairTitle, A_BOLD});
    for (int i = 0; i < coarse_rows; ++i) {
      bool last = i == coarse_rows - 1 && static_cast<int>(coarse.size()) > coarse_rows;
      line({"  " + (last ? ClipToWidth(coarse[i], inner - 3) + "..." : coarse[i])});
    }
    line({"Fine" + tag(DescriptionField::kFine) + "  E: edit  r: redraft", kPairTitle, A_BOLD});
    for (int i = 0; i < fine_rows; ++i) {
      bool last = i == fine_rows - 1 && static_cast<int>(fine.size()) > fine_rows;
      line({"  " + (last ? ClipToWidth(fine[i], inner - 3) + "..." : fine[i])});
    }
  }
  while (y < bottom) line({""});
}

void App::DrawStatus(int h, int w) {
  Counts c = s_.counts();
  std::string counts = " " + std::to_string(item_ + 1) + "/" + std::to_string(s_.size()) + "  verified " +
                       std::to_string(c.verified) + "  rejected " + std::to_string(c.rejected) + "  auto " +
                       std::to_string(c.automatic) + "  pending " + std::to_string(c.pending) + " ";
  if (filter_ != Filter::kAll)
    counts += " [" + std::string(FilterName(filter_)) + ": " + std::to_string(s_.CountMatching(filter_)) + "] ";
  std::string keys = " ?:help a:accept x:reject f:fix u:undo n/p space:next to do g:go F:filter q:quit";
  std::string legend;
  for (const auto& k : kCategoryKeys) legend += std::string(1, static_cast<char>(k.key)) + ":" + ShortName(k.category) + " ";
  // Line h-2: the last message; line h-1: counts and keys.
  Put(h - 2, 0, PadToWidth(Shown(message_.empty() ? " " + legend : " " + message_), w), message_bad_ ? kPairBad : kPairDim,
      message_bad_ ? A_BOLD : A_NORMAL);
  Put(h - 1, 0, PadToWidth(counts, w), kPairStatus, A_BOLD);
  if (TextWidth(counts) < w) Put(h - 1, TextWidth(counts), PadToWidth(keys, w - TextWidth(counts)), kPairStatus);
}

void App::Draw() {
  Paint();
  refresh();
}

void App::Paint() {
  erase();
  int h, w;
  getmaxyx(stdscr, h, w);
  if (h < 12 || w < 50) {
    Put(0, 0, ClipToWidth("villa annotate needs at least 50x12 (now " + std::to_string(w) + "x" + std::to_string(h) + ")", w));
    return;
  }
  DrawHeader(w);
  int panel = std::clamp(w * 45 / 100, 34, 78);
  // Wide terminals with several floors: the plans get more, so the floors can stand side by side.
  if (layout().LevelCount() > 1 && w >= 140) panel = std::clamp(w * 34 / 100, 50, 64);
  int plan = w - panel - 1;
  int body_top = 1, body_h = h - 3;
  DrawPlans(body_top, 0, plan, body_h);
  for (int y = body_top; y < body_top + body_h; ++y) Put(y, plan, unicode_ ? "│" : "|", kPairDim);
  DrawPanel(body_top, plan + 1, panel, body_h);
  DrawStatus(h, w);
}

void App::ClearBox(int top, int left, int width, int height) {
  int w = getmaxx(stdscr);
  int from = std::max(0, left - 1), to = std::min(w, left + width + 1);
  for (int y = 0; y < height; ++y) {
    Put(top + y, from, std::string(static_cast<std::size_t>(to - from), ' '));
    Put(top + y, left, std::string(static_cast<std::size_t>(width), ' '), kPairStatus);
  }
}

void App::Modal(const std::string& title, const std::vector<std::string>& lines, int width) {
  int h, w;
  getmaxyx(stdscr, h, w);
  width = std::min(width, w - 2);
  int height = std::min(static_cast<int>(lines.size()) + 2, h - 2);
  int top = (h - height) / 2, left = (w - width) / 2;
  ClearBox(top, left, width, height);
  Put(top, left + 1, ClipToWidth(Shown(" " + title + " "), width - 2), kPairStatus, A_BOLD);
  for (int i = 0; i < height - 2; ++i) Put(top + 1 + i, left + 1, PadToWidth(Shown(lines[i]), width - 2), kPairStatus);
  refresh();
}

KeyEvent App::Ask(const std::string& title, const std::vector<std::string>& lines, int width) {
  while (true) {
    Paint();
    Modal(title, lines, width);
    KeyEvent e = ReadKey();
    if (e.kind == KeyKind::kKey && e.text == "resize") continue;
    return e;
  }
}

bool App::Confirm(const std::string& title, const std::vector<std::string>& lines) {
  KeyEvent e = Ask(title, lines);
  return e.kind == KeyKind::kChar && !e.alt && (e.ch == 'y' || e.ch == 'Y');
}

void App::Help() {
  // Lines of at most 76 columns: the help fits an 80-column terminal.
  std::vector<std::string> lines = {
      "Tab, arrows, 1-9  select a room        [ ] PgUp PgDn  level down / up",
      "Category of the selected room:",
  };
  std::string cats;
  for (const auto& k : kCategoryKeys) {
    std::string entry = std::string(1, static_cast<char>(k.key)) + " " + std::string(CategoryName(k.category));
    if (TextWidth(cats) + TextWidth(entry) + 2 > 72) {
      lines.push_back("  " + cats);
      cats.clear();
    }
    cats += (cats.empty() ? "" : "  ") + entry;
  }
  lines.push_back("  " + cats);
  for (const char* s : {
           "a      accept, then on to the next layout to do (asks first when an",
           "       edited description names rooms the layout no longer has)",
           "x      reject (preset reasons or free text)    O  reopen (to pending)",
           "f      mechanical fixes for the rule violations",
           "e / E  edit the coarse / fine description    v  both in $EDITOR",
           "       Alt-Enter, Ctrl-J: new line   Alt-B/F, Ctrl-arrows: a word",
           "       Ctrl-W, Alt-D: delete a word   Ctrl-U: clear   Esc: cancel",
           "r      redraft the descriptions        u / U, Ctrl-R  undo / redo",
           "space  next layout to do (pending or auto)    n / p  next / previous",
           "g      go to a layout: its id, its last digits, or #position",
           "F      filter: to do, pending, auto, rejected, verified, decided, ...",
           "h      who did what on this layout, and how long it took",
           "q      quit (everything is already saved); Ctrl-C too"}) {
    lines.push_back(s);
  }
  lines.push_back(unicode_ ? "Plan: door ▒  open: gap  window ═ ║  panoramic █  entrance ▓  stairs ≡  N↑"
                           : "Plan: door #  open: gap  window = H  panoramic %  entrance E  stairs _  N^");
  Ask("villa annotate: keys (any key: back; every action is journalled first)", lines, 78);
}

std::optional<std::string> App::EditText(const std::string& title, const std::string& saved,
                                         std::optional<DescriptionField> field, const std::string* recovered) {
  bool multiline = field.has_value();
  TextEdit t(saved);
  if (recovered) {
    t.Clear();
    t.Insert(*recovered);
  } else {
    t.TextEnd();
  }
  std::string kept = recovered ? *recovered : saved;  // the text last journalled as a draft
  auto kept_at = Clock::now();
  std::string note;         // a line under the text: why a key did nothing, draft trouble
  bool asking = false;      // Esc on changed text: asking whether to throw it away
  auto keep_draft = [&] {
    if (!field || t.Text() == kept) return;
    Status s = s_.KeepDraft(item_, *field, t.Text());
    if (s) {
      kept = t.Text();
      kept_at = Clock::now();
    } else {
      note = "draft not kept: " + s.error();
    }
  };
  auto drop_draft = [&] {
    if (field) s_.DropDraft(item_, *field);
  };
  curs_set(1);
  while (true) {
    int h, w;
    getmaxyx(stdscr, h, w);
    int width = std::min(w - 4, 100);
    int inner = width - 2;
    auto rows = t.Wrap(inner - 1);  // one column spare for the cursor after the last character
    int height = std::clamp(static_cast<int>(rows.size()) + 4, 5, h - 2);
    int top = (h - height) / 2, left = (w - width) / 2;
    Paint();
    ClearBox(top, left, width, height);
    Put(top, left + 1, ClipToWidth(Shown(" " + title + " "), width - 2), kPairStatus, A_BOLD);
    int visible = height - 4;
    TextEdit::Cell cell = t.CursorCell(rows);
    int first_row = cell.row >= visible ? cell.row - visible + 1 : 0;
    for (int i = 0; i < visible && first_row + i < static_cast<int>(rows.size()); ++i)
      Put(top + 1 + i, left + 1, PadToWidth(Shown(t.RowText(rows[first_row + i])), inner), kPairText);
    std::string footer = asking ? "Discard your changes? y: discard   any other key: go on editing"
                         : multiline ? "Enter: save   Alt-Enter / Ctrl-J: new line   Esc: cancel   Ctrl-U: clear"
                                     : "Enter: OK   Esc: cancel   Ctrl-U: clear";
    Put(top + height - 2, left + 1, PadToWidth(note.empty() || asking ? footer : note, inner), kPairStatus,
        asking ? A_BOLD : A_DIM);
    move(top + 1 + cell.row - first_row, left + 1 + std::min(cell.column, inner - 1));
    refresh();

    KeyEvent e;
    bool dirty = field && t.Text() != kept;
    if (!ReadEvent(&e, dirty ? 1000 : -1)) {
      keep_draft();  // a pause in the typing
      continue;
    }
    if (asking) {
      asking = false;
      if (e.kind == KeyKind::kChar && !e.alt && (e.ch == 'y' || e.ch == 'Y')) {
        drop_draft();
        curs_set(0);
        return std::nullopt;
      }
      note.clear();
      continue;
    }
    note.clear();
    std::string before = t.Text();
    bool save = false, cancel = false;
    switch (e.kind) {
      case KeyKind::kEscape: cancel = true; break;
      case KeyKind::kPaste: {
        std::string text = e.text;
        if (!multiline) std::replace(text.begin(), text.end(), '\n', ' ');
        t.Insert(text);
        break;
      }
      case KeyKind::kIgnored: note = "ignored " + e.text + " (not a key this editor knows)"; break;
      case KeyKind::kKey:
        switch (e.key) {
          case Key::kLeft: (e.ctrl || e.alt) ? t.WordLeft() : t.Left(); break;
          case Key::kRight: (e.ctrl || e.alt) ? t.WordRight() : t.Right(); break;
          case Key::kUp: t.MoveRows(-1, inner - 1); break;
          case Key::kDown: t.MoveRows(+1, inner - 1); break;
          case Key::kPageUp: t.MoveRows(-visible, inner - 1); break;
          case Key::kPageDown: t.MoveRows(+visible, inner - 1); break;
          case Key::kHome: e.ctrl ? t.TextStart() : t.LineStart(); break;
          case Key::kEnd: e.ctrl ? t.TextEnd() : t.LineEnd(); break;
          case Key::kDelete: (e.ctrl || e.alt) ? t.DeleteWordForward() : t.DeleteForward(); break;
          case Key::kBackspace: (e.ctrl || e.alt) ? t.DeleteWordBack() : t.DeleteBack(); break;
          case Key::kEnter:
            if (e.alt && multiline)
              t.Insert("\n");
            else
              save = true;
            break;
          case Key::kTab: t.Insert(" "); break;
          default: break;  // function keys, Insert, BackTab, resize: nothing to do here
        }
        break;
      case KeyKind::kChar:
        if (e.alt) {
          switch (e.ch) {
            case 'b': case 'B': t.WordLeft(); break;
            case 'f': case 'F': t.WordRight(); break;
            case 'd': case 'D': t.DeleteWordForward(); break;
            default: note = "Alt-" + EncodeUtf8(e.ch) + " does nothing here: the text is unchanged"; break;
          }
          break;
        }
        switch (e.ch) {
          case 1: t.LineStart(); break;       // Ctrl-A
          case 5: t.LineEnd(); break;         // Ctrl-E
          case 2: t.Left(); break;            // Ctrl-B
          case 6: t.Right(); break;           // Ctrl-F
          case 4: t.DeleteForward(); break;   // Ctrl-D
          case 11: t.DeleteToLineEnd(); break;  // Ctrl-K
          case 21: t.Clear(); break;          // Ctrl-U
          case 23: t.DeleteWordBack(); break;  // Ctrl-W
          case 3: cancel = true; break;       // Ctrl-C: as Esc
          case '\n':                          // Ctrl-J
            if (multiline) t.Insert("\n");
            break;
          default:
            if (e.ch >= 0x20) t.Insert(EncodeUtf8(e.ch));
            break;
        }
        break;
    }
    if (save) {
      curs_set(0);
      std::string text = t.Text();
      // Surrounding blanks are no text.
      std::size_t a = text.find_first_not_of(" \n");
      std::size_t z = text.find_last_not_of(" \n");
      return a == std::string::npos ? std::string() : text.substr(a, z - a + 1);
    }
    if (cancel) {
      if (t.Modified()) {
        asking = true;
        continue;
      }
      drop_draft();
      curs_set(0);
      return std::nullopt;
    }
    if (t.Text() != before && std::chrono::duration<double>(Clock::now() - kept_at).count() >= 1.0) keep_draft();
  }
}

void App::EditDescription(DescriptionField field) {
  std::string saved = state().text(field);
  auto draft = s_.Draft(item_, field);
  std::string title = std::string(FieldName(field)) + " description of " + s_.record(item_).id +
                      (draft ? " (recovered unsaved text from " + draft->time + ")" : "");
  auto text = EditText(title, saved, field, draft ? &draft->text : nullptr);
  if (!text) {
    Note(std::string(FieldName(field)) + " description unchanged");
    return;
  }
  if (text->empty()) {
    s_.DropDraft(item_, field);
    Act(Error{"a description cannot be empty: unchanged"}, "");
    return;
  }
  std::string message;
  Act(s_.SetDescription(item_, field, *text, &message), message);
}

void App::EditInEditor() {
  const char* editor = std::getenv("VISUAL");
  if (!editor || !*editor) editor = std::getenv("EDITOR");
  if (!editor || !*editor) {
    Act(Error{"neither $VISUAL nor $EDITOR is set: e / E edit here"}, "");
    return;
  }
  std::filesystem::path path = std::filesystem::temp_directory_path() /
                               ("villa-annotate-" + std::to_string(::getpid()) + "-" + s_.record(item_).id + ".txt");
  std::string written = "# villa annotate: the descriptions of " + s_.record(item_).id +
                        ". Edit the text under each marker line and keep\n"
                        "# the marker lines. A blank line starts a new paragraph (a line break in the description).\n" +
                        kCoarseMarker + "\n" + ToParagraphs(state().coarse) + "\n" + kFineMarker + "\n" +
                        ToParagraphs(state().fine) + "\n";
  if (Status s = WriteFileAtomic(path, written); !s) {
    Act(s, "");
    return;
  }
  BracketedPaste(false);
  def_prog_mode();
  endwin();
  std::string command = std::string(editor) + " '" + path.string() + "'";
  int rc = std::system(command.c_str());
  reset_prog_mode();
  refresh();
  BracketedPaste(true);
  auto text = ReadFile(path);
  bool changed = text && *text != written;
  auto keep_or_remove = [&](const std::string& why) {
    if (changed) {
      Act(Error{why + ": descriptions unchanged; your text is kept in " + path.string()}, "");
    } else {
      std::filesystem::remove(path);
      Act(Error{why + ": descriptions unchanged"}, "");
    }
  };
  if (rc != 0) {
    keep_or_remove("the editor " + ExitWords(rc));
    return;
  }
  if (!text) {
    Act(Error{text.error()}, "");
    return;
  }
  std::vector<std::string> lines;
  std::istringstream in(*text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  auto coarse_at = std::find_if(lines.begin(), lines.end(), [](const std::string& l) { return l.rfind(kCoarseMarker, 0) == 0; });
  auto fine_at = std::find_if(coarse_at, lines.end(), [](const std::string& l) { return l.rfind(kFineMarker, 0) == 0; });
  if (coarse_at == lines.end() || fine_at == lines.end()) {
    keep_or_remove("the marker lines \"# ---- coarse/fine description ----\" are gone");
    return;
  }
  std::string coarse = FromParagraphs({coarse_at + 1, fine_at});
  std::string fine = FromParagraphs({fine_at + 1, lines.end()});
  if (coarse.empty() || fine.empty()) {
    keep_or_remove("a description came back empty");
    return;
  }
  std::filesystem::remove(path);
  std::string message;
  Act(s_.SetDescriptions(item_, coarse, fine, &message), message);
}

void App::RejectDialog() {
  if (std::string overturn = s_.OverturnWarning(item_);
      !overturn.empty() && state().status == AnnotationStatus::kVerified &&
      !Confirm("overturn another person's decision?", {overturn, "", "y: reject it anyway    any other key: leave it"})) {
    Note("left as " + state().decided_by + " decided");
    return;
  }
  const auto& presets = PresetRejectReasons();
  std::vector<std::string> lines;
  for (std::size_t i = 0; i < presets.size(); ++i) lines.push_back(std::to_string(i + 1) + "  " + presets[i]);
  lines.push_back("t  type a reason");
  lines.push_back("");
  lines.push_back("Esc: cancel");
  KeyEvent e = Ask("reject " + s_.record(item_).id + ": why?", lines, 74);
  std::string reason;
  int ch = e.kind == KeyKind::kChar && !e.alt ? static_cast<int>(e.ch) : 0;
  if (ch >= '1' && ch < '1' + static_cast<int>(presets.size())) {
    reason = presets[ch - '1'];
  } else if (ch == 't' || ch == '0') {
    auto text = EditText("reason for rejecting " + s_.record(item_).id, "", std::nullopt);
    if (!text || text->empty()) {
      Act(Error{"reject cancelled"}, "");
      return;
    }
    reason = *text;
  } else {
    Note("reject cancelled");
    return;
  }
  std::string message;
  Status st = s_.Reject(item_, reason, &message);
  Act(st, message);
  if (st) Advance();
}

void App::FixDialog() {
  Report();
  if (fixes_.empty()) {
    Act(Error{report_.valid() ? "nothing to fix: the layout passes every rule"
                              : "no mechanical fix for these violations: relabel, edit or reject"},
        "");
    return;
  }
  std::vector<std::string> lines;
  for (std::size_t i = 0; i < fixes_.size() && i < 9; ++i)
    lines.push_back(std::to_string(i + 1) + "  rule " + std::to_string(fixes_[i].rule) + ": " + fixes_[i].title);
  lines.push_back("");
  lines.push_back("a / Enter: apply all    1-9: apply one    Esc: cancel");
  KeyEvent e = Ask("mechanical fixes", lines, 78);
  std::vector<Fix> chosen;
  if ((e.kind == KeyKind::kChar && !e.alt && e.ch == 'a') || (e.kind == KeyKind::kKey && e.key == Key::kEnter))
    chosen = fixes_;
  else if (e.kind == KeyKind::kChar && !e.alt && e.ch >= '1' && e.ch <= '9' && static_cast<int>(e.ch - '1') < static_cast<int>(fixes_.size()))
    chosen = {fixes_[e.ch - '1']};
  if (chosen.empty()) return;
  std::string message;
  Act(s_.ApplyFixes(item_, chosen, &message), message);
}

void App::FilterDialog() {
  std::vector<std::string> lines;
  for (const FilterKey& f : kFilterKeys)
    lines.push_back(std::string(1, static_cast<char>(f.key)) + "  " + f.words + "  (" +
                    std::to_string(s_.CountMatching(f.filter)) + ")" + (f.filter == filter_ ? "  <- now" : ""));
  lines.push_back("");
  lines.push_back("n / p and space then step through these layouts only.   Esc: cancel");
  KeyEvent e = Ask("show which layouts?", lines, 78);
  if (e.kind != KeyKind::kChar || e.alt) return;
  for (const FilterKey& f : kFilterKeys) {
    if (static_cast<char32_t>(f.key) != e.ch) continue;
    filter_ = f.filter;
    int count = s_.CountMatching(filter_);
    Note("filter: " + std::string(FilterName(filter_)) + " (" + std::to_string(count) + " layout" + (count == 1 ? "" : "s") + ")");
    if (!s_.Matches(item_, filter_)) {
      int next = s_.Step(item_, +1, filter_, false);
      if (next >= 0) Go(next);
    }
    return;
  }
}

void App::GoToDialog() {
  auto text = EditText("go to: an id, its last digits, or #position", "", std::nullopt);
  if (!text || text->empty()) return;
  auto found = s_.FindItem(*text);
  if (!found) {
    Act(Error{found.error()}, "");
    return;
  }
  Go(*found);
  Note(s_.record(*found).id + (s_.Matches(*found, filter_) ? "" : " (outside the filter " + std::string(FilterName(filter_)) + ")"));
}

void App::HistoryDialog() {
  std::vector<std::string> lines;
  const Effort& effort = s_.effort(item_);
  std::string people;
  for (const std::string& a : effort.annotators) people += (people.empty() ? "" : ", ") + a;
  lines.push_back("people: " + (people.empty() ? std::string("none yet") : people) + "   time on it: " + Seconds(effort.seconds));
  for (const Rating& r : s_.Ratings(item_))
    lines.push_back("  " + r.annotator + "'s last word: " + (r.accepted ? "verified" : "rejected"));
  lines.push_back("");
  const auto& history = s_.history(item_);
  std::size_t from = history.size() > 14 ? history.size() - 14 : 0;
  if (from > 0) lines.push_back("... " + std::to_string(from) + " earlier lines");
  for (std::size_t i = from; i < history.size(); ++i) {
    const HistoryEntry& h = history[i];
    std::string when = h.time.size() >= 16 ? h.time.substr(5, 5) + " " + h.time.substr(11, 5) : h.time;
    std::string action = h.annotator == kAutoAnnotator && h.action == "auto" ? "--auto: drafted labels, fixes, descriptions" : h.action;
    std::string where = h.package.empty() ? "" : "[" + h.package.substr(h.package.find('/') + 1) + "] ";
    lines.push_back(when + "  " + (h.annotator.empty() ? "?" : h.annotator) + "  " + where + action +
                    (h.seconds > 0 ? "  (" + Seconds(h.seconds) + ")" : ""));
  }
  if (history.empty()) lines.push_back("nobody has touched this layout yet");
  Ask("who did what on " + s_.record(item_).id + " (any key: back)", lines, 96);
}

void App::Accept() {
  if (state().status == AnnotationStatus::kVerified) {
    std::string message;
    Act(s_.Accept(item_, &message), message);
    return;
  }
  if (std::string overturn = s_.OverturnWarning(item_); !overturn.empty()) {
    if (!Confirm("overturn another person's decision?", {overturn, "", "y: accept it anyway    any other key: leave it"})) {
      Note("left as " + state().decided_by + " decided");
      return;
    }
  }
  if (auto warnings = s_.AcceptWarnings(item_); !warnings.empty()) {
    int inner = std::min(76, getmaxx(stdscr) - 2) - 2;
    std::vector<std::string> lines;
    for (const std::string& warning : warnings)
      for (const std::string& l : WrapText(warning + ".", inner)) lines.push_back(l);
    lines.push_back("");
    lines.push_back("a: accept anyway   e / E: edit the coarse / fine text   any other key: back");
    KeyEvent e = Ask("accept " + s_.record(item_).id + "?", lines, 76);
    bool accept = e.kind == KeyKind::kChar && !e.alt && (e.ch == 'a' || e.ch == 'y');
    if (!accept) {
      if (e.kind == KeyKind::kChar && !e.alt && (e.ch == 'e' || e.ch == 'E'))
        EditDescription(e.ch == 'e' ? DescriptionField::kCoarse : DescriptionField::kFine);
      else
        Note(warnings[0] + ": not accepted", true);
      return;
    }
  }
  std::string message;
  Status st = s_.Accept(item_, &message);
  Act(st, message);
  if (st) Advance();
}

void App::Reopen() {
  if (std::string overturn = s_.OverturnWarning(item_); !overturn.empty()) {
    if (!Confirm("overturn another person's decision?", {overturn, "", "y: reopen it anyway    any other key: leave it"})) {
      Note("left as " + state().decided_by + " decided");
      return;
    }
  }
  std::string message;
  Act(s_.Reopen(item_, &message), message);
}

bool App::Handle(const KeyEvent& e) {
  switch (e.kind) {
    case KeyKind::kIgnored:
      Note("ignored " + e.text + " (no key of the annotator)");
      return true;
    case KeyKind::kPaste:
      Note("paste ignored: open a description with e or E first, then paste");
      return true;
    case KeyKind::kEscape:
      message_.clear();
      return true;
    case KeyKind::kKey:
      switch (e.key) {
        case Key::kRight: case Key::kDown: case Key::kTab: SelectRoom(1); break;
        case Key::kLeft: case Key::kUp: case Key::kBackTab: SelectRoom(-1); break;
        case Key::kPageUp: ChangeLevel(+1); break;
        case Key::kPageDown: ChangeLevel(-1); break;
        default: break;  // Enter, Home, End, function keys, resize: nothing (a resize just redraws)
      }
      return true;
    case KeyKind::kChar:
      break;
  }
  if (e.alt) {
    Note("Alt-" + EncodeUtf8(e.ch) + " is no key of the annotator (" + EncodeUtf8(e.ch) + " alone is)");
    return true;
  }
  return HandleCommand(static_cast<int>(e.ch));
}

bool App::HandleCommand(int ch) {
  std::string message;
  for (const auto& k : kCategoryKeys) {
    if (ch != k.key) continue;
    if (room_ < 0) return true;
    Act(s_.Relabel(item_, room_, k.category, &message), message);
    return true;
  }
  switch (ch) {
    case 'q': case 3: return false;  // 3 = Ctrl-C
    case '[': ChangeLevel(-1); break;
    case ']': ChangeLevel(+1); break;
    case 'a': Accept(); break;
    case 'x': RejectDialog(); break;
    case 'O': Reopen(); break;
    case 'f': FixDialog(); break;
    case 'r': Act(s_.Redraft(item_, &message), message); break;
    case 'e': EditDescription(DescriptionField::kCoarse); break;
    case 'E': EditDescription(DescriptionField::kFine); break;
    case 'v': EditInEditor(); break;
    case 'u': {
      int item = item_;
      Status st = s_.Undo(&item, &message);
      if (st && item != item_) Go(item);
      Act(st, message);
      break;
    }
    case 'U': case 18: {  // Ctrl-R
      int item = item_;
      Status st = s_.Redo(&item, &message);
      if (st && item != item_) Go(item);
      Act(st, message);
      break;
    }
    case 'n': case 'p': {
      int next = s_.Step(item_, ch == 'n' ? +1 : -1, filter_, false);
      if (next < 0)
        Act(Error{"no layout in filter " + std::string(FilterName(filter_))}, "");
      else {
        Go(next);
        message_.clear();
      }
      break;
    }
    case 'N': case ' ': {
      int next = s_.Step(item_, +1, filter_, true);
      if (next < 0)
        Act(Error{"nothing left to do" + (filter_ == Filter::kAll ? std::string() : " in filter " + std::string(FilterName(filter_)))}, "");
      else {
        Go(next);
        message_.clear();
      }
      break;
    }
    case 'g': GoToDialog(); break;
    case 'F': FilterDialog(); break;
    case 'h': HistoryDialog(); break;
    case '?': Help(); break;
    case 12: clearok(stdscr, TRUE); break;  // Ctrl-L: redraw
    default:
      if (ch >= '1' && ch <= '9') {
        auto rooms = LevelRooms();
        if (ch - '1' < static_cast<int>(rooms.size())) room_ = rooms[ch - '1'];
      }
      break;
  }
  // Keep the selection valid (an undo can change the layout under it).
  auto rooms = LevelRooms();
  if (level_ >= std::max(1, layout().LevelCount())) level_ = 0;
  if (std::find(rooms.begin(), rooms.end(), room_) == rooms.end()) room_ = rooms.empty() ? -1 : rooms[0];
  return true;
}

int App::Run() {
  std::setlocale(LC_ALL, "");
  std::string codeset = nl_langinfo(CODESET);
  unicode_ = !options_.ascii && (codeset == "UTF-8" || codeset == "utf8");
  if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO)) {
    std::fprintf(stderr, "villa annotate: needs a terminal (use --status, --auto or --export in scripts)\n");
    return 1;
  }
  if (options_.review && filter_ == Filter::kAll)
    filter_ = s_.CountMatching(Filter::kDisagreements) > 0 ? Filter::kDisagreements : Filter::kDecided;
  // Where to start: --id, else a layout with unsaved text, else the first layout to do in the filter.
  auto drafts = s_.OpenDrafts();
  if (!options_.start_id.empty()) {
    auto item = s_.FindItem(options_.start_id);
    if (!item) {
      std::fprintf(stderr, "villa annotate: --id %s: %s\n", options_.start_id.c_str(), item.error().c_str());
      return 2;
    }
    Go(*item);
  } else if (!drafts.empty() && s_.dataset().Find(drafts.back().id) >= 0) {
    Go(s_.dataset().Find(drafts.back().id));
  } else {
    int next = options_.review ? -1 : s_.Step(-1, +1, filter_, true);
    if (next < 0) next = s_.Step(-1, +1, filter_, false);
    Go(next < 0 ? 0 : next);
  }
  if (!s_.warnings().empty()) {
    Note(s_.warnings().front(), true);
  } else if (!drafts.empty()) {
    const OpenDraft& d = drafts.back();
    Note("recovered unsaved text of the " + std::string(FieldName(d.field)) + " description of " + d.id + " (" + d.time +
         "): " + (d.field == DescriptionField::kCoarse ? "e" : "E") + " goes on with it");
  } else if (options_.review) {
    int n = s_.CountMatching(filter_);
    Note("review: " + std::to_string(n) + (filter_ == Filter::kDisagreements ? " layout(s) two people decided differently"
                                                                            : " layout(s) decided by a person") +
         "; h: who did what, F: another filter");
  } else if (s_.Step(-1, +1, Filter::kAll, true) < 0) {
    Note("nothing left to do: every layout is verified or rejected");
  }
  if (!initscr()) {
    std::fprintf(stderr, "villa annotate: cannot initialise the terminal\n");
    return 1;
  }
  raw();   // Ctrl-C arrives as a key and quits cleanly (the terminal is restored); Ctrl-Z is ignored
  nonl();  // Enter arrives as CR, Ctrl-J as LF: a new line in the editor
  noecho();
  keypad(stdscr, FALSE);  // bytes, decoded by KeyDecoder: the terminal's key tables are not trusted
  meta(stdscr, TRUE);
  curs_set(0);
  InitColours();
  BracketedPaste(true);
  last_input_ = Clock::now();
  bool running = true;
  while (running) {
    Draw();
    KeyEvent e;
    if (!ReadEvent(&e)) continue;
    running = Handle(e);
  }
  BracketedPaste(false);
  endwin();
  Counts c = s_.counts();
  std::printf("villa annotate: saved in %s: verified %d, rejected %d, auto %d, pending %d\n",
              JournalPath(s_.dataset().dir).string().c_str(), c.verified, c.rejected, c.automatic, c.pending);
  return 0;
}

}  // namespace

int RunAnnotatorTui(Session& session, const TuiOptions& options) {
  App app(session, options);
  return app.Run();
}

}  // namespace villa::annotator
