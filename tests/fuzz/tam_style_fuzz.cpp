// tambake's stroke style JSON (the stroke image's path is resolved, not read).
#include "bake/hatching/style.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  (void)bake::hatching::parseStyle(bake::fuzz::asText(data, size), "fuzz.json", "/nonexistent-bake-fuzz", false);
  return 0;
}
