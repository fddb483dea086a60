#include "engine/outputs/report.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include "core/json_text.h"
#include "engine/judge/metric_specs.h"
#include "engine/judge/statistics.h"
#include "engine/system/environment.h"
#include "engine/system/file_writes.h"

namespace agv {

using nlohmann::json;

json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

namespace {

json summary_json(const Summary& s) {
  return {{"count", s.count},
          {"mean", number_or_null(s.mean)},
          {"stddev", number_or_null(s.stddev)},
          {"min", number_or_null(s.min)},
          {"p5", number_or_null(s.p5)},
          {"median", number_or_null(s.median)},
          {"p95", number_or_null(s.p95)},
          {"max", number_or_null(s.max)},
          {"ci95", {number_or_null(s.ci95.lo), number_or_null(s.ci95.hi)}}};
}

json paired_json(const PairedComparison& c, const MetricSpec& spec) {
  return {{"pairs", c.pairs},
          {"better", spec.better == Better::smaller ? "smaller" : "larger"},
          {"wins", c.wins},
          {"ties", c.ties},
          {"losses", c.losses},
          {"ratio", spec.ratio == RatioKind::plain ? "plain" : "shifted"},
          {"geo_mean_ratio", number_or_null(c.geo_mean_ratio)},
          {"ci95", {number_or_null(c.geo_mean_ci95.lo), number_or_null(c.geo_mean_ci95.hi)}},
          {"ratios_excluded", c.ratio_excluded},
          {"mean_difference", number_or_null(c.mean_difference)},
          {"difference_ci95",
           {number_or_null(c.mean_difference_ci95.lo), number_or_null(c.mean_difference_ci95.hi)}},
          {"wilcoxon_p", number_or_null(c.wilcoxon.p)},
          {"wilcoxon_exact", c.wilcoxon.exact}};
}

constexpr double kTieTolerance = 1e-9;

std::size_t metric_index(std::string_view name) {
  for (std::size_t i = 0; i < kRunMetricNames.size(); ++i)
    if (kRunMetricNames[i] == name) return i;
  throw std::logic_error("unknown metric");
}

// Values of one metric over the successful runs of (cell, planner), in map order.
std::vector<double> successful_values(const SweepResults& r, const SweepCell& cell,
                                      std::size_t planner, std::size_t metric) {
  std::vector<double> out;
  for (int m = 0; m < cell.maps; ++m) {
    const RunSlot& s = r.run(cell.first_task + m, planner);
    if (s.done && s.outcome == Outcome::success && std::isfinite(s.metrics[metric]))
      out.push_back(s.metrics[metric]);
  }
  return out;
}

json planner_cell_json(const SweepResults& r, const SweepCell& cell, std::size_t p,
                       const PlannerEntry& entry) {
  std::array<std::int64_t, kOutcomeCount> counts{};
  std::int64_t runs = 0;
  std::vector<double> plan_times;
  std::map<std::string, std::vector<double>> phases;
  std::map<std::string, std::vector<double>> extras;
  for (int m = 0; m < cell.maps; ++m) {
    const RunSlot& s = r.run(cell.first_task + m, p);
    if (!s.done) continue;
    ++runs;
    ++counts[static_cast<int>(s.outcome)];
    plan_times.push_back(static_cast<double>(s.plan_time_ns));
    for (const auto& ph : s.phases) phases[ph.name].push_back(static_cast<double>(ph.ns));
    if (s.outcome == Outcome::success)
      for (const auto& [name, value] : s.extra)
        if (std::isfinite(value)) extras[name].push_back(value);
  }
  const auto successes = counts[static_cast<int>(Outcome::success)];
  const Interval wilson = wilson_interval(successes, runs, 0.95);
  json failures = json::object();
  for (int o = 1; o < kOutcomeCount; ++o)
    if (counts[o] > 0) failures[std::string(to_string(static_cast<Outcome>(o)))] = counts[o];
  json metrics = json::object();
  for (std::size_t i = 0; i < kRunMetricNames.size(); ++i) {
    const auto values = successful_values(r, cell, p, i);
    metrics[std::string(kRunMetricNames[i])] = summary_json(summarize(values));
  }
  for (const auto& [name, values] : extras) metrics[name] = summary_json(summarize(values));
  json phase_json = json::object();
  for (const auto& [name, values] : phases) phase_json[name] = summary_json(summarize(values));
  return {
      {"planner", entry.label},
      {"name", entry.name},
      {"runs", runs},
      {"successes", successes},
      {"success_rate",
       runs > 0 ? json(static_cast<double>(successes) / static_cast<double>(runs)) : json(nullptr)},
      {"success_ci95", {number_or_null(wilson.lo), number_or_null(wilson.hi)}},
      {"failures", failures},
      {"metrics", metrics},
      {"timing", {{"plan_time_ns", summary_json(summarize(plan_times))}, {"phases", phase_json}}}};
}

// One metric of one run by name: a run metric or an extra the planner reported; NaN when the
// run does not define it.
double slot_value(const RunSlot& s, std::string_view name) {
  for (std::size_t i = 0; i < kRunMetricNames.size(); ++i)
    if (kRunMetricNames[i] == name) return s.metrics[i];
  for (const auto& [extra, value] : s.extra)
    if (extra == name) return value;
  return kNaN;
}

bool succeeded(const RunSlot& s) { return s.done && s.outcome == Outcome::success; }

// Whether some successful run of (cell, planner) defines the metric: a metric a planner never
// reports is absent from its comparisons, never compared as 0 or NaN (docs/METRICS.md
// "Paired comparisons").
bool defines(const SweepResults& r, const SweepCell& cell, std::size_t planner,
             std::string_view name) {
  for (int m = 0; m < cell.maps; ++m) {
    const RunSlot& s = r.run(cell.first_task + m, planner);
    if (succeeded(s) && std::isfinite(slot_value(s, name))) return true;
  }
  return false;
}

// Pairs over the maps where both planners succeeded and both values are finite, in map order.
void paired_values(const SweepResults& r, const SweepCell& cell, std::size_t a, std::size_t b,
                   std::string_view name, std::vector<double>& va, std::vector<double>& vb) {
  va.clear();
  vb.clear();
  for (int m = 0; m < cell.maps; ++m) {
    const std::int64_t task = cell.first_task + m;
    const RunSlot& sa = r.run(task, a);
    const RunSlot& sb = r.run(task, b);
    if (!succeeded(sa) || !succeeded(sb)) continue;
    const double x = slot_value(sa, name);
    const double y = slot_value(sb, name);
    if (std::isfinite(x) && std::isfinite(y)) {
      va.push_back(x);
      vb.push_back(y);
    }
  }
}

// Planning time over every map both planners ran, failures included (docs/METRICS.md
// "Statistics conventions": a planner that fails slowly is not timed on its easy maps only).
void paired_times(const SweepResults& r, const SweepCell& cell, std::size_t a, std::size_t b,
                  std::vector<double>& va, std::vector<double>& vb) {
  va.clear();
  vb.clear();
  for (int m = 0; m < cell.maps; ++m) {
    const std::int64_t task = cell.first_task + m;
    const RunSlot& sa = r.run(task, a);
    const RunSlot& sb = r.run(task, b);
    if (!sa.done || !sb.done) continue;
    va.push_back(static_cast<double>(sa.plan_time_ns));
    vb.push_back(static_cast<double>(sb.plan_time_ns));
  }
}

PairedComparison compare(const std::vector<double>& va, const std::vector<double>& vb,
                         const MetricSpec& spec) {
  return compare_paired(va, vb, spec.better, spec.ratio, kTieTolerance);
}

json paired_cell_json(const SweepConfig& config, const SweepResults& r, const SweepCell& cell) {
  const std::size_t base = baseline_index(config);
  json out = json::array();
  std::vector<double> va, vb;
  for (std::size_t p = 0; p < r.labels.size(); ++p) {
    if (p == base || r.maps_of(cell, p) == 0) continue;
    json metrics = json::object();
    for (const MetricSpec& spec : kMetricSpecs) {
      if (!spec.paired || !defines(r, cell, p, spec.name) || !defines(r, cell, base, spec.name))
        continue;
      paired_values(r, cell, p, base, spec.name, va, vb);
      metrics[std::string(spec.name)] = paired_json(compare(va, vb, spec), spec);
    }
    paired_times(r, cell, p, base, va, vb);
    out.push_back(
        {{"planner", r.labels[p]},
         {"baseline", r.labels[base]},
         {"metrics", metrics},
         {"timing",
          {{"plan_time_ns", paired_json(compare(va, vb, kPlanTimeSpec), kPlanTimeSpec)}}}});
  }
  return out;
}

json cell_report_json(const SweepConfig& config, const SweepResults& r, const SweepCell& cell) {
  std::vector<double> fractions;
  std::int64_t rejections = 0, maps = 0;
  for (int m = 0; m < cell.maps; ++m) {
    const MapSlot& ms =
        r.cells[static_cast<std::size_t>(cell.index)].maps[static_cast<std::size_t>(m)];
    if (!ms.done) continue;
    ++maps;
    rejections += ms.rejections;
    fractions.push_back(ms.obstacle_fraction);
  }
  json planners = json::array();
  // A planner scoped out of this cell has no entry in it (rather than one with no runs).
  for (std::size_t p = 0; p < r.labels.size(); ++p)
    if (r.maps_of(cell, p) > 0)
      planners.push_back(planner_cell_json(r, cell, p, config.planners[p]));
  return {{"cell", cell.key},         {"generator", cell.generator},
          {"width", cell.size.width}, {"height", cell.size.height},
          {"density", cell.density},  {"maps", maps},
          {"rejections", rejections}, {"obstacle_fraction", summary_json(summarize(fractions))},
          {"planners", planners},     {"paired", paired_cell_json(config, r, cell)}};
}

double mean_of(double sum, std::int64_t count) {
  return count > 0 ? sum / static_cast<double>(count) : kNaN;
}

void append(PlannerTally& to, const PlannerTally& from) {
  to.runs += from.runs;
  to.successes += from.successes;
  const auto extend = [](std::vector<double>& a, const std::vector<double>& b) {
    a.insert(a.end(), b.begin(), b.end());
  };
  extend(to.plan_time_us, from.plan_time_us);
  const double turns[] = {to.turns_sum, from.turns_sum};
  const double checks[] = {to.checks_sum, from.checks_sum};
  to.turns_sum = compensated_sum(turns);
  to.checks_sum = compensated_sum(checks);
  extend(to.length, from.length);
  extend(to.baseline_length, from.baseline_length);
}

// What the summary table takes of each planner's runs in the cell, in map order.
std::vector<PlannerTally> planner_tallies(const SweepConfig& config, const SweepResults& r,
                                          const SweepCell& cell) {
  const std::size_t base = baseline_index(config);
  const std::size_t il = metric_index("path_length"), it = metric_index("turns");
  std::vector<PlannerTally> tallies(r.labels.size());
  for (std::size_t p = 0; p < r.labels.size(); ++p) {
    PlannerTally& t = tallies[p];
    std::vector<double> turns, checks;
    for (int m = 0; m < cell.maps; ++m) {
      const RunSlot& s = r.run(cell, m, p);
      if (!s.done) continue;
      ++t.runs;
      t.plan_time_us.push_back(static_cast<double>(s.plan_time_ns) / 1e3);
      if (s.outcome != Outcome::success) continue;
      ++t.successes;
      turns.push_back(s.metrics[it]);
      checks.push_back(slot_value(s, "collision_checks"));
      const RunSlot& sb = r.run(cell, m, base);
      if (sb.done && sb.outcome == Outcome::success) {
        t.length.push_back(s.metrics[il]);
        t.baseline_length.push_back(sb.metrics[il]);
      }
    }
    t.turns_sum = compensated_sum(turns);
    t.checks_sum = compensated_sum(checks);
    // A released cell keeps its tallies to the end of the sweep: no spare capacity.
    for (auto* v : {&t.plan_time_us, &t.length, &t.baseline_length}) v->shrink_to_fit();
  }
  return tallies;
}

}  // namespace

CellDigest digest_cell(const SweepConfig& config, const SweepResults& r, const SweepCell& cell) {
  CellDigest d;
  d.report_cbor = json::to_cbor(cell_report_json(config, r, cell));
  const Coverage c = cell_coverage_of(r, cell);
  d.runs_present = c.runs_present;
  d.maps_missing = c.maps_missing;
  d.tallies = planner_tallies(config, r, cell);
  return d;
}

namespace {

// The report with an empty "cells" array.
json report_frame(const SweepConfig& config, const SweepResults& r) {
  const Coverage coverage = coverage_of(r);
  json report = {
      {"schema_version", kReportSchemaVersion},
      {"tool", "agvbench"},
      {"config", config_as_run(config)},
      {"complete", r.complete},
      {"coverage",
       {{"runs_expected", coverage.runs_expected},
        {"runs_present", coverage.runs_present},
        {"maps_missing", coverage.maps_missing}}},
      {"totals",
       {{"cells", r.plan.cells.size()},
        {"maps", r.plan.map_tasks()},
        {"runs", coverage.runs_present}}},
      {"cells", json::array()},
      {"environment", environment_json(r.threads)},
      {"timing",
       {{"wall_s", r.wall_s},
        {"executed_runs", r.executed_runs},
        {"runs_per_s", r.wall_s > 0 ? static_cast<double>(r.executed_runs) / r.wall_s : 0.0}}}};
  if (r.shard_count > 1) report["shard"] = {{"index", r.shard_index}, {"count", r.shard_count}};
  report["environment"]["sweep_ids"] = r.sweep_ids;  // engine/outputs/sweep_identity.h
  return report;
}

json cell_entry(const SweepConfig& config, const SweepResults& r, const SweepCell& cell) {
  const auto& digest = r.cells[static_cast<std::size_t>(cell.index)].digest;
  return digest ? json::from_cbor(digest->report_cbor) : cell_report_json(config, r, cell);
}

}  // namespace

json build_report(const SweepConfig& config, const SweepResults& r) {
  json report = report_frame(config, r);
  json& cells = report["cells"];
  for (const auto& cell : r.plan.cells) cells.push_back(cell_entry(config, r, cell));
  return report;
}

std::string report_text(const SweepConfig& config, const SweepResults& r) {
  std::string frame = json_text(report_frame(config, r), 1);
  // "cells" sorts first among the report's keys: the frame opens with it.
  const std::string empty = "{\n \"cells\": []";
  if (frame.compare(0, empty.size(), empty) != 0)
    throw std::logic_error("report_text: the report no longer opens with its cells");
  std::string text = "{\n \"cells\": [";
  bool first = true;
  for (const auto& cell : r.plan.cells) {
    // An element of an array in the report's "cells" sits two levels deep: its standalone text
    // with every line indented by two.
    const std::string entry = json_text(cell_entry(config, r, cell), 1);
    text += first ? "\n  " : ",\n  ";
    first = false;
    for (const char c : entry) {
      text += c;
      if (c == '\n') text += "  ";
    }
  }
  if (!r.plan.cells.empty())
    text += "\n ]";
  else
    text += "]";
  text.append(frame, empty.size(), std::string::npos);
  text += "\n";
  return text;
}

void write_json_atomic(const json& document, const std::string& path) {
  write_file_atomic(json_text(document, 1) + "\n", path);
}

json deterministic_part(const json& report) {
  if (report.is_object()) {
    json out = json::object();
    for (const auto& [key, value] : report.items()) {
      if (key == "timing" || key == "environment") continue;
      out[key] = deterministic_part(value);
    }
    return out;
  }
  if (report.is_array()) {
    json out = json::array();
    for (const auto& v : report) out.push_back(deterministic_part(v));
    return out;
  }
  return report;
}

std::string summary_table(const SweepConfig& config, const SweepResults& r) {
  const std::size_t base = baseline_index(config);
  // The cells' tallies (a released cell's from its digest), one planner's at a time over the
  // cells in order: a whole sweep's tallies are never copied at once.
  std::vector<std::vector<PlannerTally>> live(r.plan.cells.size());
  for (const auto& cell : r.plan.cells)
    if (!r.cells[static_cast<std::size_t>(cell.index)].digest)
      live[static_cast<std::size_t>(cell.index)] = planner_tallies(config, r, cell);
  const auto sweep_tally = [&](std::size_t p) {
    PlannerTally t;
    for (const auto& cell : r.plan.cells) {
      const auto i = static_cast<std::size_t>(cell.index);
      append(t, r.cells[i].digest ? r.cells[i].digest->tallies[p] : live[i][p]);
    }
    return t;
  };
  std::ostringstream out;
  char line[256];
  // %11s: "µ" is two bytes and one column.
  std::snprintf(line, sizeof line, "%-24s %8s %8s %10s %12s %8s %12s %11s\n", "planner", "runs",
                "success", "len/base", "[95% CI]", "turns", "checks", "median µs");
  out << line;
  for (std::size_t p = 0; p < r.labels.size(); ++p) {
    const PlannerTally t = sweep_tally(p);
    const PairedComparison c =
        compare(t.length, t.baseline_length, *find_metric_spec("path_length"));
    char ci[64];
    std::snprintf(ci, sizeof ci, "[%.3f,%.3f]", c.geo_mean_ci95.lo, c.geo_mean_ci95.hi);
    std::snprintf(
        line, sizeof line, "%-24s %8lld %7.1f%% %10.4f %12s %8.2f %12.0f %10.1f\n",
        r.labels[p].c_str(), static_cast<long long>(t.runs),
        t.runs ? 100.0 * static_cast<double>(t.successes) / static_cast<double>(t.runs) : 0.0,
        c.geo_mean_ratio, p == base ? "(baseline)" : ci, mean_of(t.turns_sum, t.successes),
        mean_of(t.checks_sum, t.successes), summarize(t.plan_time_us).median);
    out << line;
  }
  return out.str();
}

}  // namespace agv
