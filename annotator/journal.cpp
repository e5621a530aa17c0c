#include "annotator/journal.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "util/atomic_file.h"
#include "util/json_read.h"

namespace villa::annotator {

Result<JournalContents> ReadJournal(const std::filesystem::path& path, bool repair) {
  JournalContents out;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return out;
  auto text = ReadFile(path);
  if (!text) return Error{text.error()};
  const std::string& data = *text;
  std::size_t pos = 0;
  int number = 0;
  while (pos < data.size()) {
    std::size_t end = data.find('\n', pos);
    bool complete = end != std::string::npos;
    std::string line = data.substr(pos, complete ? end - pos : std::string::npos);
    ++number;
    std::size_t next = complete ? end + 1 : data.size();
    if (line.find_first_not_of(" \t\r") == std::string::npos) {
      pos = next;
      continue;
    }
    JournalJson json;
    bool parsed = true;
    std::string why;
    if (Result<JournalJson> read = ParseJson<JournalJson>(line, ""); read.ok()) {
      json = std::move(*read);
    } else {
      parsed = false;
      why = read.error();
    }
    if (!parsed && !complete && !repair) {
      out.warnings.push_back(path.string() + ":" + std::to_string(number) + ": torn last line (" +
                             std::to_string(line.size()) + " bytes, an interrupted write) skipped");
      break;
    }
    if (!parsed && !complete) {
      // A torn last write: set it aside, keep the journal's complete lines.
      std::filesystem::path torn = path;
      torn += ".torn";
      if (FILE* f = std::fopen(torn.c_str(), "ab")) {
        std::fwrite(line.data(), 1, line.size(), f);
        std::fputc('\n', f);
        std::fclose(f);
      }
      std::filesystem::resize_file(path, pos, ec);
      if (ec) return Error{path.string() + ": cannot truncate the torn last line: " + ec.message()};
      out.warnings.push_back(path.string() + ":" + std::to_string(number) + ": torn last line (" +
                             std::to_string(line.size()) + " bytes, an interrupted write) skipped; kept in " +
                             torn.filename().string());
      break;
    }
    if (!parsed) return Error{path.string() + ":" + std::to_string(number) + ": corrupt journal line: " + why};
    if (!json.is_object())
      return Error{path.string() + ":" + std::to_string(number) + ": corrupt journal line: not a JSON object"};
    if (!complete && repair) {
      // Complete JSON missing only its newline: keep it, and finish the line so appends stay separate.
      if (FILE* f = std::fopen(path.c_str(), "ab")) {
        std::fputc('\n', f);
        std::fflush(f);
        ::fsync(fileno(f));
        std::fclose(f);
      }
    }
    out.lines.push_back({std::move(json), number});
    pos = next;
  }
  return out;
}

JournalWriter::~JournalWriter() {
  if (fd_ >= 0) ::close(fd_);
}

Status JournalWriter::Open(const std::filesystem::path& path) {
  path_ = path;
  std::error_code ec;
  bool created = !std::filesystem::exists(path, ec);
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) return Error{path.string() + ": cannot open for appending: " + std::strerror(errno)};
  // One writer at a time: two sessions appending to one journal would each replay a different history.
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    return Error{path.string() + ": in use by another `villa annotate` (one session a dataset at a time)"};
  }
  if (created) {
    // Make the new file's directory entry durable too.
    int dir = ::open(path.parent_path().empty() ? "." : path.parent_path().c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
      ::fsync(dir);
      ::close(dir);
    }
  }
  return {};
}

Status JournalWriter::Append(const std::vector<JournalJson>& lines) {
  if (fd_ < 0) return Error{path_.string() + ": journal not open"};
  std::string buffer;
  for (const JournalJson& line : lines) {
    buffer += line.dump(-1, ' ', false, JournalJson::error_handler_t::replace);
    buffer += '\n';
  }
  const char* p = buffer.data();
  std::size_t left = buffer.size();
  while (left > 0) {
    ssize_t n = ::write(fd_, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return Error{path_.string() + ": write failed: " + std::strerror(errno)};
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fsync(fd_) != 0) return Error{path_.string() + ": fsync failed: " + std::strerror(errno)};
  return {};
}

}  // namespace villa::annotator
