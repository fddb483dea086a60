// libFuzzer harness for the sweep config loader: arbitrary bytes through nlohmann::json::parse
// (exceptions off: malformed JSON is discarded) and parse_config. Only InputError or a
// nlohmann::json exception may come out; anything else, a crash, a leak or a hang is a finding.
// A config that parses must survive its own round trip: config_as_run parses back to the same
// config hash (the journal's compatibility key).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/sweep_config.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto j = nlohmann::json::parse(data, data + size, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return 0;
  // "plugins" would dlopen whatever shared library a fuzzed path names (and keep it loaded for
  // every later input): the plugin loader has its own tests (cli_plugin), not this harness.
  if (j.is_object() && j.contains("plugins")) return 0;
  agv::SweepConfig config;
  try {
    config = agv::parse_config(j);
  } catch (const agv::InputError&) {
    return 0;
  } catch (const nlohmann::json::exception&) {
    return 0;
  }
  const nlohmann::json as_run = agv::config_as_run(config);
  try {
    const agv::SweepConfig again = agv::parse_config(as_run);
    if (agv::config_hash(again) != agv::config_hash(config)) {
      std::fprintf(stderr, "fuzz_config: config_as_run does not parse back to the same hash\n%s\n",
                   as_run.dump().c_str());
      std::abort();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_config: config_as_run does not parse back: %s\n%s\n", e.what(),
                 as_run.dump().c_str());
    std::abort();
  }
  return 0;
}
