#include "annotator/drafts.h"

#include <algorithm>
#include <ctime>

namespace villa::annotator {

namespace {

// The start of a draft line: format, time and what it is about.
JournalJson DraftLine(const std::string& id, DescriptionField field) {
  JournalJson line;
  line["v"] = 1;
  line["time"] = UtcNow();
  line["id"] = id;
  line["field"] = std::string(FieldName(field));
  return line;
}

}  // namespace

std::string_view FieldName(DescriptionField field) { return field == DescriptionField::kCoarse ? "coarse" : "fine"; }

std::filesystem::path DraftsPath(const std::filesystem::path& dir) { return dir / "annotations.drafts.jsonl"; }

std::string UtcNow() {
  std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}

Status DraftJournal::Open(const std::filesystem::path& path, bool writable) {
  writable_ = writable;
  auto contents = ReadJournal(path, writable);
  if (!contents) return Error{contents.error()};
  warnings_ = contents->warnings;
  for (const JournalLine& line : contents->lines) {
    const JournalJson& j = line.json;
    std::string where = path.string() + ":" + std::to_string(line.line);
    auto id = j.find("id");
    auto field = j.find("field");
    if (id == j.end() || !id->is_string() || field == j.end() || !field->is_string() ||
        (*field != "coarse" && *field != "fine")) {
      // A draft line that cannot be placed is reported, never fatal: the journal proper is intact.
      warnings_.push_back(where + ": draft line without \"id\" and \"field\" (coarse or fine): skipped");
      continue;
    }
    DescriptionField f = *field == "coarse" ? DescriptionField::kCoarse : DescriptionField::kFine;
    Key key{id->get<std::string>(), static_cast<int>(f)};
    if (j.contains("closed")) {
      open_.erase(key);
      continue;
    }
    auto text = j.find("text");
    if (text == j.end() || !text->is_string()) {
      warnings_.push_back(where + ": draft line without \"text\": skipped");
      continue;
    }
    OpenDraft d{key.first, f, text->get<std::string>(), j.value("time", ""), j.value("annotator", "")};
    open_[key] = {++order_, std::move(d)};
  }
  path_ = path;
  if (!writable) return {};
  std::error_code ec;
  if (open_.empty() && std::filesystem::exists(path, ec)) {
    std::filesystem::remove(path, ec);
    if (ec) return Error{path.string() + ": cannot empty the draft journal: " + ec.message()};
  }
  // Opened for appending when the first draft is kept: a session that types nothing leaves no file.
  if (!open_.empty()) return writer_.Open(path);
  return {};
}

Status DraftJournal::Append(const JournalJson& line) {
  if (!writable_) return Error{"session opened read-only"};
  if (writer_.path().empty())
    if (Status s = writer_.Open(path_); !s) return s;
  return writer_.Append(line);
}

std::optional<OpenDraft> DraftJournal::Find(const std::string& id, DescriptionField field) const {
  auto it = open_.find({id, static_cast<int>(field)});
  if (it == open_.end()) return std::nullopt;
  return it->second.second;
}

std::vector<OpenDraft> DraftJournal::All() const {
  std::vector<std::pair<long, OpenDraft>> all;
  for (const auto& [key, value] : open_) all.push_back(value);
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<OpenDraft> out;
  for (auto& [order, draft] : all) out.push_back(std::move(draft));
  return out;
}

Status DraftJournal::Keep(const std::string& id, DescriptionField field, const std::string& text,
                          const std::string& annotator) {
  JournalJson line = DraftLine(id, field);
  line["annotator"] = annotator;
  line["text"] = text;
  if (Status s = Append(line); !s) return s;
  open_[{id, static_cast<int>(field)}] = {++order_, OpenDraft{id, field, text, line["time"], annotator}};
  return {};
}

Status DraftJournal::Close(const std::string& id, DescriptionField field, const std::string& how) {
  Key key{id, static_cast<int>(field)};
  if (!open_.count(key)) return {};
  JournalJson line = DraftLine(id, field);
  line["closed"] = how;
  if (Status s = Append(line); !s) return s;
  open_.erase(key);
  return {};
}

}  // namespace villa::annotator
