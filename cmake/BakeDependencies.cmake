# Every dependency is a Debian 12 package (scripts/setup.sh installs them).
# Trap: OpenImageIO's CMake config fails unless openimageio-tools (iconvert, oiiotool, ...) is installed.
find_package(Threads REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(CLI11 2.1 REQUIRED)
find_package(OpenMesh REQUIRED)
find_package(OpenImageIO REQUIRED)
find_package(zstd REQUIRED)
find_package(LibXml2 REQUIRED)  # SVG drawings as groove input
# Draco is linked statically: Debian's libdraco.so exports a private copy of tinygltf. We read glTF
# with our own reader (libbake/io/glb_read.cpp explains why Debian's tinygltf cannot open Draco files).
find_package(draco REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(XXHASH REQUIRED IMPORTED_TARGET libxxhash)
if(BAKE_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()

# Geodesic solvers: Eigen for sparse matrices, CHOLMOD (SuiteSparse 5, no CMake config in Debian 12)
# for the supernodal Cholesky factorisation of the heat method.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig REQUIRED)
add_library(bake_cholmod INTERFACE)
target_include_directories(bake_cholmod INTERFACE ${CHOLMOD_INCLUDE_DIR})
target_link_libraries(bake_cholmod INTERFACE ${CHOLMOD_LIBRARY} ${SUITESPARSECONFIG_LIBRARY})

# CGAL: exact predicates for the independent references a bake measures itself against (libbake,
# few translation units: its headers are slow to compile), and the geodesic peer of tests and benchmarks.
find_package(CGAL REQUIRED)
# CGAL's exact rationals: what libbake links for them (CGAL::CGAL itself would put -frounding-math on
# every libbake source).
find_library(BAKE_GMP_LIBRARY gmp REQUIRED)
find_library(BAKE_MPFR_LIBRARY mpfr REQUIRED)
set(BAKE_GMP_LIBRARIES ${BAKE_MPFR_LIBRARY} ${BAKE_GMP_LIBRARY})
