#include "engine/outputs/journal_table.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

#include "engine/outputs/journal.h"

namespace agv {

namespace {

// Numbers names in the order they are first given.
class Numbering {
 public:
  int of(const std::string& name) {
    const auto [it, added] = index_.emplace(name, static_cast<int>(index_.size()));
    if (added) names_.push_back(name);
    return it->second;
  }
  const std::vector<std::string>& names() const { return names_; }

 private:
  std::map<std::string, int> index_;
  std::vector<std::string> names_;
};

template <class T>
void permute(std::vector<T>& v, const std::vector<std::size_t>& order) {
  std::vector<T> out;
  out.reserve(order.size());
  for (const std::size_t i : order) out.push_back(v[i]);
  v = std::move(out);
}

// The rows sorted by (cell, map index, planner).
void sort_rows(RunColumns& c) {
  std::vector<std::size_t> order(c.rows());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&c](std::size_t a, std::size_t b) {
    return std::tie(c.cell[a], c.map_index[a], c.planner[a]) <
           std::tie(c.cell[b], c.map_index[b], c.planner[b]);
  });
  permute(c.cell, order);
  permute(c.map_index, order);
  permute(c.planner, order);
  permute(c.outcome, order);
  permute(c.plan_time_ns, order);
  for (auto& column : c.metrics) permute(column, order);
}

}  // namespace

JournalTable read_journal_table(const std::string& path) {
  JournalTable table;
  JournalRecordReader reader(path);
  Numbering cells, planners;
  std::map<std::string, JournalHeader::Cell> cell_facts;
  std::set<std::tuple<int, int, int>> seen;
  RunRows rows;
  DecodedRecord record;
  std::string where;
  while (reader.next(record, where)) {
    if (record.kind == DecodedRecord::Kind::header) {
      for (const auto& c : reader.header()->cells) {
        cells.of(c.key);
        cell_facts.emplace(c.key, c);
      }
      for (const auto& p : reader.header()->planners) planners.of(p);
    }
    if (record.kind != DecodedRecord::Kind::run) continue;
    const int cell = cells.of(record.cell);
    const int planner = planners.of(record.planner);
    if (!seen.emplace(cell, record.map_index, planner).second) {
      ++table.duplicates;
      continue;
    }
    rows.add(cell, record.map_index, planner, record.run);
  }
  table.torn_lines = reader.stats().torn_lines;
  table.runs = rows.take();
  sort_rows(table.runs);
  for (const std::string& key : cells.names()) {
    const auto it = cell_facts.find(key);
    JournalHeader::Cell c;
    c.key = key;
    table.cells.push_back(it != cell_facts.end() ? it->second : c);
  }
  table.planners = planners.names();
  return table;
}

}  // namespace agv
