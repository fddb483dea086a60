#pragma once
// Planner plugins (docs/ARCHITECTURE.md "Plugins"): a shared library built against an installed
// agvbench (find_package(agvbench), target agvbench::plugin) that hands over registry entries
// (algos/registry.h PlannerInfo, with their parameter declarations) through ONE versioned C entry
// point, and nothing else: no registration by static initialisation (STYLE.md point 6).
//
//   extern "C" AGVBENCH_PLUGIN_EXPORT const AgvPlugin* agvbench_plugin_v1(void) {
//     static const AgvPlugin plugin = {AGVBENCH_PLUGIN_BUILD, "my_plugin", "1.0", add_planners};
//     return &plugin;
//   }
//
// where add_planners(void* planners) appends to *static_cast<std::vector<agv::PlannerInfo>*>.
// The engine (engine/plan/plugins.h) reads the plain-C build record first and calls add_planners
// only when it matches its own: the same plugin ABI, the same agvbench version (the headers that
// define PlannerInfo, Planner and PlanRequest), the same compiler family and major version and
// the same C++ standard library ABI, because C++ objects cross the boundary. The record is made
// of macros, expanded in the plugin's own translation unit: an inline function would be taken
// from the engine at load time (the program exports its symbols) and describe the engine.
//
// A plugin takes every symbol of core/ and algos/ from the agvbench program that loads it, never
// a copy of its own, so the engine's per-thread collision-check counter counts a plugin's checks
// like any planner's.

#include <vector>  // the standard library's version macros

#include "algos/registry.h"
#include "core/version.h"

// The layout of AgvPlugin and AgvPluginBuild and the meaning of add_planners; a change bumps it
// and renames the entry point.
#define AGVBENCH_PLUGIN_ABI 1
#define AGVBENCH_PLUGIN_ENTRY "agvbench_plugin_v1"

#define AGVBENCH_PLUGIN_STR2(x) #x
#define AGVBENCH_PLUGIN_STR(x) AGVBENCH_PLUGIN_STR2(x)
#if defined(__clang__)
#define AGVBENCH_PLUGIN_COMPILER "clang " AGVBENCH_PLUGIN_STR(__clang_major__)
#elif defined(__GNUC__)
#define AGVBENCH_PLUGIN_COMPILER "gcc " AGVBENCH_PLUGIN_STR(__GNUC__)
#else
#define AGVBENCH_PLUGIN_COMPILER "unknown compiler"
#endif
#if defined(_LIBCPP_VERSION)
#define AGVBENCH_PLUGIN_STDLIB_NAME "libc++ abi " AGVBENCH_PLUGIN_STR(_LIBCPP_ABI_VERSION)
#elif defined(__GLIBCXX__) && _GLIBCXX_USE_CXX11_ABI
#define AGVBENCH_PLUGIN_STDLIB_NAME "libstdc++ cxx11-abi"
#elif defined(__GLIBCXX__)
#define AGVBENCH_PLUGIN_STDLIB_NAME "libstdc++ old-abi"
#else
#define AGVBENCH_PLUGIN_STDLIB_NAME "unknown standard library"
#endif
// The debug mode changes the layout of every container.
#if defined(_GLIBCXX_DEBUG) || defined(_LIBCPP_DEBUG)
#define AGVBENCH_PLUGIN_STDLIB AGVBENCH_PLUGIN_STDLIB_NAME " debug"
#else
#define AGVBENCH_PLUGIN_STDLIB AGVBENCH_PLUGIN_STDLIB_NAME
#endif
// What engine and plugin must share, as one string: "gcc 12, libstdc++ cxx11-abi".
#define AGVBENCH_PLUGIN_TOOLCHAIN AGVBENCH_PLUGIN_COMPILER ", " AGVBENCH_PLUGIN_STDLIB

#define AGVBENCH_PLUGIN_EXPORT __attribute__((visibility("default")))

extern "C" {

// Plain C, read before anything else of the plugin is touched.
struct AgvPluginBuild {
  int abi;                       // AGVBENCH_PLUGIN_ABI
  const char* agvbench_version;  // AGVBENCH_VERSION of the headers it was compiled with
  const char* toolchain;         // AGVBENCH_PLUGIN_TOOLCHAIN
  const char* compiler;          // the full compiler version, for the report
};

struct AgvPlugin {
  AgvPluginBuild build;
  const char* name;     // unique among the plugins of a run: [A-Za-z0-9_.-]+
  const char* version;  // the plugin's own version
  // Appends the plugin's planners to the std::vector<agv::PlannerInfo> that `planners` points
  // to; called once, after the build record matched.
  void (*add_planners)(void* planners);
};

// The entry point every plugin defines (AGVBENCH_PLUGIN_ENTRY names it for dlsym).
typedef const AgvPlugin* (*AgvPluginEntry)(void);
}

// The build record of the translation unit that expands it.
#define AGVBENCH_PLUGIN_BUILD \
  AgvPluginBuild { AGVBENCH_PLUGIN_ABI, AGVBENCH_VERSION, AGVBENCH_PLUGIN_TOOLCHAIN, __VERSION__ }
