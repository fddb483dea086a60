#pragma once
// Which sweep a report's and a journal's runs came from, when the config hash cannot tell: two
// sweeps of one config share it (and all their non-timing values) but not their times. Each fresh
// run draws a random sweep id that its resumes keep; every journal segment's header names its
// sweep ("sweep_id"), and a report lists the sweeps whose runs it holds (environment.sweep_ids:
// one, or a merge's shards). A journal given beside a report (compare's --runs-before/-after,
// the report scripts' --runs) must hold exactly the report's sweeps. Reports and journals from
// before the ids carry none: only their config hash is checked.

#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

namespace agv {

// 16 hex digits from the system's random source.
std::string new_sweep_id();

// A report's environment.sweep_ids; empty for a report from before them. Throws InputError
// naming `what` for a malformed list.
std::vector<std::string> report_sweep_ids(const nlohmann::json& report, const std::string& what);

// Throws InputError unless `journal_ids` (the ids of the journals' segments that name one) are
// exactly `report_ids`; nothing is checked when the report has none. A segment without an id
// (written before them) is no sweep's: the config hash alone matched it, and a resume by this
// version gave the rest of its runs an id. `journals` and `report` name the files.
void require_same_sweeps(const std::vector<std::string>& report_ids,
                         const std::set<std::string>& journal_ids, const std::string& journals,
                         const std::string& report);

}  // namespace agv
