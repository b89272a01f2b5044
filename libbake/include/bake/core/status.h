// Errors in libbake: one exit-code enum for every tool, and Status / Result<T> values that carry the
// code, a message and the place at fault (file + element). Library code returns these for bad data;
// asserts are kept for programmer errors only. Tools turn a failed Status into
// "TOOL: error: FILE: ELEMENT: message" and exit with its code.
#pragma once

#include <cassert>
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace bake {

// Process exit codes, shared by every tool (documented in docs/conventions.md).
enum class ExitCode : int {
  Ok = 0,
  Usage = 1,         // bad command line
  Io = 2,            // a file could not be read or written
  InvalidInput = 3,  // the input is malformed or violates the format
  Internal = 4,      // a bug or an unexpected failure inside the tool
  Unsupported = 5,   // a valid input using a feature we do not implement
};

const char* exitCodeName(ExitCode code);

// Where an error is: the file, and inside it the element (line 12, vertex 40, accessor 3, ...).
struct Location {
  std::string file;
  std::string element;
};

class [[nodiscard]] Status {
 public:
  Status() = default;  // ok
  Status(ExitCode code, std::string message, Location where = {})
      : code_(code), message_(std::move(message)), where_(std::move(where)) {}

  static Status ok() { return {}; }
  bool isOk() const { return code_ == ExitCode::Ok; }
  explicit operator bool() const { return isOk(); }

  ExitCode code() const { return code_; }
  const std::string& message() const { return message_; }
  const Location& where() const { return where_; }

  // Fills in the file and/or element when the callee did not know them.
  Status& inFile(const std::string& file);
  Status& atElement(const std::string& element);

  // "FILE: ELEMENT: message" (parts that are unknown are left out).
  std::string describe() const;

 private:
  ExitCode code_ = ExitCode::Ok;
  std::string message_;
  Location where_;
};

// Shorthands for the common failures.
Status ioError(std::string message, Location where = {});
Status invalidInput(std::string message, Location where = {});
Status unsupported(std::string message, Location where = {});
Status internalError(std::string message, Location where = {});
Status usageError(std::string message);

// A value or the Status explaining why there is none.
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : state_(std::move(value)) {}  // NOLINT: implicit by design
  Result(Status status) : state_(std::move(status)) {  // NOLINT: implicit by design
    assert(!std::get<Status>(state_).isOk() && "a Result built from a Status must be an error");
  }

  bool isOk() const { return std::holds_alternative<T>(state_); }
  explicit operator bool() const { return isOk(); }

  const Status& status() const {
    static const Status okStatus;
    return isOk() ? okStatus : std::get<Status>(state_);
  }
  Status takeStatus() { return isOk() ? Status() : std::move(std::get<Status>(state_)); }

  T& value() & { return std::get<T>(state_); }
  const T& value() const& { return std::get<T>(state_); }
  T&& value() && { return std::move(std::get<T>(state_)); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }

 private:
  std::variant<T, Status> state_;
};

}  // namespace bake

#define BAKE_CONCAT_INNER(a, b) a##b
#define BAKE_CONCAT(a, b) BAKE_CONCAT_INNER(a, b)

// Returns the Status from the enclosing function when `expr` (a Status) failed.
#define BAKE_RETURN_IF_ERROR(expr)                   \
  do {                                               \
    ::bake::Status bake_status_ = (expr);            \
    if (!bake_status_.isOk()) return bake_status_;   \
  } while (0)

// `lhs = value of expr` (a Result<T>), or return its Status from the enclosing function.
#define BAKE_ASSIGN_OR_RETURN(lhs, expr) \
  BAKE_ASSIGN_OR_RETURN_IMPL(BAKE_CONCAT(bake_result_, __LINE__), lhs, expr)
#define BAKE_ASSIGN_OR_RETURN_IMPL(tmp, lhs, expr) \
  auto tmp = (expr);                               \
  if (!tmp.isOk()) return tmp.takeStatus();        \
  lhs = std::move(tmp).value()
