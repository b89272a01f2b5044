#include "bake/core/status.h"

namespace bake {

const char* exitCodeName(ExitCode code) {
  switch (code) {
    case ExitCode::Ok: return "ok";
    case ExitCode::Usage: return "usage";
    case ExitCode::Io: return "io";
    case ExitCode::InvalidInput: return "invalid-input";
    case ExitCode::Internal: return "internal";
    case ExitCode::Unsupported: return "unsupported";
  }
  return "unknown";
}

Status& Status::inFile(const std::string& file) {
  if (where_.file.empty()) where_.file = file;
  return *this;
}

Status& Status::atElement(const std::string& element) {
  if (where_.element.empty()) where_.element = element;
  return *this;
}

std::string Status::describe() const {
  std::string text;
  if (!where_.file.empty()) text += where_.file + ": ";
  if (!where_.element.empty()) text += where_.element + ": ";
  return text + message_;
}

Status ioError(std::string message, Location where) {
  return {ExitCode::Io, std::move(message), std::move(where)};
}
Status invalidInput(std::string message, Location where) {
  return {ExitCode::InvalidInput, std::move(message), std::move(where)};
}
Status unsupported(std::string message, Location where) {
  return {ExitCode::Unsupported, std::move(message), std::move(where)};
}
Status internalError(std::string message, Location where) {
  return {ExitCode::Internal, std::move(message), std::move(where)};
}
Status usageError(std::string message) { return {ExitCode::Usage, std::move(message)}; }

}  // namespace bake
