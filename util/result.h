#pragma once
// Result<T>: a value or an error message, for everything that reads outside input (files, JSON, CLI
// flags, HTTP answers, LLM text). The message names the place (file, line, JSON path) and the bad value,
// so it can be shown to a person as it is.
#include <cassert>
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace villa {

struct Error {
  std::string message;
};

template <class T>
class Result {
 public:
  Result(T value) : data_(std::move(value)) {}          // NOLINT: implicit on purpose
  Result(Error error) : data_(std::move(error)) {}      // NOLINT: implicit on purpose

  bool ok() const { return std::holds_alternative<T>(data_); }
  explicit operator bool() const { return ok(); }

  const T& value() const& { assert(ok() && "Result::value() on an error"); return std::get<T>(data_); }
  T& value() & { assert(ok() && "Result::value() on an error"); return std::get<T>(data_); }
  T&& value() && { assert(ok() && "Result::value() on an error"); return std::get<T>(std::move(data_)); }
  const T& operator*() const& { return value(); }
  T& operator*() & { return value(); }
  const T* operator->() const { return &value(); }
  T* operator->() { return &value(); }

  const std::string& error() const { assert(!ok() && "Result::error() on a value"); return std::get<Error>(data_).message; }

 private:
  std::variant<T, Error> data_;
};

// Result<void> equivalent.
class Status {
 public:
  Status() = default;
  Status(Error error) : error_(std::move(error.message)) {}  // NOLINT
  static Status Ok() { return {}; }
  bool ok() const { return !error_.has_value(); }
  explicit operator bool() const { return ok(); }
  const std::string& error() const { assert(!ok()); return *error_; }

 private:
  std::optional<std::string> error_;
};

}  // namespace villa
