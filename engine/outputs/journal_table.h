#pragma once
// A journal's runs as columns (engine/outputs/run_table.h), for the Python module's read_runs:
// every version the engine reads, plain or gzip, a torn tail left out, each run once (a later
// record of a run already read is a duplicate and skipped, as a resume does). Cells and planners
// are numbered in the order the journal's headers list them (version 1 records: as first seen),
// and rows come in (cell, map index, planner) order, so a sweep's journal gives the table its
// DataFrame has, whatever order the runs finished in.

#include <cstdint>
#include <string>
#include <vector>

#include "engine/outputs/run_record.h"
#include "engine/outputs/run_table.h"

namespace agv {

struct JournalTable {
  RunColumns runs;
  std::vector<JournalHeader::Cell> cells;  // by the columns' cell index
  std::vector<std::string> planners;       // labels, by the columns' planner index
  std::int64_t duplicates = 0;
  std::int64_t torn_lines = 0;
};

// Throws InputError naming the journal (and line) for what a resume refuses.
JournalTable read_journal_table(const std::string& path);

}  // namespace agv
