#include "util/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

namespace villa {
namespace {

std::filesystem::path TempPathFor(const std::filesystem::path& path) {
  static thread_local std::mt19937_64 rng{std::random_device{}()};
  std::ostringstream name;
  name << "." << path.filename().string() << ".tmp-" << ::getpid() << "-" << std::hex << (rng() & 0xffffff);
  return path.parent_path() / name.str();
}

std::string Describe(const std::filesystem::path& path, const char* what) {
  return path.string() + ": " + what + ": " + std::strerror(errno);
}

// Empty when `path` is missing or a regular file; otherwise why it may not be replaced. Renaming a temporary
// onto /dev/null, a folder's name or a symbolic link would swap a device or a link for a plain file (a
// helper once replaced /dev/null that way), so anything but a regular file is left alone.
std::string NotReplaceable(const std::filesystem::path& path) {
  std::error_code ec;
  const auto status = std::filesystem::symlink_status(path, ec);
  if (ec || !std::filesystem::exists(status) || std::filesystem::is_regular_file(status)) return {};
  const char* kind = std::filesystem::is_directory(status)      ? "a folder"
                     : std::filesystem::is_symlink(status)      ? "a symbolic link"
                     : std::filesystem::is_character_file(status) ? "a character device"
                     : std::filesystem::is_block_file(status)   ? "a block device"
                     : std::filesystem::is_fifo(status)         ? "a named pipe"
                     : std::filesystem::is_socket(status)       ? "a socket"
                                                                : "not a regular file";
  return path.string() + ": is " + kind + ", not a regular file: refusing to replace it";
}

}  // namespace

Status WriteFileAtomic(const std::filesystem::path& path, std::string_view content) {
  AtomicFileWriter writer(path);
  if (!writer.ok()) return Error{writer.error()};
  writer.Write(content);
  return writer.Commit();
}

Status CheckReadable(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || st.type() == fs::file_type::not_found) return Error{path.string() + ": no such file"};
  const char* kind = nullptr;
  switch (st.type()) {
    case fs::file_type::regular: break;
    case fs::file_type::directory: kind = "a folder"; break;
    case fs::file_type::fifo: kind = "a FIFO"; break;
    case fs::file_type::character: kind = "a character device"; break;
    case fs::file_type::block: kind = "a block device"; break;
    case fs::file_type::socket: kind = "a socket"; break;
    default: kind = "not a plain file"; break;
  }
  if (kind) return Error{path.string() + ": " + kind + ", not a regular file"};
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) return Error{path.string() + ": cannot tell its size: " + ec.message()};
  if (size > max_bytes) {
    auto text = [](std::uintmax_t b) {
      char t[32];
      if (b >= (std::uintmax_t{1} << 30)) std::snprintf(t, sizeof t, "%.1f GB", b / 1073741824.0);
      else if (b >= (std::uintmax_t{1} << 20)) std::snprintf(t, sizeof t, "%.1f MB", b / 1048576.0);
      else std::snprintf(t, sizeof t, "%ju bytes", b);
      return std::string(t);
    };
    return Error{path.string() + ": " + text(size) + ", more than the " + text(max_bytes) + " this reader takes"};
  }
  return Status{};
}

Result<std::string> ReadFile(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  if (Status s = CheckReadable(path, max_bytes); !s) return Error{s.error()};
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{Describe(path, "cannot open")};
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) return Error{Describe(path, "cannot read")};
  return buffer.str();
}

AtomicFileWriter::AtomicFileWriter(std::filesystem::path path) : path_(std::move(path)) {
  if (std::string refused = NotReplaceable(path_); !refused.empty()) {
    error_ = std::move(refused);
    return;
  }
  temp_ = TempPathFor(path_.has_parent_path() ? path_ : std::filesystem::path(".") / path_);
  file_ = std::fopen(temp_.c_str(), "wb");
  if (!file_) error_ = Describe(temp_, "cannot create");
}

AtomicFileWriter::~AtomicFileWriter() {
  if (file_) {
    std::fclose(file_);
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
  }
}

void AtomicFileWriter::Write(std::string_view data) {
  if (file_ && !data.empty() && std::fwrite(data.data(), 1, data.size(), file_) != data.size() && error_.empty()) {
    error_ = Describe(temp_, "cannot write");
  }
}

Status AtomicFileWriter::Commit() {
  if (!file_) return Error{error_};
  bool flushed = std::fflush(file_) == 0 && ::fsync(::fileno(file_)) == 0;
  if (!flushed && error_.empty()) error_ = Describe(temp_, "cannot flush");
  std::fclose(file_);
  file_ = nullptr;
  if (error_.empty()) error_ = NotReplaceable(path_);  // it may have appeared since the temporary was made
  if (error_.empty() && std::rename(temp_.c_str(), path_.c_str()) != 0) error_ = Describe(path_, "cannot rename into place");
  if (!error_.empty()) {
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
    return Error{error_};
  }
  return {};
}

}  // namespace villa
