#include "engine/outputs/sweep_identity.h"

#include <cstdio>
#include <random>

#include "core/input_error.h"
#include "core/json_text.h"

namespace agv {

std::string new_sweep_id() {
  std::random_device source;
  const auto high = static_cast<unsigned long long>(source());
  const auto low = static_cast<unsigned long long>(source());
  char buf[17];
  std::snprintf(buf, sizeof buf, "%08llx%08llx", high & 0xffffffffULL, low & 0xffffffffULL);
  return buf;
}

std::vector<std::string> report_sweep_ids(const nlohmann::json& report, const std::string& what) {
  if (!report.is_object() || !report.contains("environment")) return {};
  const nlohmann::json& env = report.at("environment");
  if (!env.is_object() || !env.contains("sweep_ids")) return {};
  const nlohmann::json& ids = env.at("sweep_ids");
  std::vector<std::string> out;
  if (ids.is_array())
    for (const auto& id : ids)
      if (id.is_string() && !id.get_ref<const std::string&>().empty())
        out.push_back(id.get<std::string>());
  if (!ids.is_array() || out.size() != ids.size())
    throw InputError(what + ": environment.sweep_ids is not a list of sweep ids (" +
                     json_text(ids) + ")");
  return out;
}

namespace {

std::string listed(const std::set<std::string>& ids) {
  std::string out;
  for (const auto& id : ids) out += (out.empty() ? "" : ", ") + id;
  return out.empty() ? "(none: written before sweep ids)" : out;
}

}  // namespace

void require_same_sweeps(const std::vector<std::string>& report_ids,
                         const std::set<std::string>& journal_ids, const std::string& journals,
                         const std::string& report) {
  if (report_ids.empty()) return;
  const std::set<std::string> want(report_ids.begin(), report_ids.end());
  if (journal_ids == want) return;
  throw InputError(journals + ": holds sweep " + listed(journal_ids) + ", but " + report +
                   " reports sweep " + listed(want) +
                   ": not this report's journal (another sweep of the same config has other "
                   "times; a merged report needs every shard's journal)");
}

}  // namespace agv
