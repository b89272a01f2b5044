# Every dependency is a Debian 12 package (scripts/setup.sh installs them).
# Trap: OpenImageIO's CMake config fails unless openimageio-tools (iconvert, oiiotool, ...) is installed.
find_package(Threads REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(CLI11 2.1 REQUIRED)
find_package(OpenMesh REQUIRED)
find_package(OpenImageIO REQUIRED)
find_package(TinyGLTF REQUIRED)
find_package(zstd REQUIRED)
# Debian's libdraco.so also exports its own copy of tinygltf, with a different layout; linking the
# static archive pulls in only the codec objects, so tinygltf symbols come from libtinygltf alone.
find_package(draco REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(XXHASH REQUIRED IMPORTED_TARGET libxxhash)
if(BAKE_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
