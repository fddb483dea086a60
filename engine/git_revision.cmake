# Writes the git revision header at build time (run by the agv_git_revision target on every
# build): the 12-digit short hash of HEAD, with "-dirty" when a tracked file differs from HEAD
# (staged or not; untracked files do not count, as for `git describe --dirty`), or "unknown"
# without git or outside a git checkout of SOURCE_DIR. The header is rewritten only when its
# text changes, so a build of an unchanged tree recompiles and relinks nothing.
#
#   cmake -DSOURCE_DIR=... -DGIT_EXECUTABLE=... -DOUTPUT=... -P git_revision.cmake

set(revision "unknown")
if(GIT_EXECUTABLE)
  execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${SOURCE_DIR}" rev-parse --show-toplevel
    OUTPUT_VARIABLE toplevel RESULT_VARIABLE toplevel_rc
    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  file(REAL_PATH "${SOURCE_DIR}" source_real)
  if(toplevel_rc EQUAL 0)
    file(REAL_PATH "${toplevel}" toplevel_real)
  endif()
  # A source tree unpacked inside some other checkout must not take that checkout's revision.
  if(toplevel_rc EQUAL 0 AND toplevel_real STREQUAL source_real)
    execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${SOURCE_DIR}" rev-parse --short=12 HEAD
      OUTPUT_VARIABLE head RESULT_VARIABLE head_rc
      OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    # --no-optional-locks: a build must not take the index lock from a git command the user
    # runs at the same time.
    execute_process(
      COMMAND "${GIT_EXECUTABLE}" -C "${SOURCE_DIR}" --no-optional-locks status --porcelain
              --untracked-files=no
      OUTPUT_VARIABLE changes RESULT_VARIABLE status_rc
      OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(head_rc EQUAL 0 AND status_rc EQUAL 0 AND head)
      set(revision "${head}")
      if(changes)
        string(APPEND revision "-dirty")
      endif()
    endif()
  endif()
endif()

set(text "#pragma once
// Generated at build time by engine/git_revision.cmake: the tree this binary was built from.
namespace agv {
inline constexpr const char* kGitRevision = \"${revision}\";
}  // namespace agv
")
set(old "")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUTPUT}" "${text}")
endif()
