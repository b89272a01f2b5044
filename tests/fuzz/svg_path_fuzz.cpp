// SVG 1.1 path data as groove scenes give it ("d" strings).
#include "fuzz_support.h"
#include "groove/path_svg.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  (void)bake::groove::parseSvgPath(bake::fuzz::asText(data, size), "fuzz.json", "/grooves/0/path");
  return 0;
}
