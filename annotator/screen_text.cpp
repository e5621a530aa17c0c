#include "annotator/screen_text.h"

#include <algorithm>
#include <cstdio>
#include <iterator>

#include "annotator/relabel.h"
#include "annotator/utf8.h"
#include "layout/topology.h"

namespace villa::annotator {

std::vector<std::string> WrapText(std::string_view text, int width) {
  std::vector<std::string> lines;
  if (width <= 1) return lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    std::string_view paragraph = text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
    std::string line;
    std::size_t i = 0;
    auto flush = [&] {
      lines.push_back(line);
      line.clear();
    };
    bool any = false;
    while (i < paragraph.size()) {
      while (i < paragraph.size() && (paragraph[i] == ' ' || paragraph[i] == '\t' || paragraph[i] == '\r')) ++i;
      std::size_t j = i;
      while (j < paragraph.size() && paragraph[j] != ' ' && paragraph[j] != '\t' && paragraph[j] != '\r') ++j;
      if (j == i) break;
      std::string word(paragraph.substr(i, j - i));
      i = j;
      any = true;
      while (TextWidth(word) > width) {
        if (!line.empty()) flush();
        std::string head = ClipToWidth(word, width);
        if (head.empty()) head = Utf8Glyphs(word).front();  // a wide character in a one-column line
        lines.push_back(head);
        word = word.substr(head.size());
      }
      if (word.empty()) continue;
      if (line.empty())
        line = word;
      else if (TextWidth(line) + 1 + TextWidth(word) <= width)
        line += " " + word;
      else {
        flush();
        line = word;
      }
    }
    if (!line.empty() || !any) lines.push_back(line);
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  // A trailing empty line of a text ending in '\n' carries nothing.
  while (!lines.empty() && lines.back().empty() && lines.size() > 1) lines.pop_back();
  return lines;
}

std::string LevelName(int level, int floors) {
  if (level == 0) return "ground floor";
  if (level == floors - 1) return "top floor";
  return "floor " + std::to_string(level + 1);
}

std::vector<RoomListLine> RoomListLines(const Layout& layout, int level, int selected, int width, bool unicode) {
  std::vector<RoomListLine> out;
  auto connections = RoomConnections(layout);
  auto rooms = layout.RoomsOnLevel(level);
  int name_w = 0;
  for (int r : rooms) name_w = std::max(name_w, TextWidth(layout.rooms[r].name()));
  const std::string indent = "    ";
  for (std::size_t k = 0; k < rooms.size(); ++k) {
    int r = rooms[k];
    const Room& room = layout.rooms[r];
    std::vector<std::string> tokens;
    for (const Connection& c : connections) {
      if (c.room_a != r && c.room_b != r) continue;
      int other = c.room_a == r ? c.room_b : c.room_a;
      std::string token = c.via == Via::kDoor ? "" : c.via == Via::kOpen ? "~" : "^";
      tokens.push_back(token.append(RoomToken(layout.rooms[other])));
    }
    char area[32];
    std::snprintf(area, sizeof area, "%.1f%s", Area(room.polygon), unicode ? "m²" : "m2");
    std::string number = std::to_string(k + 1);
    std::string line = (r == selected ? ">" : " ") + number + " " + PadToWidth(room.name(), name_w) + " " + PadToWidth(area, 7);
    RoomListLine first;
    first.room = r;
    first.first = true;
    first.swatch = 1 + static_cast<int>(number.size());
    bool on_first = true;
    for (const std::string& token : tokens) {
      if (TextWidth(line) + 1 + TextWidth(token) <= width) {
        line += " " + token;
        continue;
      }
      RoomListLine done = on_first ? first : RoomListLine{};
      done.room = r;
      done.text = PadToWidth(line, width);
      out.push_back(done);
      on_first = false;
      line = indent + ClipToWidth(token, width - static_cast<int>(indent.size()));
    }
    RoomListLine last = on_first ? first : RoomListLine{};
    last.room = r;
    last.text = PadToWidth(line, width);
    out.push_back(last);
  }
  return out;
}

std::string HeaderText(const std::string& id, const std::string& position, const std::string& shape,
                       const std::string& status, const std::string& level, const std::string& extra, int width) {
  std::string right = level + " ";
  // What to show, fullest first: the extra goes first, then the shape, then the position.
  struct Parts {
    bool position, shape, extra;
  };
  const Parts tries[] = {{true, true, true}, {true, true, false}, {true, false, false}, {false, false, false}};
  for (std::size_t t = 0; t < std::size(tries); ++t) {
    const Parts& p = tries[t];
    std::string left = " " + id;
    if (p.position) left += "  " + position;
    if (p.shape) left += "  " + shape;
    left += "  [" + status + "]";
    std::string middle = p.extra && !extra.empty() ? "  " + extra : "";
    int used = TextWidth(left) + TextWidth(middle) + TextWidth(right);
    bool last = t + 1 == std::size(tries);
    if (last && used + 1 > width) {
      // Even the id does not fit beside the level: the id gives way, the level stays.
      left = ClipToWidth(left, std::max(0, width - TextWidth(right) - 1));
      used = TextWidth(left) + TextWidth(right);
    }
    if (used + 1 <= width || last) {
      std::string gap(static_cast<std::size_t>(std::max(1, width - used)), ' ');
      return ClipToWidth(left + middle + gap + right, width);
    }
  }
  return "";
}

}  // namespace villa::annotator
