# The installed CMake package (README "Your own planner as a plugin"): `cmake --install build
# --prefix P` puts the agvbench program in P/bin, the libraries in P/lib, every header of core/,
# generators/, algos/ and engine/ under P/include/agvbench/ and the package files in
# P/lib/cmake/agvbench, so that `find_package(agvbench CONFIG)` gives
#   agvbench::core, agvbench::generators, agvbench::algos, agvbench::engine  the static libraries
#       (PIC), for programs of one's own built on them;
#   agvbench::plugin  headers and header-only dependencies only, for a planner plugin: its
#       symbols come from the agvbench program that loads it (engine/plan/plugins.h), so a plugin
#       shares the engine's one copy of everything (the thread-local collision-check counter
#       among them) instead of linking a second.
# Includes: P/include/agvbench is on the include path, so the repository's own spelling
# ("algos/planner.h") works, as the installed headers include each other that way; P/include
# is too, for the namespaced spelling ("agvbench/algos/planner.h") that a user's project with a
# core/ of its own should prefer. The build's warnings and -march=native stay in the build
# (agv::options is a build-time requirement only): a consumer chooses its own flags.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(AGVBENCH_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/agvbench)

# Headers only: the plugin interface target.
add_library(agv_plugin INTERFACE)
add_library(agv::plugin ALIAS agv_plugin)
target_link_libraries(agv_plugin INTERFACE Eigen3::Eigen nlohmann_json::nlohmann_json
  nanoflann::nanoflann)

foreach(target agv_core agv_generators agv_algos agv_engine agv_plugin)
  string(REPLACE "agv_" "" export_name ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
  target_include_directories(${target} INTERFACE
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/agvbench>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(${target} INTERFACE cxx_std_20)
endforeach()
target_include_directories(agv_plugin INTERFACE $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
  $<BUILD_INTERFACE:${AGVBENCH_GENERATED_INCLUDE}> $<BUILD_INTERFACE:${PCG_INCLUDE_DIR}>)

install(TARGETS agv_core agv_generators agv_algos agv_engine agv_plugin EXPORT agvbenchTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS agvbench RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY core generators algos engine DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/agvbench
  FILES_MATCHING PATTERN "*.h")
install(FILES ${AGVBENCH_GENERATED_INCLUDE}/core/version.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/agvbench/core)
install(EXPORT agvbenchTargets NAMESPACE agvbench:: DESTINATION ${AGVBENCH_CMAKE_DIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/agvbenchConfig.cmake.in
  ${PROJECT_BINARY_DIR}/agvbenchConfig.cmake INSTALL_DESTINATION ${AGVBENCH_CMAKE_DIR})
# A plugin runs only in the agvbench of its own version (checked at load time as well).
write_basic_package_version_file(${PROJECT_BINARY_DIR}/agvbenchConfigVersion.cmake
  COMPATIBILITY ExactVersion)
install(FILES ${PROJECT_BINARY_DIR}/agvbenchConfig.cmake
  ${PROJECT_BINARY_DIR}/agvbenchConfigVersion.cmake DESTINATION ${AGVBENCH_CMAKE_DIR})
