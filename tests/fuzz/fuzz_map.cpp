// libFuzzer harness for the MovingAI .map reader: arbitrary bytes either parse or throw
// InputError (anything else, a crash, a leak or a hang is a finding). A map that parses, written
// back with write_map and read again, must give the same cells, and writing is a fixed point.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "generators/movingai.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  agv::Grid grid;
  try {
    std::istringstream in(bytes);
    grid = agv::parse_map(in, "fuzz.map");
  } catch (const agv::InputError&) {
    return 0;
  }
  std::ostringstream out;
  agv::write_map(grid, out);
  const std::string written = out.str();
  agv::Grid again;
  try {
    std::istringstream in(written);
    again = agv::parse_map(in, "rewritten.map");
  } catch (const agv::InputError& e) {
    std::fprintf(stderr, "fuzz_map: write_map output does not parse: %s\n", e.what());
    std::abort();
  }
  if (!grid.same_cells(again)) {
    std::fprintf(stderr, "fuzz_map: map read back after write_map differs\n");
    std::abort();
  }
  std::ostringstream out2;
  agv::write_map(again, out2);
  if (out2.str() != written) {
    std::fprintf(stderr, "fuzz_map: write_map is not a fixed point\n");
    std::abort();
  }
  return 0;
}
