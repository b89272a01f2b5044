// SVG files as groove input (libbake/grooves/input/svg_file.h): libxml2's parse, then the shapes, groups and
// transforms read into path pieces with the placement a scene gives.
#include "fuzz_support.h"
#include "grooves/input/svg_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = bake::fuzz::writeInput(data, size, "drawing.svg");
  (void)bake::grooves::readSvgFile(file, bake::grooves::SvgPlacement{{0.1, 0.2}, 0.01}, "/paths/0");
  return 0;
}
