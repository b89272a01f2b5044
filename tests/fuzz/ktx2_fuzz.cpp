// KTX2 textures: the header describer and the full decoder (levels, DFD, key/value data, zstd).
#include <span>

#include "io/ktx2.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  (void)bake::ktx2::decodeHeader(bytes, "fuzz.ktx2");
  (void)bake::ktx2::decode(bytes, "fuzz.ktx2");
  return 0;
}
