// Groove scene JSON (groovebake's input): parsing, checking and finishing the scene (paths, SVG path
// data, cross-sections, flattening).
#include "fuzz_support.h"
#include "groove/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  (void)bake::groove::parseGrooveScene(bake::fuzz::asText(data, size), "fuzz.json");
  return 0;
}
