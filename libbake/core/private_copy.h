// A private temporary copy of bytes already read, for the few readers that only open files by name
// (OIIO 2.4's PNG reader, OpenMesh's OFF reader). It lives in the temporary folder, is registered
// like every temporary (core/temporaries.h) and is removed when the copy goes out of scope.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "bake/core/status.h"

namespace bake {

class PrivateCopy {
 public:
  PrivateCopy() = default;
  ~PrivateCopy();
  PrivateCopy(const PrivateCopy&) = delete;
  PrivateCopy& operator=(const PrivateCopy&) = delete;

  // Writes `bytes` to a fresh file named bake-<stem>.XXXXXX<suffix>; I/O error naming `name` on failure.
  Status write(std::span<const std::uint8_t> bytes, const std::string& stem, const std::string& suffix,
               const std::string& name);
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace bake
