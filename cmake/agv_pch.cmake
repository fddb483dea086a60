# Precompiled headers (issue 25: build time). Every translation unit of ours reads nlohmann-json
# through core/params.h (1.6 s of parsing alone, GCC 12 -O2), the tests GoogleTest (1.2 s) and the
# benchmarks Google Benchmark: parsed once per target instead of once per file. The test and
# benchmark executables share one header each (REUSE_FROM), since most hold one or two files.
# The headers are still included where they are used: the sources build without it
# (-DAGVBENCH_PCH=OFF).
option(AGVBENCH_PCH "Precompile the heavy third-party headers" ON)

set(AGV_PCH_COMMON <nlohmann/json.hpp> <algorithm> <cmath> <cstdint> <functional> <map>
  <memory> <optional> <string> <string_view> <utility> <vector>)

# agv_pch(TARGET [HEADER...]): TARGET precompiles the common headers plus HEADERs.
function(agv_pch target)
  if(AGVBENCH_PCH)
    target_precompile_headers(${target} PRIVATE ${AGV_PCH_COMMON} ${ARGN})
  endif()
endfunction()

# agv_pch_shared(TARGET FIRST [HEADER...]): TARGET uses FIRST's precompiled header, which the first
# target of a family (FIRST itself) builds from the common headers plus HEADERs.
function(agv_pch_shared target first)
  if(NOT AGVBENCH_PCH)
    return()
  endif()
  if(target STREQUAL first)
    target_precompile_headers(${target} PRIVATE ${AGV_PCH_COMMON} ${ARGN})
  else()
    target_precompile_headers(${target} REUSE_FROM ${first})
  endif()
endfunction()
