# Every dependency is a Debian 12 package (scripts/setup.sh installs them).
# Trap: OpenImageIO's CMake config fails unless openimageio-tools (iconvert, oiiotool, ...) is installed.
find_package(Threads REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(CLI11 2.1 REQUIRED)
find_package(OpenMesh REQUIRED)
find_package(OpenImageIO REQUIRED)
find_package(zstd REQUIRED)
# Draco is linked statically: Debian's libdraco.so exports a private copy of tinygltf. We read glTF
# with our own reader (libbake/io/glb_read.cpp explains why Debian's tinygltf cannot open Draco files).
find_package(draco REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(XXHASH REQUIRED IMPORTED_TARGET libxxhash)
if(BAKE_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
