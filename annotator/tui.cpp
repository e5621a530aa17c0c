#include "annotator/tui.h"

#ifndef NCURSES_WIDECHAR
#define NCURSES_WIDECHAR 1
#endif
#include <curses.h>
#include <langinfo.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <clocale>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "annotator/fixes.h"
#include "annotator/floorplan_canvas.h"
#include "annotator/relabel.h"
#include "layout/layout_io.h"
#include "layout/topology.h"
#include "layout/validate.h"
#include "render/palette.h"
#include "util/atomic_file.h"

namespace villa::annotator {
namespace {

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

// layout.h's short name in lower case, for the legend and tight labels ("bed", "child", "utility").
std::string ShortName(Category c) {
  std::string name(CategoryShortName(c));
  for (char& ch : name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return name;
}

// Code points of a UTF-8 string (display width 1 each; the tool writes no wide glyphs).
int Width(const std::string& s) {
  int n = 0;
  for (unsigned char c : s)
    if ((c & 0xC0) != 0x80) ++n;
  return n;
}

// The first `width` code points of s.
std::string Clip(const std::string& s, int width) {
  if (width <= 0) return "";
  int n = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    if ((c & 0xC0) != 0x80) {
      if (n == width) return s.substr(0, i);
      ++n;
    }
  }
  return s;
}

std::string Pad(const std::string& s, int width) {
  std::string out = Clip(s, width);
  return out + std::string(std::max(0, width - Width(out)), ' ');
}

// Greedy word wrap to `width` columns.
std::vector<std::string> Wrap(const std::string& text, int width) {
  std::vector<std::string> lines;
  if (width <= 1) return lines;
  std::istringstream words(text);
  std::string word, line;
  while (words >> word) {
    while (Width(word) > width) {
      if (!line.empty()) {
        lines.push_back(line);
        line.clear();
      }
      lines.push_back(Clip(word, width));
      word = word.substr(Clip(word, width).size());
    }
    if (line.empty())
      line = word;
    else if (Width(line) + 1 + Width(word) <= width)
      line += " " + word;
    else {
      lines.push_back(line);
      line = word;
    }
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

std::string Fixed1(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f", v);
  return buffer;
}

std::string LevelName(int level, int floors) {
  if (level == 0) return "ground floor";
  if (level == floors - 1) return "top floor";
  return "floor " + std::to_string(level + 1);
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
short Xterm256(double r, double g, double b) {
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

void Put(int y, int x, const std::string& text, short pair = kPairText, attr_t attr = A_NORMAL) {
  attr_set(attr, pair, nullptr);
  mvaddstr(y, x, text.c_str());
  attr_set(A_NORMAL, kPairText, nullptr);
}

// ---------------------------------------------------------------- the app

class App {
 public:
  App(Session& session, const TuiOptions& options) : s_(session), options_(options) {}
  int Run();

 private:
  void Draw();   // paints and refreshes
  void Paint();  // paints without refreshing (under a dialog)
  void DrawHeader(int w);
  void DrawPlan(int top, int left, int width, int height);
  int DrawPanel(int top, int left, int width, int height);
  void DrawStatus(int h, int w);
  bool Handle(int key, bool is_key_code);
  void Go(int item);
  void SelectRoom(int delta);
  void Advance();  // after accept / reject: on to the next pending layout, if any
  void Act(const Status& status, const std::string& message);

  // Modal dialogs.
  void Help();
  void RejectDialog();
  void FixDialog();
  bool EditText(const std::string& title, std::string& text);  // in place; false = cancelled
  void EditInEditor();
  bool Prompt(const std::string& title, std::string& text);
  void Modal(const std::string& title, const std::vector<std::string>& lines, int width);

  const AnnotationState& state() const { return s_.state(item_); }
  const Layout& layout() const { return state().layout; }
  std::vector<int> LevelRooms() const { return layout().RoomsOnLevel(level_); }
  const ValidationReport& Report();

  Session& s_;
  TuiOptions options_;
  int item_ = 0;
  int level_ = 0;
  int room_ = -1;  // index into layout().rooms, on level_
  std::string message_;
  bool message_bad_ = false;
  bool unicode_ = true;
  // Validation cache: recomputed when the layout shown changes.
  int cached_item_ = -1;
  std::string cached_key_;
  ValidationReport report_;
  std::vector<Fix> fixes_;
};

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

void App::Go(int item) {
  if (item < 0 || item >= s_.size()) return;
  item_ = item;
  level_ = 0;
  auto rooms = LevelRooms();
  room_ = rooms.empty() ? -1 : rooms[0];
}

void App::Advance() {
  int next = s_.NextPending(item_ + 1);
  if (next < 0) {
    message_ += "; no pending layout left";
    return;
  }
  message_ += "; next pending: " + s_.record(next).id;
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

void App::Act(const Status& status, const std::string& message) {
  if (status) {
    message_ = message;
    message_bad_ = false;
  } else {
    message_ = status.error();
    message_bad_ = true;
  }
}

void App::DrawHeader(int w) {
  const DatasetRecord& rec = s_.record(item_);
  int floors = layout().LevelCount();
  std::string status(StatusName(state().status));
  std::string left = " " + rec.id + "  " + std::to_string(item_ + 1) + "/" + std::to_string(s_.size()) + "  " +
                     (rec.shape == "rectangle" ? "rectangular" : rec.shape == "irregular" ? "irregular" : rec.shape + "-shaped") +
                     ", " + std::to_string(floors) + (floors == 1 ? " floor" : " floors");
  std::string right = "level " + std::to_string(level_) + " (" + LevelName(level_, floors) + ")  [ ] ";
  Put(0, 0, Pad(left, w), kPairTitle, A_BOLD);
  short pair = state().status == AnnotationStatus::kVerified   ? kPairGood
               : state().status == AnnotationStatus::kRejected ? kPairBad
                                                                : kPairDim;
  int sx = Width(left) + 2;
  if (sx + Width(status) + 2 < w) Put(0, sx, "[" + status + "]", pair, A_BOLD);
  if (w - Width(right) > sx + Width(status) + 4) Put(0, w - Width(right), right, kPairDim);
}

void App::DrawPlan(int top, int left, int width, int height) {
  CanvasOptions o;
  o.width = width;
  o.height = height;
  o.unicode = unicode_;
  o.labels.resize(layout().rooms.size());
  auto rooms = LevelRooms();
  for (std::size_t k = 0; k < rooms.size(); ++k) {
    const Room& r = layout().rooms[rooms[k]];
    std::string n = std::to_string(k + 1);
    o.labels[rooms[k]] = {n + " " + std::string(CategoryName(r.category)), n + " " + ShortName(r.category),
                          n + " " + ShortName(r.category).substr(0, 3), n};
  }
  Canvas canvas = DrawFloorPlan(layout(), level_, o);
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
          pair = CategoryPair(layout().rooms[cell.room].category);
          if (cell.room == room_) {
            if (cell.kind == CellKind::kLabel)
              attr = A_BOLD | A_UNDERLINE;
            else if (cell.kind == CellKind::kFloor)
              glyph = unicode_ ? "·" : ".";
          }
          if (cell.kind == CellKind::kStair) attr |= A_DIM;
          break;
        case CellKind::kWall: pair = kPairWall; attr = A_BOLD; break;
        case CellKind::kDoor: pair = kPairDoor; attr = A_BOLD; break;
        case CellKind::kOpen: break;
        case CellKind::kWindow: pair = kPairWindow; break;
        case CellKind::kPanoramic: pair = kPairWindow; attr = A_BOLD; break;
        case CellKind::kEntrance: pair = kPairEntrance; attr = A_BOLD; break;
      }
      Put(top + y, left + x, glyph, pair, attr);
    }
  }
}

int App::DrawPanel(int top, int left, int width, int height) {
  int y = top;
  int bottom = top + height;
  auto line = [&](const std::string& text, short pair = kPairText, attr_t attr = A_NORMAL) {
    if (y >= bottom) return;
    Put(y++, left, Pad(text, width), pair, attr);
  };
  const Layout& l = layout();
  auto connections = RoomConnections(l);
  auto rooms = LevelRooms();
  line("Rooms on " + LevelName(level_, l.LevelCount()) + "  (Tab, 1-" + std::to_string(rooms.size()) + ")", kPairTitle,
       A_BOLD);
  std::size_t name_w = 0;
  for (int r : rooms) name_w = std::max(name_w, l.rooms[r].name().size());
  std::vector<std::string> selected_links;
  for (std::size_t k = 0; k < rooms.size(); ++k) {
    int r = rooms[k];
    const Room& room = l.rooms[r];
    std::vector<std::string> links;
    for (const Connection& c : connections) {
      if (c.room_a != r && c.room_b != r) continue;
      int other = c.room_a == r ? c.room_b : c.room_a;
      std::string via = c.via == Via::kDoor ? "" : c.via == Via::kOpen ? "~" : "^";
      links.push_back(via + RoomToken(l.rooms[other]));
      if (r == room_)
        selected_links.push_back(l.rooms[other].name() +
                                 (c.via == Via::kDoor ? " (door)" : c.via == Via::kOpen ? " (open)" : " (stairs)"));
    }
    std::string text = (r == room_ ? ">" : " ") + std::to_string(k + 1) + " " +
                       Pad(room.name(), static_cast<int>(name_w)) + " " +
                       Pad(Fixed1(Area(room.polygon)) + (unicode_ ? "m²" : "m2"), 7);
    std::string joined;
    for (const std::string& s : links) joined += (joined.empty() ? "" : " ") + s;
    text += " " + joined;
    if (y < bottom) {
      Put(y, left, Pad(text, width), r == room_ ? kPairSelected : kPairText, r == room_ ? A_BOLD : A_NORMAL);
      // The category swatch.
      Put(y, left + 1 + static_cast<int>(std::to_string(k + 1).size()), " ", CategoryPair(room.category));
      ++y;
    }
  }
  if (room_ >= 0) {
    std::string joins;
    for (const std::string& s : selected_links) joins += (joins.empty() ? "" : ", ") + s;
    auto wrapped = Wrap(l.rooms[room_].name() + " joins " + (joins.empty() ? "nothing" : joins), width - 2);
    for (std::size_t i = 0; i < wrapped.size() && i < 2; ++i) line("  " + wrapped[i], kPairDim);
  }

  const ValidationReport& report = Report();
  if (report.valid()) {
    line(unicode_ ? "✓ passes all ten rules" : "OK passes all ten rules", kPairGood, A_BOLD);
  } else {
    line(std::to_string(report.violations.size()) + " rule violation" + (report.violations.size() == 1 ? "" : "s") +
             (fixes_.empty() ? "" : "   f: " + std::to_string(fixes_.size()) + " fix" + (fixes_.size() == 1 ? "" : "es")),
         kPairBad, A_BOLD);
    int shown = 0;
    int room_for = std::max(1, (bottom - y) / 3);
    for (const Violation& v : report.violations) {
      if (shown >= room_for) {
        line("  ... " + std::to_string(report.violations.size() - shown) + " more", kPairBad);
        break;
      }
      line((unicode_ ? " ✗ " : " x ") + std::to_string(v.rule) + ": " + v.message, kPairBad);
      ++shown;
    }
  }
  if (state().status == AnnotationStatus::kRejected && !state().reason.empty())
    line("rejected: " + state().reason, kPairBad);

  // Descriptions share what is left.
  int left_rows = bottom - y;
  if (left_rows >= 4) {
    int inner = width - 2;
    auto coarse = Wrap(state().coarse, inner);
    auto fine = Wrap(state().fine, inner);
    int avail = left_rows - 2;
    int coarse_rows = std::min<int>(static_cast<int>(coarse.size()), std::max(1, avail / 3));
    int fine_rows = avail - coarse_rows;
    std::string tag = state().edited ? " (edited)" : " (draft)";
    line("Coarse" + tag + "  e: edit", kPairTitle, A_BOLD);
    for (int i = 0; i < coarse_rows && i < static_cast<int>(coarse.size()); ++i) {
      bool last = i == coarse_rows - 1 && static_cast<int>(coarse.size()) > coarse_rows;
      line("  " + (last ? Clip(coarse[i], inner - 3) + "..." : coarse[i]));
    }
    line("Fine" + tag + "  E: edit  v: $EDITOR  r: redraft", kPairTitle, A_BOLD);
    for (int i = 0; i < fine_rows && i < static_cast<int>(fine.size()) && y < bottom; ++i) {
      bool last = i == fine_rows - 1 && static_cast<int>(fine.size()) > fine_rows;
      line("  " + (last ? Clip(fine[i], inner - 3) + "..." : fine[i]));
    }
  }
  while (y < bottom) line("");
  return y;
}

void App::DrawStatus(int h, int w) {
  Counts c = s_.counts();
  std::string counts = " " + std::to_string(item_ + 1) + "/" + std::to_string(s_.size()) + "  verified " +
                       std::to_string(c.verified) + "  rejected " + std::to_string(c.rejected) + "  auto " +
                       std::to_string(c.automatic) + "  pending " + std::to_string(c.pending) + " ";
  std::string keys = " ?:help a:accept x:reject f:fix u:undo n/p/N:next/prev/pending q:quit";
  std::string legend;
  for (const auto& k : kCategoryKeys) legend += std::string(1, static_cast<char>(k.key)) + ":" + ShortName(k.category) + " ";
  // Line h-2: the last message; line h-1: counts and keys.
  Put(h - 2, 0, Pad(message_.empty() ? " " + legend : " " + message_, w), message_bad_ ? kPairBad : kPairDim,
      message_bad_ ? A_BOLD : A_NORMAL);
  Put(h - 1, 0, Pad(counts, w), kPairStatus, A_BOLD);
  if (Width(counts) < w) Put(h - 1, Width(counts), Pad(keys, w - Width(counts)), kPairStatus);
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
    Put(0, 0, Clip("villa annotate needs at least 50x12 (now " + std::to_string(w) + "x" + std::to_string(h) + ")", w));
    return;
  }
  DrawHeader(w);
  int panel = std::clamp(w * 45 / 100, 34, 78);
  int plan = w - panel - 1;
  int body_top = 1, body_h = h - 3;
  DrawPlan(body_top, 0, plan, body_h);
  for (int y = body_top; y < body_top + body_h; ++y) Put(y, plan, unicode_ ? "│" : "|", kPairDim);
  DrawPanel(body_top, plan + 1, panel, body_h);
  DrawStatus(h, w);
}

void App::Modal(const std::string& title, const std::vector<std::string>& lines, int width) {
  int h, w;
  getmaxyx(stdscr, h, w);
  width = std::min(width, w - 2);
  int height = std::min(static_cast<int>(lines.size()) + 2, h - 2);
  int top = (h - height) / 2, left = (w - width) / 2;
  for (int y = 0; y < height; ++y) Put(top + y, left, std::string(width, ' '), kPairStatus);
  Put(top, left + 1, Clip(" " + title + " ", width - 2), kPairStatus, A_BOLD);
  for (int i = 0; i < height - 2; ++i) Put(top + 1 + i, left + 1, Pad(lines[i], width - 2), kPairStatus);
  refresh();
}

void App::Help() {
  std::vector<std::string> lines = {
      "Tab / arrows / 1-9   select a room on this level",
      "[ ] PgUp PgDn        level down / up",
      "Category of the selected room:",
  };
  std::string cats;
  for (const auto& k : kCategoryKeys) {
    std::string entry = std::string(1, static_cast<char>(k.key)) + " " + std::string(CategoryName(k.category));
    if (Width(cats) + Width(entry) + 2 > 64) {
      lines.push_back("  " + cats);
      cats.clear();
    }
    cats += (cats.empty() ? "" : "  ") + entry;
  }
  lines.push_back("  " + cats);
  for (const char* s : {
           "a      accept as verified (refused while a rule breaks)",
           "x      reject (preset reasons or free text)",
           "O      reopen (back to pending)",
           "f      mechanical fixes for the rule violations",
           "e / E  edit the coarse / fine description here",
           "v      edit both descriptions in $VISUAL / $EDITOR",
           "r      redraft the descriptions",
           "u / U  undo / redo (Ctrl-R also redoes)",
           "n / p  next / previous layout;  N or space: next pending",
           "q      quit (everything is already saved); Ctrl-C too"}) {
    lines.push_back(s);
  }
  lines.push_back(unicode_ ? "Plan: door ▒  open: gap  window ═ ║  panoramic █  entrance ▓  stairs ═"
                           : "Plan: door #  open: gap  window = H  panoramic %  entrance E  stairs =");
  lines.push_back("Each action is in annotations.journal.jsonl before it shows.");
  Modal("villa annotate: keys (any key: back)", lines, 76);
  getch();
}

bool App::Prompt(const std::string& title, std::string& text) { return EditText(title, text); }

bool App::EditText(const std::string& title, std::string& text) {
  // A small multi-line editor over the screen; the text is kept as UTF-8, edited by code points.
  std::vector<std::string> cps;
  for (std::size_t i = 0; i < text.size();) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    std::size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : 4;
    cps.push_back(text.substr(i, n));
    i += n;
  }
  std::size_t cursor = cps.size();
  curs_set(1);
  while (true) {
    int h, w;
    getmaxyx(stdscr, h, w);
    int width = std::min(w - 4, 100);
    int inner = width - 2;
    // Wrap by characters so the cursor maps to a cell.
    std::vector<std::pair<std::size_t, std::size_t>> rows;  // [begin, end) in cps
    std::size_t begin = 0;
    while (begin < cps.size()) {
      std::size_t end = std::min(cps.size(), begin + static_cast<std::size_t>(inner));
      if (end < cps.size()) {
        std::size_t space = end;
        while (space > begin && cps[space - 1] != " ") --space;
        if (space > begin) end = space;
      }
      rows.push_back({begin, end});
      begin = end;
    }
    if (rows.empty() || (rows.back().second == cps.size() && rows.back().second - rows.back().first == static_cast<std::size_t>(inner)))
      rows.push_back({cps.size(), cps.size()});
    int height = std::min(static_cast<int>(rows.size()) + 4, h - 2);
    int top = (h - height) / 2, left = (w - width) / 2;
    Paint();
    for (int y = 0; y < height; ++y) Put(top + y, left, std::string(width, ' '), kPairStatus);
    Put(top, left + 1, Clip(" " + title + " ", width - 2), kPairStatus, A_BOLD);
    int cy = top + 1, cx = left + 1;
    int first_row = 0;
    int visible = height - 4;
    std::size_t cursor_row = 0;
    for (std::size_t r = 0; r < rows.size(); ++r)
      if (rows[r].first <= cursor) cursor_row = r;
    if (static_cast<int>(cursor_row) >= visible) first_row = static_cast<int>(cursor_row) - visible + 1;
    for (int i = 0; i < visible && first_row + i < static_cast<int>(rows.size()); ++i) {
      auto [b, e] = rows[first_row + i];
      std::string s;
      for (std::size_t k = b; k < e; ++k) s += cps[k];
      Put(top + 1 + i, left + 1, Pad(s, inner), kPairText);
      if (first_row + i == static_cast<int>(cursor_row)) {
        cy = top + 1 + i;
        cx = left + 1 + static_cast<int>(cursor - b);
      }
    }
    Put(top + height - 2, left + 1, Pad("Enter: save   Esc: cancel   Ctrl-U: clear", inner), kPairStatus, A_DIM);
    move(cy, cx);
    refresh();
    wint_t ch;
    int kind = get_wch(&ch);
    if (kind == ERR) continue;
    if (kind == KEY_CODE_YES) {
      switch (ch) {
        case KEY_LEFT: if (cursor > 0) --cursor; break;
        case KEY_RIGHT: if (cursor < cps.size()) ++cursor; break;
        case KEY_HOME: cursor = rows[cursor_row].first; break;
        case KEY_END: cursor = rows[cursor_row].second; break;
        case KEY_UP:
          if (cursor_row > 0) cursor = std::min(rows[cursor_row - 1].second, rows[cursor_row - 1].first + (cursor - rows[cursor_row].first));
          break;
        case KEY_DOWN:
          if (cursor_row + 1 < rows.size()) cursor = std::min(rows[cursor_row + 1].second, rows[cursor_row + 1].first + (cursor - rows[cursor_row].first));
          break;
        case KEY_BACKSPACE: if (cursor > 0) cps.erase(cps.begin() + static_cast<long>(--cursor)); break;
        case KEY_DC: if (cursor < cps.size()) cps.erase(cps.begin() + static_cast<long>(cursor)); break;
        case KEY_ENTER: goto done;
        default: break;
      }
      continue;
    }
    if (ch == 27) {
      curs_set(0);
      return false;
    }
    if (ch == '\n' || ch == '\r') break;
    if (ch == 127 || ch == 8) {
      if (cursor > 0) cps.erase(cps.begin() + static_cast<long>(--cursor));
      continue;
    }
    if (ch == 21) {  // Ctrl-U
      cps.clear();
      cursor = 0;
      continue;
    }
    if (ch == 1) { cursor = 0; continue; }            // Ctrl-A
    if (ch == 5) { cursor = cps.size(); continue; }   // Ctrl-E
    if (ch < 32) continue;
    // Encode the code point as UTF-8.
    std::string u;
    unsigned cp = static_cast<unsigned>(ch);
    if (cp < 0x80) u += static_cast<char>(cp);
    else if (cp < 0x800) { u += static_cast<char>(0xC0 | (cp >> 6)); u += static_cast<char>(0x80 | (cp & 0x3F)); }
    else if (cp < 0x10000) { u += static_cast<char>(0xE0 | (cp >> 12)); u += static_cast<char>(0x80 | ((cp >> 6) & 0x3F)); u += static_cast<char>(0x80 | (cp & 0x3F)); }
    else { u += static_cast<char>(0xF0 | (cp >> 18)); u += static_cast<char>(0x80 | ((cp >> 12) & 0x3F)); u += static_cast<char>(0x80 | ((cp >> 6) & 0x3F)); u += static_cast<char>(0x80 | (cp & 0x3F)); }
    cps.insert(cps.begin() + static_cast<long>(cursor++), u);
  }
done:
  curs_set(0);
  text.clear();
  for (const std::string& c : cps) text += c;
  // Trim surrounding spaces.
  while (!text.empty() && text.back() == ' ') text.pop_back();
  while (!text.empty() && text.front() == ' ') text.erase(text.begin());
  return true;
}

void App::EditInEditor() {
  const char* editor = std::getenv("VISUAL");
  if (!editor || !*editor) editor = std::getenv("EDITOR");
  if (!editor || !*editor) {
    Act(Error{"neither $VISUAL nor $EDITOR is set: e / E edit here"}, "");
    return;
  }
  const std::string marker = "# ---- fine description below; lines starting with # are ignored ----";
  std::filesystem::path path = std::filesystem::temp_directory_path() /
                               ("villa-annotate-" + std::to_string(::getpid()) + "-" + s_.record(item_).id + ".txt");
  {
    std::ofstream out(path);
    out << "# " << s_.record(item_).id << ": coarse description below (one paragraph)\n"
        << state().coarse << "\n" << marker << "\n" << state().fine << "\n";
  }
  def_prog_mode();
  endwin();
  std::string command = std::string(editor) + " '" + path.string() + "'";
  int rc = std::system(command.c_str());
  reset_prog_mode();
  refresh();
  if (rc != 0) {
    Act(Error{std::string("editor exited with status ") + std::to_string(rc) + ": descriptions unchanged"}, "");
    std::filesystem::remove(path);
    return;
  }
  std::ifstream in(path);
  std::string line, coarse, fine;
  bool in_fine = false;
  while (std::getline(in, line)) {
    if (line == marker) {
      in_fine = true;
      continue;
    }
    if (!line.empty() && line[0] == '#') continue;
    std::string& target = in_fine ? fine : coarse;
    if (!line.empty()) target += (target.empty() ? "" : " ") + line;
  }
  std::filesystem::remove(path);
  if (coarse.empty() || fine.empty()) {
    Act(Error{"a description came back empty: descriptions unchanged"}, "");
    return;
  }
  std::string message;
  Act(s_.SetDescriptions(item_, coarse, fine, &message), message);
}

void App::RejectDialog() {
  const auto& presets = PresetRejectReasons();
  std::vector<std::string> lines;
  for (std::size_t i = 0; i < presets.size(); ++i) lines.push_back(std::to_string(i + 1) + "  " + presets[i]);
  lines.push_back("t  type a reason");
  lines.push_back("");
  lines.push_back("Esc: cancel");
  Modal("reject " + s_.record(item_).id + ": why?", lines, 74);
  int ch = getch();
  std::string reason;
  if (ch >= '1' && ch < '1' + static_cast<int>(presets.size())) {
    reason = presets[ch - '1'];
  } else if (ch == 't' || ch == '0') {
    std::string text;
    if (!Prompt("reason for rejecting " + s_.record(item_).id, text) || text.empty()) {
      Act(Error{"reject cancelled"}, "");
      return;
    }
    reason = text;
  } else {
    message_ = "reject cancelled";
    message_bad_ = false;
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
  Modal("mechanical fixes", lines, 78);
  int ch = getch();
  std::vector<Fix> chosen;
  if (ch == 'a' || ch == '\n' || ch == KEY_ENTER)
    chosen = fixes_;
  else if (ch >= '1' && ch <= '9' && ch - '1' < static_cast<int>(fixes_.size()))
    chosen = {fixes_[ch - '1']};
  if (chosen.empty()) return;
  std::string message;
  Act(s_.ApplyFixes(item_, chosen, &message), message);
}

bool App::Handle(int ch, bool is_code) {
  std::string message;
  if (is_code) {
    switch (ch) {
      case KEY_RIGHT: case KEY_DOWN: SelectRoom(1); return true;
      case KEY_LEFT: case KEY_UP: case KEY_BTAB: SelectRoom(-1); return true;
      case KEY_NPAGE: case KEY_PPAGE: {
        int floors = layout().LevelCount();
        level_ = std::clamp(level_ + (ch == KEY_PPAGE ? 1 : -1), 0, std::max(0, floors - 1));
        auto rooms = LevelRooms();
        room_ = rooms.empty() ? -1 : rooms[0];
        return true;
      }
      case KEY_RESIZE: return true;
      default: return true;
    }
  }
  for (const auto& k : kCategoryKeys) {
    if (ch != k.key) continue;
    if (room_ < 0) return true;
    Act(s_.Relabel(item_, room_, k.category, &message), message);
    return true;
  }
  switch (ch) {
    case 'q': case 3: return false;  // 3 = Ctrl-C
    case '\t': SelectRoom(1); break;
    case '[': case ']': {
      int floors = layout().LevelCount();
      level_ = std::clamp(level_ + (ch == ']' ? 1 : -1), 0, std::max(0, floors - 1));
      auto rooms = LevelRooms();
      room_ = rooms.empty() ? -1 : rooms[0];
      break;
    }
    case 'a': {
      Status st = s_.Accept(item_, &message);
      Act(st, message);
      if (st) Advance();
      break;
    }
    case 'x': RejectDialog(); break;
    case 'O': Act(s_.Reopen(item_, &message), message); break;
    case 'f': FixDialog(); break;
    case 'r': Act(s_.Redraft(item_, &message), message); break;
    case 'e': case 'E': {
      bool fine = ch == 'E';
      std::string text = fine ? state().fine : state().coarse;
      if (!EditText(std::string(fine ? "fine" : "coarse") + " description of " + s_.record(item_).id, text)) break;
      if (text.empty()) {
        Act(Error{"a description cannot be empty: unchanged"}, "");
        break;
      }
      Act(s_.SetDescriptions(item_, fine ? state().coarse : text, fine ? text : state().fine, &message), message);
      break;
    }
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
    case 'n': Go(std::min(item_ + 1, s_.size() - 1)); message_.clear(); break;
    case 'p': Go(std::max(item_ - 1, 0)); message_.clear(); break;
    case 'N': case ' ': {
      int next = s_.NextPending(item_ + 1);
      if (next < 0)
        Act(Error{"no pending layout left"}, "");
      else {
        Go(next);
        message_.clear();
      }
      break;
    }
    case '?': Help(); break;
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
  if (!options_.start_id.empty()) {
    int item = s_.dataset().Find(options_.start_id);
    if (item < 0) {
      std::fprintf(stderr, "villa annotate: --id %s: not in the dataset\n", options_.start_id.c_str());
      return 2;
    }
    Go(item);
  } else {
    int next = s_.NextPending(0);
    Go(next < 0 ? 0 : next);
  }
  if (!s_.warnings().empty()) {
    message_ = s_.warnings().front();
    message_bad_ = true;
  } else if (s_.NextPending(0) < 0) {
    message_ = "no pending layout left: every layout is verified, rejected or auto";
  }
  set_escdelay(25);
  if (!initscr()) {
    std::fprintf(stderr, "villa annotate: cannot initialise the terminal\n");
    return 1;
  }
  raw();  // Ctrl-C arrives as a key and quits cleanly (the terminal is restored); Ctrl-Z is ignored
  noecho();
  keypad(stdscr, TRUE);
  curs_set(0);
  InitColours();
  bool running = true;
  while (running) {
    Draw();
    wint_t ch;
    int kind = get_wch(&ch);
    if (kind == ERR) continue;
    running = Handle(static_cast<int>(ch), kind == KEY_CODE_YES);
  }
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
