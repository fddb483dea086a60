# agv_simd_levels(TARGET SOURCE PREFIX LIBS...): compiles SOURCE once per instruction-set level of
# core/simd_path.h into TARGET, as OBJECT libraries PREFIX_LEVEL (each copy in the namespace its
# AGV_SIMD_LEVEL names, with the level's features applied through core/simd_target.h), and
# defines AGV_SIMD_LEVELS_X86=1 on TARGET when the x86-64 levels are built, for the code that
# picks a copy. LIBS give the copies their compile settings (flags, include folders); their
# objects go into TARGET, which links what they need. core/simd_path.cpp checks the same features
# at run time: change both together.
set(AGV_SIMD_TARGET_avx2 "sse3,ssse3,sse4.1,sse4.2,popcnt,avx,avx2,fma,bmi,bmi2")
set(AGV_SIMD_TARGET_avx512 "${AGV_SIMD_TARGET_avx2},avx512f,avx512bw,avx512cd,avx512dq,avx512vl")
if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
  set(AGV_SIMD_LEVELS baseline avx2 avx512)
else()
  set(AGV_SIMD_LEVELS baseline)
endif()

function(agv_simd_levels target source prefix)
  if(AGV_SIMD_LEVELS MATCHES "avx2")
    target_compile_definitions(${target} PRIVATE AGV_SIMD_LEVELS_X86=1)
  endif()
  foreach(level IN LISTS AGV_SIMD_LEVELS)
    add_library(${prefix}_${level} OBJECT ${source})
    set_target_properties(${prefix}_${level} PROPERTIES UNITY_BUILD OFF)
    target_compile_definitions(${prefix}_${level} PRIVATE AGV_SIMD_LEVEL=${level})
    if(DEFINED AGV_SIMD_TARGET_${level})
      target_compile_definitions(${prefix}_${level} PRIVATE
        "AGV_SIMD_TARGET=\"${AGV_SIMD_TARGET_${level}}\"")
    endif()
    target_link_libraries(${prefix}_${level} PRIVATE ${ARGN})
    target_sources(${target} PRIVATE $<TARGET_OBJECTS:${prefix}_${level}>)
  endforeach()
endfunction()
