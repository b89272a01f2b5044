# find_package(BakeTools): the installed bakers as imported executables (BakeTools::geobake,
# BakeTools::groovebake, ...) and bake_add_asset() (BakeAsset.cmake) to bake assets at build time.
include("${CMAKE_CURRENT_LIST_DIR}/BakeToolsTargets.cmake")
include("${CMAKE_CURRENT_LIST_DIR}/BakeAsset.cmake")
