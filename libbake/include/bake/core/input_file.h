// Reading inputs, the one way every tool does it. readFileBytes (core/atomic_file.h) opens a file
// once and reads it with a bound, whatever kind of file it is:
// - a regular file: its size is checked against the input-bytes budget before reading, and the read
//   stops at the budget even when the size was unknown or wrong (/proc files say 0);
// - a pipe or FIFO (`<(...)`, /dev/stdin from a pipe): read once, to its end, under the same budget,
//   and kept: reading it again in the same process gives the same bytes;
//   opened without blocking, then waited on for at most kPipeIdleSeconds at a time: a FIFO whose
//   writer never comes, or stops sending, is an I/O error, never a hang;
// - a device node or socket (/dev/zero, /dev/urandom, a terminal): refused, never read;
// - a directory: refused.
// Errors of the system (EIO, EACCES) are I/O errors (exit 2). The content hash of every input read
// this way is remembered, so the report and the cache never open an input a second time (a FIFO could
// not be read twice).
#pragma once

#include <filesystem>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "bake/core/status.h"

namespace bake {

inline constexpr int kPipeIdleSeconds = 10;

// The content hash (core/hash.h) of `path` when readFileBytes has read it in this process.
std::optional<std::string> hashOfReadInput(const std::filesystem::path& path);
struct ReadInput {
  std::uint64_t bytes = 0;
  std::string hash;
};
std::optional<ReadInput> readInputRecord(const std::filesystem::path& path);

// I/O error when `path` exists and is not a regular file or a pipe (a device, a socket, a
// directory): what readFileBytes would refuse, for readers that must name the file first.
Status checkInputKind(const std::filesystem::path& path);

// A text input without its UTF-8 byte-order mark, if it has one: every text reader accepts one.
std::string_view withoutByteOrderMark(std::string_view text);

// URI confinement (process-wide policy like the budgets, set by --allow-outside-uris): whether a
// .gltf may name buffers and images outside its own folder. Off by default.
bool outsideUrisAllowed();
void setOutsideUrisAllowed(bool allowed);

}  // namespace bake
