// SVG 1.1 path data as groove scenes give it ("d" strings).
#include "fuzz_support.h"
#include "io/svg_path.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  (void)bake::svg::parsePathData(bake::fuzz::asText(data, size), "fuzz.json", "/grooves/0/path");
  return 0;
}
