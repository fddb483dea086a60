#include "engine/outputs/report_compare.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include "core/input_error.h"
#include "core/json_text.h"
#include "core/rng.h"
#include "core/str_cat.h"
#include "core/text_file.h"
#include "engine/outputs/journal.h"
#include "engine/outputs/report.h"
#include "engine/outputs/run_record.h"

namespace agv {

using nlohmann::json;

namespace {

std::string label_of(const json& entry) { return entry.value("planner", std::string()); }

// The parts of a report the comparison walks, each of the type it reads: a hand-edited or damaged
// report is InputError naming its field, not the JSON library's type_error after half the work.
void require_shape(const json& r, const std::string& name) {
  const auto fail = [&name](const std::string& field, const char* want) {
    throw InputError(name + ": " + field + ": expected " + want + " (a damaged report?)");
  };
  if (!r.at("config").is_object()) fail("config", "an object");
  const json& planners = r["config"].value("planners", json::array());
  if (!planners.is_array()) fail("config.planners", "a list");
  for (std::size_t i = 0; i < planners.size(); ++i)
    if (!planners[i].is_object()) fail(str_cat("config.planners[", i, "]"), "an object");
  if (!r.at("cells").is_array()) fail("cells", "a list");
  for (std::size_t i = 0; i < r["cells"].size(); ++i) {
    const json& cell = r["cells"][i];
    const std::string at = str_cat("cells[", i, "]");
    if (!cell.is_object()) fail(at, "an object");
    if (!cell.value("cell", json()).is_string()) fail(at + ".cell", "a string");
    if (!cell.value("planners", json()).is_array()) fail(at + ".planners", "a list");
    for (std::size_t k = 0; k < cell["planners"].size(); ++k) {
      const json& p = cell["planners"][k];
      const std::string pk = str_cat(at, ".planners[", k, "]");
      if (!p.is_object()) fail(pk, "an object");
      if (!p.value("planner", json()).is_string()) fail(pk + ".planner", "a string");
      if (p.contains("timing") && !p["timing"].is_object()) fail(pk + ".timing", "an object");
    }
  }
}

// A report this build can read, or InputError naming `name`.
void require_report(const json& r, const std::string& name) {
  if (!r.is_object() || r.value("tool", json()) != "agvbench" || !r.contains("config") ||
      !r.contains("cells"))
    throw InputError(name + ": not an agvbench report (no \"tool\": \"agvbench\", config, cells)");
  const json version = r.value("schema_version", json());
  if (version != kReportSchemaVersion)
    throw InputError(name + ": report schema_version " + json_text(version) +
                     "; this agvbench reads " + std::to_string(kReportSchemaVersion) +
                     " (re-run the sweep)");
  require_shape(r, name);
}

// The config without what `compare` lets differ: the planners' parameters (and what they
// loosen, which follows from them).
json without_planner_params(json config) {
  if (config.contains("planners") && config["planners"].is_array())
    for (json& p : config["planners"]) {
      p.erase("params");
      p.erase("looser_than_model");
    }
  return config;
}

std::string short_dump(const json& v) {
  std::string text = json_text(v);
  return text.size() > 80 ? text.substr(0, 77) + "..." : text;
}

void check_configs(const json& a, const json& b) {
  const json sa = without_planner_params(a), sb = without_planner_params(b);
  if (sa == sb) return;
  std::string what;
  std::set<std::string> keys;
  for (const auto& [k, v] : sa.items()) keys.insert(k);
  for (const auto& [k, v] : sb.items()) keys.insert(k);
  for (const std::string& k : keys) {
    const json x = sa.value(k, json()), y = sb.value(k, json());
    if (x == y) continue;
    if (!what.empty()) what += "; ";
    if (k == "planners" && x.is_array() && y.is_array() && x.size() == y.size()) {
      for (std::size_t i = 0; i < x.size(); ++i)
        if (x[i] != y[i])
          what += "planners[" + std::to_string(i) + "] " + short_dump(x[i]) + " -> " +
                  short_dump(y[i]) + " ";
    } else {
      what += k + " " + short_dump(x) + " -> " + short_dump(y);
    }
  }
  throw InputError(
      "the reports are of configs that differ in more than planner parameters, so their results "
      "cannot be compared: " +
      what);
}

std::vector<std::string> parameter_changes(const json& a, const json& b) {
  std::vector<std::string> out;
  const json& pa = a.at("planners");
  const json& pb = b.at("planners");
  for (std::size_t i = 0; i < pa.size(); ++i) {
    const json x = pa[i].value("params", json::object()), y = pb[i].value("params", json::object());
    if (x == y) continue;
    std::set<std::string> keys;
    for (const auto& [k, v] : x.items()) keys.insert(k);
    for (const auto& [k, v] : y.items()) keys.insert(k);
    std::string line = pa[i].value("label", std::string()) + ":";
    for (const std::string& k : keys) {
      const json u = x.value(k, json()), v = y.value(k, json());
      if (u != v) line += " " + k + " " + json_text(u) + " -> " + json_text(v);
    }
    out.push_back(line);
  }
  return out;
}

struct Leaf {
  std::vector<std::string> path;
  json before;
  json after;
};

// Every leaf where a and b differ; a key or element missing on one side compares as null.
void diff_leaves(const json& a, const json& b, std::vector<std::string>& path,
                 std::vector<Leaf>& out) {
  if (a == b) return;
  if (a.is_object() && b.is_object()) {
    std::set<std::string> keys;
    for (const auto& [k, v] : a.items()) keys.insert(k);
    for (const auto& [k, v] : b.items()) keys.insert(k);
    for (const std::string& k : keys) {
      path.push_back(k);
      diff_leaves(a.value(k, json()), b.value(k, json()), path, out);
      path.pop_back();
    }
    return;
  }
  if (a.is_array() && b.is_array() && a.size() == b.size()) {
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::size_t length = path.back().size();
      path.back().append(1, '[').append(std::to_string(i)).append(1, ']');
      diff_leaves(a[i], b[i], path, out);
      path.back().resize(length);
    }
    return;
  }
  out.push_back({path, a, b});
}

std::string joined(const std::vector<std::string>& parts, std::size_t from) {
  std::string s;
  for (std::size_t i = from; i < parts.size(); ++i) s += (s.empty() ? "" : ".") + parts[i];
  return s;
}

// A planner entry's leaves: metrics.NAME.FIELD -> (NAME, FIELD), else (first, rest).
void add_entry_differences(const json& a, const json& b, const std::string& planner,
                           const std::string& cell, const std::string& metric_prefix,
                           std::vector<ValueDifference>& out) {
  std::vector<Leaf> leaves;
  std::vector<std::string> path;
  diff_leaves(a, b, path, leaves);
  for (Leaf& leaf : leaves) {
    std::string metric, field;
    if (leaf.path.size() >= 2 && leaf.path[0] == "metrics") {
      metric = leaf.path[1];
      field = joined(leaf.path, 2);
    } else if (!leaf.path.empty()) {
      metric = leaf.path[0];
      field = joined(leaf.path, 1);
    }
    out.push_back({planner, cell, metric_prefix + metric, field, std::move(leaf.before),
                   std::move(leaf.after)});
  }
}

const json* find_by(const json& list, const std::string& key, const std::string& value) {
  for (const json& e : list)
    if (e.value(key, std::string()) == value) return &e;
  return nullptr;
}

void add_list_differences(const json& a, const json& b, const std::string& cell,
                          const std::string& prefix, std::vector<ValueDifference>& out) {
  std::vector<std::string> labels;
  for (const json& e : a) labels.push_back(label_of(e));
  for (const json& e : b)
    if (!find_by(a, "planner", label_of(e))) labels.push_back(label_of(e));
  for (const std::string& label : labels) {
    const json* x = find_by(a, "planner", label);
    const json* y = find_by(b, "planner", label);
    if (x && y) {
      add_entry_differences(*x, *y, label, cell, prefix, out);
    } else {
      out.push_back({label, cell, prefix + "(entry)", "", x ? json("present") : json(),
                     y ? json("present") : json()});
    }
  }
}

std::vector<ValueDifference> value_differences(const json& before, const json& after) {
  std::vector<ValueDifference> out;
  json a = deterministic_part(before), b = deterministic_part(after);
  const json cells_a = a["cells"], cells_b = b["cells"];
  for (json* r : {&a, &b}) {
    r->erase("config");
    r->erase("cells");
  }
  add_entry_differences(a, b, "(sweep)", "", "", out);
  std::vector<std::string> keys;
  for (const json& c : cells_a) keys.push_back(c.value("cell", std::string()));
  for (const json& c : cells_b)
    if (!find_by(cells_a, "cell", c.value("cell", std::string())))
      keys.push_back(c.value("cell", std::string()));
  for (const std::string& key : keys) {
    const json* x = find_by(cells_a, "cell", key);
    const json* y = find_by(cells_b, "cell", key);
    if (!x || !y) {
      out.push_back({"(sweep)", key, "(cell)", "", x ? json("present") : json(),
                     y ? json("present") : json()});
      continue;
    }
    json cx = *x, cy = *y;
    for (json* c : {&cx, &cy}) {
      c->erase("planners");
      c->erase("paired");
    }
    add_entry_differences(cx, cy, "(maps)", key, "", out);
    add_list_differences(x->value("planners", json::array()), y->value("planners", json::array()),
                         key, "", out);
    add_list_differences(x->value("paired", json::array()), y->value("paired", json::array()), key,
                         "paired:", out);
  }
  return out;
}

double median_time(const json& cell, const std::string& planner) {
  const json* entry = find_by(cell.at("planners"), "planner", planner);
  if (!entry) return kNaN;
  const json m = entry->at("timing").at("plan_time_ns").value("median", json());
  return m.is_number() ? m.get<double>() : kNaN;
}

std::vector<double> times_of(const std::map<int, std::int64_t>& runs) {
  std::vector<double> out;
  out.reserve(runs.size());
  // A clock may return 0 ns for a trivial run: 1 ns keeps its logarithm finite.
  for (const auto& [map, ns] : runs)
    out.push_back(static_cast<double>(std::max<std::int64_t>(ns, 1)));
  return out;
}

double mean_log(const std::vector<double>& v) {
  CompensatedSum s;
  for (double x : v) s.add(std::log(x));
  return s.value() / static_cast<double>(v.size());
}

TimingComparison compare_timing(const json& cell_before, const json& cell_after,
                                const std::string& planner, const RunTimes* rb,
                                const RunTimes* ra) {
  TimingComparison t;
  t.planner = planner;
  t.cell = cell_after.value("cell", std::string());
  const auto key = std::make_pair(t.cell, planner);
  const auto ib = rb ? rb->find(key) : RunTimes::const_iterator{};
  const auto ia = ra ? ra->find(key) : RunTimes::const_iterator{};
  if (!rb || !ra || ib == rb->end() || ia == ra->end() || ib->second.empty() ||
      ia->second.empty()) {
    const double mb = median_time(cell_before, planner), ma = median_time(cell_after, planner);
    t.ratio = mb > 0.0 ? ma / mb : kNaN;
    const json* eb = find_by(cell_before.at("planners"), "planner", planner);
    const json* ea = find_by(cell_after.at("planners"), "planner", planner);
    t.runs_before = eb ? eb->value("runs", std::size_t{0}) : 0;
    t.runs_after = ea ? ea->value("runs", std::size_t{0}) : 0;
    return t;
  }
  t.runs_before = ib->second.size();
  t.runs_after = ia->second.size();
  const bool paired =
      std::equal(ib->second.begin(), ib->second.end(), ia->second.begin(), ia->second.end(),
                 [](const auto& x, const auto& y) { return x.first == y.first; });
  const std::vector<double> b = times_of(ib->second), a = times_of(ia->second);
  if (paired) {
    t.pairs = a.size();
    t.test = TimingTest::wilcoxon;
    const PairedComparison c = compare_paired(a, b, Better::smaller, RatioKind::plain, 0.0);
    t.ratio = c.geo_mean_ratio;
    t.ci95 = c.geo_mean_ci95;
    // On log ratios: the test of the same scale-free quantity the geometric mean summarises.
    std::vector<double> logs(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) logs[i] = std::log(a[i]) - std::log(b[i]);
    t.p = wilcoxon_signed_rank(logs).p;
  } else {
    t.test = TimingTest::mann_whitney;
    t.ratio = std::exp(mean_log(a) - mean_log(b));
    t.p = mann_whitney_u(a, b).p;
  }
  return t;
}

const char* test_name(TimingTest t) {
  switch (t) {
    case TimingTest::wilcoxon:
      return "wilcoxon";
    case TimingTest::mann_whitney:
      return "mann_whitney";
    case TimingTest::none:
      break;
  }
  return "none";
}

std::string fixed(double v, int digits) {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string p_text(double p) {
  if (!std::isfinite(p)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, p < 1e-4 ? "%.1e" : "%.4f", p);
  return buf;
}

}  // namespace

std::string report_config_hash(const json& report) { return config_hash_of(report.at("config")); }

void read_run_times(const std::string& journal, const std::string& config_hash, RunTimes& times,
                    std::set<std::string>& sweep_ids) {
  // A torn last line is a run resume would redo: skipped.
  for_each_journal_record(journal, [&](const DecodedRecord& rec, const std::string& where) {
    if (rec.kind == DecodedRecord::Kind::header && !rec.sweep_id.empty())
      sweep_ids.insert(rec.sweep_id);
    if (rec.kind == DecodedRecord::Kind::map) return;
    if (rec.config_hash != config_hash)
      throw InputError(where + ": a record of config " + rec.config_hash +
                       ", not of the report's config (hash " + config_hash + ")");
    if (rec.kind == DecodedRecord::Kind::run)
      times[{rec.cell, rec.planner}][rec.map_index] = rec.run.plan_time_ns;
  });
}

int ReportComparison::exit_code() const {
  if (!differences.empty() || overall_regression) return 1;
  for (const TimingComparison& t : timing)
    if (t.regression) return 1;
  return 0;
}

ReportComparison compare_reports(const json& before, const json& after, const RunTimes* rb,
                                 const RunTimes* ra, std::optional<double> pct) {
  require_report(before, "BEFORE");
  require_report(after, "AFTER");
  check_configs(before.at("config"), after.at("config"));
  ReportComparison c;
  c.fail_on_regression_pct = pct;
  c.parameter_changes = parameter_changes(before.at("config"), after.at("config"));
  c.differences = value_differences(before, after);
  // By planner in config order, then the order the walk found them in.
  const json& planners = after.at("config").at("planners");
  auto rank = [&planners](const std::string& label) {
    if (label == "(sweep)") return std::size_t{0};
    if (label == "(maps)") return std::size_t{1};
    for (std::size_t i = 0; i < planners.size(); ++i)
      if (planners[i].value("label", std::string()) == label) return i + 2;
    return planners.size() + 2;
  };
  std::stable_sort(c.differences.begin(), c.differences.end(),
                   [&rank](const ValueDifference& x, const ValueDifference& y) {
                     return rank(x.planner) < rank(y.planner);
                   });

  const double limit = pct ? 1.0 + *pct / 100.0 : kNaN;
  CompensatedSum log_sum;
  for (const json& p : planners) {
    const std::string label = p.value("label", std::string());
    CompensatedSum planner_logs;
    std::size_t planner_groups = 0;
    for (const json& cell_after : after.at("cells")) {
      const json* cell_before = find_by(before.at("cells"), "cell", cell_after.value("cell", ""));
      if (!cell_before || !find_by(cell_after.at("planners"), "planner", label) ||
          !find_by(cell_before->at("planners"), "planner", label))
        continue;
      TimingComparison t = compare_timing(*cell_before, cell_after, label, rb, ra);
      if (pct && t.ratio > limit && (t.test == TimingTest::none || t.p < kRegressionAlpha))
        t.regression = true;
      if (std::isfinite(t.ratio) && t.ratio > 0.0) {
        log_sum.add(std::log(t.ratio));
        ++c.overall_groups;
        planner_logs.add(std::log(t.ratio));
        ++planner_groups;
      }
      c.timing.push_back(std::move(t));
    }
    c.planner_ratios.emplace_back(
        label, planner_groups > 0
                   ? std::exp(planner_logs.value() / static_cast<double>(planner_groups))
                   : kNaN);
  }
  if (c.overall_groups > 0)
    c.overall_ratio = std::exp(log_sum.value() / static_cast<double>(c.overall_groups));
  c.overall_regression = pct && c.overall_ratio > limit;
  return c;
}

namespace {

// The non-timing differences, one line per (planner, cell, metric) with its fields together.
void differences_text(const ReportComparison& c, std::ostringstream& out) {
  std::size_t groups = 0;
  std::ostringstream list;
  std::string planner;
  for (std::size_t i = 0; i < c.differences.size();) {
    const ValueDifference& d = c.differences[i];
    if (i == 0 || d.planner != planner) {
      planner = d.planner;
      list << "  " << planner << "\n";
    }
    list << "    " << (d.cell.empty() ? "(all cells)" : d.cell) << "  " << d.metric << ":";
    std::size_t j = i;
    for (; j < c.differences.size() && c.differences[j].planner == d.planner &&
           c.differences[j].cell == d.cell && c.differences[j].metric == d.metric;
         ++j) {
      const ValueDifference& f = c.differences[j];
      list << (j == i ? " " : "; ") << (f.field.empty() ? "" : f.field + " ")
           << short_dump(f.before) << " -> " << short_dump(f.after);
    }
    list << "\n";
    ++groups;
    i = j;
  }
  if (c.differences.empty()) {
    out << "non-timing results: identical\n";
  } else {
    out << "non-timing differences: " << c.differences.size() << " values in " << groups
        << " planner/cell/metric groups\n"
        << list.str();
  }
}

}  // namespace

std::string comparison_text(const ReportComparison& c) {
  std::ostringstream out;
  if (!c.parameter_changes.empty()) {
    out << "planner parameters changed:\n";
    for (const auto& line : c.parameter_changes) out << "  " << line << "\n";
  }
  differences_text(c, out);

  out << "\nplanning time, after / before (per planner and cell; wilcoxon: signed-rank test over "
         "the maps, paired by task; mann_whitney: U test; none: ratio of the reports' medians)\n";
  char line[256];
  std::snprintf(line, sizeof line, "  %-24s %-22s %7s %7s %8s %19s %-12s %8s\n", "planner", "cell",
                "runs", "runs", "ratio", "[95% CI]", "test", "p");
  out << line;
  std::snprintf(line, sizeof line, "  %-24s %-22s %7s %7s\n", "", "", "before", "after");
  out << line;
  for (const TimingComparison& t : c.timing) {
    std::string ci;
    if (t.ci95.defined())
      ci.append(1, '[')
          .append(fixed(t.ci95.lo, 3))
          .append(", ")
          .append(fixed(t.ci95.hi, 3))
          .append(1, ']');
    std::snprintf(line, sizeof line, "  %-24s %-22s %7zu %7zu %8s %19s %-12s %8s%s\n",
                  t.planner.c_str(), t.cell.c_str(), t.runs_before, t.runs_after,
                  fixed(t.ratio, 3).c_str(), ci.c_str(), test_name(t.test), p_text(t.p).c_str(),
                  t.regression ? "  REGRESSION" : "");
    out << line;
  }
  out << "per planner (geometric mean over its cells):";
  for (const auto& [label, ratio] : c.planner_ratios)
    out << "  " << label << " " << fixed(ratio, 3);
  out << "\n";
  out << "overall: geometric mean of " << c.overall_groups
      << " planner/cell ratios: " << fixed(c.overall_ratio, 4);
  if (std::isfinite(c.overall_ratio))
    out << " (" << (c.overall_ratio >= 1 ? "+" : "") << fixed(100.0 * (c.overall_ratio - 1), 1)
        << "% planning time)";
  out << (c.overall_regression ? "  REGRESSION" : "") << "\n";
  std::size_t regressions = 0;
  for (const TimingComparison& t : c.timing) regressions += t.regression ? 1 : 0;
  out << "result: " << c.differences.size() << " non-timing differences; ";
  if (c.fail_on_regression_pct) {
    out << regressions << " planner/cell timing regressions beyond "
        << fixed(*c.fail_on_regression_pct, 1) << "% (p < " << kRegressionAlpha << ")"
        << (c.overall_regression ? ", and overall" : "") << "; ";
  } else {
    out << "timing not gated (--fail-on-regression PCT); ";
  }
  out << "exit " << c.exit_code() << "\n";
  return out.str();
}

json comparison_json(const ReportComparison& c) {
  json differences = json::array();
  for (const ValueDifference& d : c.differences)
    differences.push_back({{"planner", d.planner},
                           {"cell", d.cell},
                           {"metric", d.metric},
                           {"field", d.field},
                           {"before", d.before},
                           {"after", d.after}});
  json planners = json::array();
  for (const auto& [label, ratio] : c.planner_ratios)
    planners.push_back({{"planner", label}, {"plan_time_ratio", number_or_null(ratio)}});
  json timing = json::array();
  for (const TimingComparison& t : c.timing)
    timing.push_back({{"planner", t.planner},
                      {"cell", t.cell},
                      {"runs_before", t.runs_before},
                      {"runs_after", t.runs_after},
                      {"pairs", t.pairs},
                      {"plan_time_ratio", number_or_null(t.ratio)},
                      {"ci95", {number_or_null(t.ci95.lo), number_or_null(t.ci95.hi)}},
                      {"test", test_name(t.test)},
                      {"p", number_or_null(t.p)},
                      {"regression", t.regression}});
  return {{"parameter_changes", c.parameter_changes},
          {"differences", differences},
          {"timing", timing},
          {"planners", planners},
          {"overall",
           {{"plan_time_ratio", number_or_null(c.overall_ratio)},
            {"groups", c.overall_groups},
            {"regression", c.overall_regression}}},
          {"fail_on_regression_pct",
           c.fail_on_regression_pct ? json(*c.fail_on_regression_pct) : json(nullptr)},
          {"exit_code", c.exit_code()}};
}

}  // namespace agv
