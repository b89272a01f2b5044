// revolbake's vector profile inputs: the JSON, CSV and SVG readers (they take a path), each followed
// by the profile check that normalises contours.
#include <string>
#include <vector>

#include "bake/revolution/profile.h"
#include "fuzz_support.h"

namespace {

void check(bake::Result<bake::revolution::Profile> profile) {
  if (!profile.isOk()) return;
  std::vector<std::string> warnings;
  (void)bake::revolution::validateProfile(*profile, warnings);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = bake::fuzz::writeInput(data, size, "profile").string();
  check(bake::revolution::readProfileJson(path));
  check(bake::revolution::readProfileCsv(path));
  check(bake::revolution::readProfileSvg(path));
  return 0;
}
