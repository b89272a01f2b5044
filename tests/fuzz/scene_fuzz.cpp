// Scene descriptions (bakepipe's input): JSON parse errors are caught as readScene does; anything
// parseScene throws is a finding. Relative input paths resolve in a directory that does not exist.
#include <nlohmann/json.hpp>

#include "fuzz_support.h"
#include "pipe/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(bake::fuzz::asText(data, size));
  } catch (const nlohmann::json::exception&) {
    return 0;
  }
  (void)bake::pipe::parseScene(doc, "/nonexistent-bake-fuzz/scene.json");
  return 0;
}
