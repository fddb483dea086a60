#include "engine/outputs/run_record.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

#include "core/input_error.h"
#include "core/json_text.h"
#include "core/version.h"
#include "engine/judge/metric_specs.h"

namespace agv {

using nlohmann::json;

namespace {

constexpr double kUndefined = std::numeric_limits<double>::quiet_NaN();

constexpr std::size_t kPathLengthM = 1;
constexpr std::size_t kSmoothnessMean = 6;
constexpr std::size_t kMinClearanceM = 9;
static_assert(kRunMetricNames[0] == "path_length" &&
              kRunMetricNames[kPathLengthM] == "path_length_m" &&
              kRunMetricNames[2] == "waypoints" && kRunMetricNames[4] == "turn_angle_rad" &&
              kRunMetricNames[kSmoothnessMean] == "smoothness_mean" &&
              kRunMetricNames[8] == "min_clearance" &&
              kRunMetricNames[kMinClearanceM] == "min_clearance_m");
// The metrics a reader rebuilds (rebuild_derived_metrics): each one operation on others, so no
// compiler's contraction of a multiply-add can make the rebuilt value differ from the engine's.
// motion_time_s (paper 000 eq. 5.2e, a sum of products) is not among them: a build that fuses
// its multiply-add and one that does not give values an ulp apart, so it is always written.
// jq reads every number as a double: a mask of at most 53 bits stays exact there. A declared
// metric beyond them travels by name under "extra".
constexpr int kMaskBits = 53;
static_assert(kRunMetricNames.size() <= kMaskBits);

constexpr bool is_derived(std::size_t i) {
  return i == kPathLengthM || i == kSmoothnessMean || i == kMinClearanceM ||
         i == kOptimalityMetric || i == kAnyAngleMetric || i == kScenMetric;
}

// Shortest round-trip form: "2984" for 2984.0, "0.1", "1e+20"; -0 as "-0.0" (a JSON "-0" reads
// back as the integer 0).
void append_double(std::string& out, double v) {
  if (v == 0.0 && std::signbit(v)) {
    out += "-0.0";
    return;
  }
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void append_int(std::string& out, std::int64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void append_string(std::string& out, const std::string& s) { out += json_text(json(s)); }

bool same_bits(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  std::uint64_t x = 0;
  std::uint64_t y = 0;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}

// engine/judge/run_executor.cpp set_ratio: length / reference, 1 for a zero reference, NaN without.
double ratio(double length, const std::optional<double>& reference) {
  if (!std::isfinite(length) || !reference) return kUndefined;
  if (*reference > 0.0) return length / *reference;
  if (*reference == 0.0) return 1.0;
  return kUndefined;
}

int metric_index(const std::string& name) {
  const auto& names = journal_metric_names();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int>(i);
  return -1;
}

// A finite double, or NaN for null (version 1's undefined metric).
double number_or_nan(const json& v) { return v.is_number() ? v.get<double>() : kUndefined; }

const json& member(const json& object, const char* key) {
  if (!object.is_object()) throw json::other_error::create(501, "expected an object", &object);
  return object.at(key);
}

}  // namespace

MapFacts map_facts_of(const MapSlot& slot, const MapReference& ref) {
  MapFacts f;
  f.slot = slot;
  f.optimal_length = ref.known_optimal_length(ref.model().corner_rule);
  f.any_angle_length = ref.known_any_angle_length();
  f.scen_optimum = ref.scenario_optimum();
  return f;
}

const std::vector<std::string>& journal_metric_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out(kRunMetricNames.begin(), kRunMetricNames.end());
    for (const MetricSpec& s : kMetricSpecs)
      if (std::find(out.begin(), out.end(), s.name) == out.end()) out.emplace_back(s.name);
    return out;
  }();
  return names;
}

RunSlot run_slot_of(const RunOutput& run) {
  RunSlot slot;
  slot.outcome = run.outcome;
  slot.metrics = run.metrics;
  slot.plan_time_ns = run.plan_time_ns;
  slot.phases = run.result.phases;
  slot.extra = run.result.extra;
  return slot;
}

void rebuild_derived_metrics(RunMetrics& m, std::bitset<kRunMetricNames.size()> explicit_metrics,
                             const MapFacts& facts, double cell_edge) {
  const double length = m[0];
  const double turn = m[4];
  if (!explicit_metrics[kPathLengthM])
    m[kPathLengthM] = std::isfinite(length) ? length * cell_edge : kUndefined;
  // engine/judge/metrics.cpp: defined for a path of positive length.
  if (!explicit_metrics[kSmoothnessMean])
    m[kSmoothnessMean] =
        std::isfinite(turn) && std::isfinite(length) && length > 0.0 ? turn / length : kUndefined;
  if (!explicit_metrics[kMinClearanceM])
    m[kMinClearanceM] = std::isfinite(m[8]) ? m[8] * cell_edge : kUndefined;
  if (!explicit_metrics[kOptimalityMetric])
    m[kOptimalityMetric] = ratio(length, facts.optimal_length);
  if (!explicit_metrics[kAnyAngleMetric])
    m[kAnyAngleMetric] = ratio(length, facts.any_angle_length);
  if (!explicit_metrics[kScenMetric]) m[kScenMetric] = ratio(length, facts.scen_optimum);
}

std::string journal_header(const std::string& config_hash, const SweepConfig& config,
                           const SweepPlan& plan, const std::string& sweep_id) {
  // In this order (not sorted): what the file is first.
  using ordered = nlohmann::ordered_json;
  ordered cells = ordered::array();
  for (const SweepCell& c : plan.cells) {
    ordered cell = {
        {"cell", c.key},        {"generator", c.generator}, {"size", {c.size.width, c.size.height}},
        {"density", c.density}, {"maps", c.maps},           {"cell_edge", c.spec.cell_edge}};
    if (c.file != nullptr)
      cell["map_file"] = {{"name", c.file->name}, {"content_hash", c.file->content_hash}};
    cells.push_back(std::move(cell));
  }
  ordered planners = ordered::array();
  for (const PlannerEntry& p : config.planners)
    planners.push_back({{"label", p.label}, {"name", p.name}});
  // Named again here (they are in the config hash already) so that a resume after a plugin
  // changed can say which one did.
  ordered plugins = ordered::array();
  for (const PluginRecord& p : config.plugins)
    plugins.push_back({{"name", p.name}, {"path", p.path}, {"sha256", p.sha256}});
  const ordered derived = {
      {"path_length_m", "path_length * cell_edge"},
      {"smoothness_mean", "turn_angle_rad / path_length (where path_length > 0)"},
      {"min_clearance_m", "min_clearance * cell_edge"},
      {"optimality_ratio", "path_length / optimal_length (1 where that is 0)"},
      {"any_angle_ratio", "path_length / any_angle_length (1 where that is 0)"},
      {"scen_ratio", "path_length / scen_optimum (1 where that is 0)"}};
  const ordered header = {{"tool", kJournalTool},
                          {"journal_version", kJournalVersion},
                          {"agvbench", AGVBENCH_VERSION},
                          {"record", "header"},
                          {"config_hash", config_hash},
                          {"sweep_id", sweep_id},
                          {"name", config.name},
                          {"seed", config.seed},
                          {"cells", cells},
                          {"planners", planners},
                          {"plugins", plugins},
                          {"metrics", journal_metric_names()},
                          {"derived", derived},
                          {"units", {{"plan_time_ns", "ns"}, {"phases", "ns"}}}};
  return header.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + '\n';
}

std::string map_record(const SweepCell& cell, int map_index, const MapFacts& facts) {
  std::string out = "{\"record\":\"map\",\"cell\":";
  append_int(out, cell.index);
  out += ",\"map_index\":";
  append_int(out, map_index);
  if (facts.slot.done) {
    out += ",\"obstacle_fraction\":";
    append_double(out, facts.slot.obstacle_fraction);
    out += ",\"rejections\":";
    append_int(out, facts.slot.rejections);
  }
  const auto reference = [&out](const char* key, const std::optional<double>& v) {
    if (!v || !std::isfinite(*v)) return;
    out += ",\"";
    out += key;
    out += "\":";
    append_double(out, *v);
  };
  reference("optimal_length", facts.optimal_length);
  reference("any_angle_length", facts.any_angle_length);
  reference("scen_optimum", facts.scen_optimum);
  out += "}\n";
  return out;
}

namespace {

// A run's metrics as a version 2 record carries them.
struct EncodedMetrics {
  std::uint64_t mask = 0;
  std::string values;  // comma-separated, in mask order
  std::string extra;   // what the mask cannot say: undeclared names, undefined values
};

EncodedMetrics encode_metrics(const RunSlot& slot, const MapFacts& facts, double cell_edge) {
  // Which derived metrics the reader would not rebuild bit for bit: those are written.
  RunMetrics rebuilt = slot.metrics;
  rebuild_derived_metrics(rebuilt, {}, facts, cell_edge);
  EncodedMetrics e;
  std::uint64_t& mask = e.mask;
  std::string& values = e.values;
  std::string& extra = e.extra;
  const auto add_extra = [&extra](const std::string& name, double v) {
    extra += extra.empty() ? "{" : ",";
    append_string(extra, name);
    extra += ':';
    if (std::isfinite(v)) {
      append_double(extra, v);
    } else {
      extra += "null";
    }
  };
  const auto add_value = [&](int bit, double v) {
    mask |= std::uint64_t{1} << bit;
    if (!values.empty()) values += ',';
    append_double(values, v);
  };
  // Bits of the declared extras are taken as they are met, so a name given twice keeps one bit.
  // Values in mask order: the run metrics first, then the declared extras by their index.
  std::vector<std::pair<int, double>> declared;
  for (std::size_t i = 0; i < kRunMetricNames.size(); ++i) {
    const double v = slot.metrics[i];
    if (is_derived(i) && same_bits(v, rebuilt[i])) continue;
    if (std::isfinite(v)) {
      declared.emplace_back(static_cast<int>(i), v);
    } else if (!std::isnan(v) || (is_derived(i) && !std::isnan(rebuilt[i]))) {
      add_extra(std::string(kRunMetricNames[i]), v);  // an undefined value the reader would fill
    }
  }
  for (const auto& [name, v] : slot.extra) {
    const int i = metric_index(name);
    if (i >= static_cast<int>(kRunMetricNames.size()) && i < kMaskBits && std::isfinite(v) &&
        (mask >> i & 1) == 0) {
      mask |= std::uint64_t{1} << i;
      declared.emplace_back(i, v);
    } else {
      add_extra(name, v);
    }
  }
  std::stable_sort(declared.begin(), declared.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [i, v] : declared) add_value(i, v);
  return e;
}

}  // namespace

std::string run_record(const SweepCell& cell, int map_index, std::size_t planner,
                       const RunSlot& slot, const std::string& message, const MapFacts& facts) {
  const EncodedMetrics e = encode_metrics(slot, facts, cell.spec.cell_edge);
  std::string out = "{\"cell\":";
  append_int(out, cell.index);
  out += ",\"map_index\":";
  append_int(out, map_index);
  out += ",\"planner\":";
  append_int(out, static_cast<std::int64_t>(planner));
  out += ",\"outcome\":\"";
  out += to_string(slot.outcome);
  out += '"';
  if (e.mask != 0) {
    out += ",\"mask\":";
    append_int(out, static_cast<std::int64_t>(e.mask));
    out += ",\"metrics\":[";
    out += e.values;
    out += ']';
  }
  if (!e.extra.empty()) {
    out += ",\"extra\":";
    out += e.extra;
    out += '}';
  }
  out += ",\"plan_time_ns\":";
  append_int(out, slot.plan_time_ns);
  out += ",\"phases\":{";
  for (std::size_t i = 0; i < slot.phases.size(); ++i) {
    if (i > 0) out += ',';
    append_string(out, slot.phases[i].name);
    out += ':';
    append_int(out, slot.phases[i].ns);
  }
  out += '}';
  if (!message.empty()) {
    out += ",\"message\":";
    append_string(out, message);
  }
  out += "}\n";
  return out;
}

// --- reading ---------------------------------------------------------------------------------

DecodedRecord JournalDecoder::decode_line(std::string_view line, const std::string& where) {
  const json rec = json::parse(line, nullptr, false);
  if (rec.is_discarded()) throw InputError(where + ": malformed journal record");
  return decode(rec, where);
}

DecodedRecord JournalDecoder::decode(const json& rec, const std::string& where) {
  try {
    if (!rec.is_object()) throw InputError(where + ": malformed journal record");
    const auto tool = rec.find("tool");
    const auto version = rec.find("journal_version");
    const json t = tool == rec.end() ? json() : *tool;
    const json v = version == rec.end() ? json() : *version;
    // A version 2 header, a version 1 record, or a version 2 map or run record after a header.
    if (t == kJournalTool && v == kJournalVersion) {
      if (rec.value("record", json()) != "header")
        throw InputError(where + ": a record naming journal_version " +
                         std::to_string(kJournalVersion) + " must be its header");
      return decode_header(rec, where);
    }
    if (t == kJournalTool && v == kJournalVersionV1) return decode_v1(rec, where);
    if (tool != rec.end() || version != rec.end() || !header_)
      throw InputError(
          where + ": not a record of this agvbench's journal format (it says tool " +
          (t.is_null() ? std::string("(none)") : json_text(t)) + ", journal_version " +
          (v.is_null() ? std::string("(none)") : json_text(v)) +
          (header_ || tool != rec.end() || version != rec.end() ? ""
                                                                : ", and no header precedes it") +
          "; this agvbench reads tool \"" + kJournalTool + "\", journal_version " +
          std::to_string(kJournalVersion) + " (and " + std::to_string(kJournalVersionV1) + "))");
    const auto kind = rec.find("record");
    if (kind == rec.end()) return decode_run(rec, where);
    if (*kind == "map") return decode_map(rec, where);
    throw InputError(where + ": unknown record kind " + json_text(*kind));
  } catch (const json::exception& e) {
    throw InputError(where + ": malformed journal record (" + e.what() + ")");
  }
}

DecodedRecord JournalDecoder::decode_header(const json& rec, const std::string& where) {
  JournalHeader h;
  h.config_hash = rec.at("config_hash").get<std::string>();
  if (const auto stamp = rec.find("agvbench"); stamp != rec.end())
    h.agvbench = stamp->get<std::string>();
  if (const auto id = rec.find("sweep_id"); id != rec.end()) h.sweep_id = id->get<std::string>();
  for (const json& p : rec.value("plugins", json::array()))
    h.plugins.push_back({member(p, "name").get<std::string>(), member(p, "path").get<std::string>(),
                         member(p, "sha256").get<std::string>()});
  for (const json& c : rec.at("cells")) {
    JournalHeader::Cell cell;
    cell.key = member(c, "cell").get<std::string>();
    cell.cell_edge = member(c, "cell_edge").get<double>();
    if (c.contains("map_file")) {
      cell.map_file = member(c.at("map_file"), "name").get<std::string>();
      cell.content_hash = member(c.at("map_file"), "content_hash").get<std::string>();
    }
    h.cells.push_back(std::move(cell));
  }
  for (const json& p : rec.at("planners"))
    h.planners.push_back(member(p, "label").get<std::string>());
  h.metrics = rec.at("metrics").get<std::vector<std::string>>();
  if (h.metrics.size() > 63) throw InputError(where + ": more metrics than a mask holds");
  // The engine's run metrics lead the order: the derived ones are rebuilt by their index.
  for (std::size_t i = 0; i < kRunMetricNames.size(); ++i)
    if (i >= h.metrics.size() || h.metrics[i] != kRunMetricNames[i])
      throw InputError(where + ": header's metric order does not start with this agvbench's " +
                       std::to_string(kRunMetricNames.size()) + " run metrics (" +
                       std::string(kRunMetricNames[i]) +
                       " missing): written by an agvbench that measures other metrics; start a "
                       "new journal");
  header_ = std::move(h);
  maps_.clear();
  DecodedRecord out;
  out.kind = DecodedRecord::Kind::header;
  out.config_hash = header_->config_hash;
  out.agvbench = header_->agvbench;
  out.sweep_id = header_->sweep_id;
  return out;
}

namespace {

int table_index(const json& rec, const char* key, std::size_t size, const std::string& where) {
  const json& v = rec.at(key);
  if (!v.is_number_integer() || v.get<std::int64_t>() < 0 ||
      v.get<std::int64_t>() >= static_cast<std::int64_t>(size))
    throw InputError(where + ": \"" + key + "\" " + json_text(v) +
                     " is not an index of the header's table of " + std::to_string(size));
  return v.get<int>();
}

}  // namespace

DecodedRecord JournalDecoder::decode_map(const json& rec, const std::string& where) {
  DecodedRecord out;
  out.kind = DecodedRecord::Kind::map;
  out.config_hash = header_->config_hash;
  out.agvbench = header_->agvbench;
  const int cell = table_index(rec, "cell", header_->cells.size(), where);
  out.cell = header_->cells[static_cast<std::size_t>(cell)].key;
  out.map_index = rec.at("map_index").get<int>();
  MapFacts& f = out.map;
  if (rec.contains("rejections")) {
    f.slot.rejections = rec.at("rejections").get<int>();
    f.slot.obstacle_fraction = rec.at("obstacle_fraction").get<double>();
    f.slot.done = true;
  }
  const auto reference = [&rec](const char* key, std::optional<double>& v) {
    if (rec.contains(key)) v = rec.at(key).get<double>();
  };
  reference("optimal_length", f.optimal_length);
  reference("any_angle_length", f.any_angle_length);
  reference("scen_optimum", f.scen_optimum);
  // A map met again (a task resumed part way) keeps what it said: a different value is damage.
  auto [it, fresh] = maps_.try_emplace({cell, out.map_index}, f);
  if (!fresh) {
    MapFacts& known = it->second;
    const auto merge = [&where](std::optional<double>& have, const std::optional<double>& now,
                                const char* key) {
      if (!now) return;
      if (have && !same_bits(*have, *now))
        throw InputError(where + ": map record's " + key +
                         " differs from an earlier record of the same map");
      have = now;
    };
    if (f.slot.done) {
      if (known.slot.done && (known.slot.rejections != f.slot.rejections ||
                              !same_bits(known.slot.obstacle_fraction, f.slot.obstacle_fraction)))
        throw InputError(where + ": map record differs from an earlier record of the same map");
      known.slot = f.slot;
    }
    merge(known.optimal_length, f.optimal_length, "optimal_length");
    merge(known.any_angle_length, f.any_angle_length, "any_angle_length");
    merge(known.scen_optimum, f.scen_optimum, "scen_optimum");
    out.map = known;
  }
  return out;
}

DecodedRecord JournalDecoder::decode_run(const json& rec, const std::string& where) {
  DecodedRecord out;
  out.kind = DecodedRecord::Kind::run;
  out.config_hash = header_->config_hash;
  out.agvbench = header_->agvbench;
  const int cell = table_index(rec, "cell", header_->cells.size(), where);
  const JournalHeader::Cell& hc = header_->cells[static_cast<std::size_t>(cell)];
  out.cell = hc.key;
  out.map_index = rec.at("map_index").get<int>();
  out.planner = header_->planners[static_cast<std::size_t>(
      table_index(rec, "planner", header_->planners.size(), where))];
  const auto outcome = outcome_from_string(rec.at("outcome").get<std::string>());
  if (!outcome) throw InputError(where + ": unknown outcome");
  RunSlot& slot = out.run;
  slot.outcome = *outcome;
  slot.metrics.fill(kUndefined);
  std::bitset<kRunMetricNames.size()> explicit_metrics;
  if (rec.contains("mask")) {
    const std::uint64_t mask = rec.at("mask").get<std::uint64_t>();
    const json& values = rec.at("metrics");
    if (!values.is_array()) throw InputError(where + ": \"metrics\" is not an array");
    std::size_t next = 0;
    for (std::size_t bit = 0; bit < 64; ++bit) {
      if ((mask >> bit & 1) == 0) continue;
      if (bit >= header_->metrics.size())
        throw InputError(where + ": mask bit " + std::to_string(bit) +
                         " names no metric of the header");
      if (next >= values.size())
        throw InputError(where + ": \"metrics\" holds fewer values than its mask names");
      const json& v = values[next++];
      if (!v.is_number()) throw InputError(where + ": a metric value that is not a number");
      const double value = v.get<double>();
      if (bit < kRunMetricNames.size()) {
        slot.metrics[bit] = value;
        explicit_metrics[bit] = true;
      } else {
        slot.extra.emplace_back(header_->metrics[bit], value);
      }
    }
    if (next != values.size())
      throw InputError(where + ": \"metrics\" holds more values than its mask names");
  }
  if (rec.contains("extra")) {
    for (const auto& [name, value] : rec.at("extra").items()) {
      bool run_metric = false;
      for (std::size_t i = 0; i < kRunMetricNames.size(); ++i) {
        if (kRunMetricNames[i] == name) {
          slot.metrics[i] = number_or_nan(value);
          explicit_metrics[i] = true;
          run_metric = true;
        }
      }
      if (!run_metric) slot.extra.emplace_back(name, number_or_nan(value));
    }
  }
  const auto map = maps_.find({cell, out.map_index});
  if (map != maps_.end()) out.map = map->second;
  rebuild_derived_metrics(slot.metrics, explicit_metrics, out.map, hc.cell_edge);
  slot.plan_time_ns = rec.at("plan_time_ns").get<std::int64_t>();
  for (const auto& [name, ns] : rec.at("phases").items())
    slot.phases.push_back({name, ns.get<std::int64_t>()});
  if (rec.contains("message")) out.message = rec.at("message").get<std::string>();
  return out;
}

DecodedRecord JournalDecoder::decode_v1(const json& rec, const std::string& where) {
  DecodedRecord out;
  out.kind = DecodedRecord::Kind::run;
  out.version = kJournalVersionV1;
  out.config_hash = rec.at("config_hash").get<std::string>();
  out.cell = rec.at("cell").get<std::string>();
  out.planner = rec.at("planner").get<std::string>();
  out.map_index = rec.at("map_index").get<int>();
  if (rec.contains("map_file") && rec.at("map_file").is_object()) {
    out.has_map_file = true;
    out.map_file_hash = rec.at("map_file").value("content_hash", std::string());
  }
  const auto outcome = outcome_from_string(rec.at("outcome").get<std::string>());
  if (!outcome) throw InputError(where + ": unknown outcome");
  RunSlot& slot = out.run;
  slot.outcome = *outcome;
  slot.metrics.fill(kUndefined);
  // A version 1 record holds every one of the engine's metrics, null where undefined: a record
  // without one was written by an agvbench that measures others (the journal format alone does
  // not say), and mixing its values in would report two definitions under one name.
  const json& metrics = rec.at("metrics");
  for (const auto name : kRunMetricNames)
    if (!metrics.contains(name))
      throw InputError(where + ": no metric \"" + std::string(name) +
                       "\": written by an agvbench that measures other metrics than this one "
                       "(which writes each of its " +
                       std::to_string(kRunMetricNames.size()) +
                       " on every record, null when undefined); start a new journal");
  for (const auto& [name, value] : metrics.items()) {
    bool known = false;
    for (std::size_t i = 0; i < kRunMetricNames.size(); ++i) {
      if (kRunMetricNames[i] == name) {
        slot.metrics[i] = number_or_nan(value);
        known = true;
      }
    }
    if (!known) slot.extra.emplace_back(name, number_or_nan(value));
  }
  const json& timing = rec.at("timing");
  slot.plan_time_ns = timing.at("plan_time_ns").get<std::int64_t>();
  for (const auto& [name, ns] : timing.at("phases").items())
    slot.phases.push_back({name, ns.get<std::int64_t>()});
  const json& map = rec.at("map");
  if (map.contains("rejections")) {
    out.map.slot.rejections = map.at("rejections").get<int>();
    out.map.slot.obstacle_fraction = map.at("obstacle_fraction").get<double>();
    out.map.slot.done = true;
  }
  if (rec.contains("message")) out.message = rec.at("message").get<std::string>();
  return out;
}

}  // namespace agv
