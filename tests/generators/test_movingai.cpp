// MovingAI .map / .scen reading and writing: the benchmark sets where present, round trips, and a
// table of malformed inputs whose messages must name the line.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "core/rng.h"
#include "generators/movingai.h"
#include "tests/movingai_data.h"

namespace agv {
namespace {

struct SharedMap {
  const char* name;
  int width;
  int height;
  std::size_t scenarios;
};
// The five maps of the full sets we test on.
constexpr SharedMap kSharedMaps[] = {
    {"arena2.map", 281, 209, 910},        {"random512-10-0.map", 512, 512, 1780},
    {"maze512-1-0.map", 512, 512, 12120}, {"8room_000.map", 512, 512, 2140},
    {"Berlin_0_512.map", 512, 512, 1870},
};

// Obstacle count straight from the file's characters, without the reader.
std::int64_t count_obstacle_chars(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int i = 0; i < 4; ++i) std::getline(in, line);
  std::int64_t n = 0;
  while (std::getline(in, line)) {
    for (char c : line) n += (c == '@' || c == 'O' || c == 'T' || c == 'S' || c == 'W') ? 1 : 0;
  }
  return n;
}

Grid parse_map_text(const std::string& text) {
  std::istringstream in(text);
  return parse_map(in, "test.map");
}

std::vector<ScenarioQuery> parse_scen_text(const std::string& text) {
  std::istringstream in(text);
  return parse_scen(in, "test.scen");
}

void expect_reads(const std::string& dir, const SharedMap& m) {
  const std::string path = dir + "/" + m.name;
  const Grid g = read_map(path);
  EXPECT_EQ(g.width(), m.width) << m.name;
  EXPECT_EQ(g.height(), m.height) << m.name;
  EXPECT_EQ(g.obstacle_count(), count_obstacle_chars(path)) << m.name;
  EXPECT_GT(g.free_count(), 0);

  const std::string scen_path = path + ".scen";
  const std::vector<ScenarioQuery> queries = read_scen(scen_path);
  EXPECT_EQ(queries.size(), m.scenarios) << m.name;
  for (const ScenarioQuery& q : queries) {
    EXPECT_EQ(q.map, m.name);
    ASSERT_NO_THROW(check_scenario_fits(g, q, scen_path)) << m.name << " line " << q.line;
  }
}

TEST(MovingAi, FullSetsReadWithTheirScenarios) {
  AGV_MOVINGAI_SETS_OR_SKIP(sets);
  for (const SharedMap& m : kSharedMaps) expect_reads(sets, m);
}

TEST(MovingAi, FullSetsScenarioFieldsAndLineNumbers) {
  AGV_MOVINGAI_SETS_OR_SKIP(sets);
  const std::vector<ScenarioQuery> q = read_scen(sets + "/random512-10-0.map.scen");
  ASSERT_FALSE(q.empty());
  EXPECT_EQ(q[0].bucket, 0);
  EXPECT_EQ(q[0].map_width, 512);
  EXPECT_EQ(q[0].map_height, 512);
  EXPECT_EQ(q[0].start, (Cell{174, 10}));
  EXPECT_EQ(q[0].goal, (Cell{172, 9}));
  EXPECT_DOUBLE_EQ(q[0].optimal_length, 2.41421356);
  EXPECT_EQ(q[0].line, 2);
  EXPECT_EQ(q[1].line, 3);
}

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string to_crlf(const std::string& lf) {
  std::string crlf;
  for (char c : lf) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  return crlf;
}

Grid random_grid(int width, int height, double density, Rng& rng) {
  Grid g(width, height);
  for (int y = 0; y < g.height(); ++y)
    for (int x = 0; x < g.width(); ++x) g.set_blocked(x, y, rng.chance(density));
  return g;
}

// A scenario file for `g` named `map` in MovingAI's layout: random endpoints, each length the
// straight line's times 1.25 with 8 decimals (the reader checks no more than that bound).
std::string random_scen_text(const Grid& g, const std::string& map, int queries, Rng& rng) {
  std::string text = "version 1\n";
  for (int i = 0; i < queries; ++i) {
    const Cell s{rng.between(0, g.width() - 1), rng.between(0, g.height() - 1)};
    const Cell t{rng.between(0, g.width() - 1), rng.between(0, g.height() - 1)};
    char line[160];
    std::snprintf(line, sizeof line, "%d\t%s\t%d\t%d\t%d\t%d\t%d\t%d\t%.8f\n", i / 4, map.c_str(),
                  g.width(), g.height(), s.x, s.y, t.x, t.y,
                  1.25 * std::hypot(s.x - t.x, s.y - t.y));
    text += line;
  }
  return text;
}

// Windows line endings: a map and its scenarios read as from LF.
TEST(MovingAi, CrlfParsesLikeLf) {
  Rng rng(10, 10);
  const Grid g = random_grid(53, 41, 0.25, rng);
  std::ostringstream map;
  write_map(g, map);
  const std::string lf = map.str();
  ASSERT_EQ(lf.find('\r'), std::string::npos);
  EXPECT_TRUE(parse_map_text(to_crlf(lf)).same_cells(g));
  const std::string scen = random_scen_text(g, "crlf.map", 40, rng);
  const auto from_crlf = parse_scen_text(to_crlf(scen));
  const auto from_lf = parse_scen_text(scen);
  ASSERT_EQ(from_lf.size(), 40u);
  ASSERT_EQ(from_crlf.size(), from_lf.size());
  for (std::size_t i = 0; i < from_lf.size(); ++i) {
    EXPECT_EQ(from_crlf[i].map, from_lf[i].map);
    EXPECT_EQ(from_crlf[i].start, from_lf[i].start);
    EXPECT_EQ(from_crlf[i].goal, from_lf[i].goal);
    EXPECT_EQ(from_crlf[i].line, from_lf[i].line);
    EXPECT_DOUBLE_EQ(from_crlf[i].optimal_length, from_lf[i].optimal_length);
  }
}

// The one published map that really has CRLF endings.
TEST(MovingAi, FullSetsBerlinHasCrlfAndParsesLikeLf) {
  AGV_MOVINGAI_SETS_OR_SKIP(sets);
  const std::string path = sets + "/Berlin_0_512.map";
  const std::string text = file_text(path);
  ASSERT_NE(text.find("\r\n"), std::string::npos);
  std::string lf;
  for (char c : text) {
    if (c != '\r') lf += c;
  }
  EXPECT_TRUE(parse_map_text(lf).same_cells(read_map(path)));
}

TEST(MovingAi, WriteThenReadIsIdentical) {
  Rng rng(8, 8);
  for (int trial = 0; trial < 20; ++trial) {
    const Grid g = random_grid(rng.between(1, 70), rng.between(1, 70), 0.3, rng);
    std::ostringstream out;
    write_map(g, out);
    EXPECT_TRUE(parse_map_text(out.str()).same_cells(g));
  }
  // Through a file, at a benchmark map's size.
  const Grid big = random_grid(512, 512, 0.1, rng);
  const std::string tmp = testing::TempDir() + "/agv_roundtrip.map";
  write_map_file(big, tmp);
  EXPECT_TRUE(read_map(tmp).same_cells(big));
  std::filesystem::remove(tmp);
}

// Editors on some systems start a text file with a UTF-8 byte-order mark: it is skipped, on the
// map's first line and on the scenario's, so the file reads like the one without it.
TEST(MovingAi, AByteOrderMarkIsSkipped) {
  Rng rng(9, 9);
  Grid g(7, 5);
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) g.set_blocked(x, y, rng.chance(0.3));
  }
  std::ostringstream text;
  write_map(g, text);
  const std::string map = testing::TempDir() + "/agv_bom.map";
  std::ofstream(map, std::ios::binary) << "\xEF\xBB\xBF" << text.str();
  EXPECT_TRUE(read_map(map).same_cells(g));
  const std::string scen = testing::TempDir() + "/agv_bom.scen";
  std::ofstream(scen, std::ios::binary)
      << "\xEF\xBB\xBFversion 1\n0\tagv_bom.map\t7\t5\t0\t0\t1\t1\t1.41421356\n";
  ASSERT_EQ(read_scen(scen).size(), 1u);
  std::filesystem::remove(map);
  std::filesystem::remove(scen);
}

// Only regular files are read: a directory is refused by name, not read as an empty map.
TEST(MovingAi, ADirectoryIsNotAMap) {
  try {
    read_map(testing::TempDir());
    FAIL() << "a directory was read as a map";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a directory, not a regular file"), std::string::npos)
        << e.what();
  }
}

TEST(MovingAi, AcceptsAllCharactersAndTrailingBlankLines) {
  const Grid g =
      parse_map_text("type octile\r\nheight 2\r\nwidth 4\r\nmap\r\n.G@O\r\nTSW.\r\n\r\n \n");
  EXPECT_EQ(g.width(), 4);
  EXPECT_EQ(g.height(), 2);
  EXPECT_FALSE(g.blocked(0, 0));
  EXPECT_FALSE(g.blocked(1, 0));
  EXPECT_TRUE(g.blocked(2, 0));
  EXPECT_TRUE(g.blocked(3, 0));
  EXPECT_TRUE(g.blocked(0, 1));
  EXPECT_TRUE(g.blocked(1, 1));
  EXPECT_TRUE(g.blocked(2, 1));
  EXPECT_FALSE(g.blocked(3, 1));
  // No final newline.
  EXPECT_EQ(parse_map_text("type octile\nheight 1\nwidth 2\nmap\n.@").obstacle_count(), 1);
}

struct BadInput {
  const char* text;
  int line;
  const char* what;  // a fragment of the message
};

TEST(MovingAi, MalformedMapsNameTheLine) {
  const BadInput cases[] = {
      {"", 1, "type octile"},
      {"type octagon\nheight 1\nwidth 1\nmap\n.\n", 1, "type octile"},
      {"height 1\nwidth 1\nmap\n.\n", 1, "type octile"},
      {"type octile\nwidth 1\nheight 1\nmap\n.\n", 2, "height"},
      {"type octile\nheight x\nwidth 1\nmap\n.\n", 2, "not a whole number"},
      {"type octile\nheight 1.5\nwidth 1\nmap\n.\n", 2, "not a whole number"},
      {"type octile\nheight 0\nwidth 1\nmap\n", 2, "outside"},
      {"type octile\nheight 1\nwidth 99999999\nmap\n", 3, "outside"},
      // The one map size limit (core/grid.h kMaxMapSide), as for generated maps and images.
      {"type octile\nheight 8193\nwidth 1\nmap\n", 2, "height 8193 is outside [1, 8192]"},
      {"type octile\nheight 1\nwidth 2\n", 4, "map"},
      {"type octile\nheight 1\nwidth 2\nmop\n..\n", 4, "map"},
      {"type octile\nheight 2\nwidth 2\nmap\n..\n", 6, "ends after 1"},
      {"type octile\nheight 2\nwidth 2\nmap\n..\n...\n", 6, "3 characters"},
      {"type octile\nheight 2\nwidth 2\nmap\n.\n..\n", 5, "1 characters"},
      {"type octile\nheight 2\nwidth 3\nmap\n...\n.x.\n", 6, "'x' at column 2"},
      {"type octile\nheight 1\nwidth 3\nmap\n.\t.\n", 5, "byte 0x9"},
      {"type octile\nheight 1\nwidth 2\nmap\n..\n..\n", 6, "after the 1 map rows"},
      {"type octile\nheight 1\nwidth 2\nmap\n..\n\n@\n", 7, "after the 1 map rows"},
  };
  for (const BadInput& c : cases) {
    try {
      parse_map_text(c.text);
      ADD_FAILURE() << "no error for: " << c.text;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("test.map:" + std::to_string(c.line) + ": ", 0), 0U) << what;
      EXPECT_NE(what.find(c.what), std::string::npos) << what;
    }
  }
}

TEST(MovingAi, UnreadableFilesAreNamed) {
  const std::string missing = testing::TempDir() + "/no_such_dir/none.map";
  try {
    read_map(missing);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos);
  }
  EXPECT_THROW(read_scen(missing + ".scen"), InputError);
  EXPECT_THROW(write_map_file(Grid(2, 2), missing), InputError);
}

TEST(MovingAi, ScenarioVariantsParse) {
  // version 1.0, CRLF, blank lines, 6-significant-digit lengths, spaces, a path with spaces.
  const auto q = parse_scen_text(
      "\r\nversion 1.0\r\n"
      "3\tmaps/dao/arena2.map\t281\t209\t99\t159\t101\t162\t3.82843\r\n"
      "\r\n"
      "0 random512-10-0.map 512 512 220 250 220 250 0\n"
      "1\tmy maps/a b.map\t10\t10\t0\t0\t9\t9\t12.7279\n\n");
  ASSERT_EQ(q.size(), 3U);
  EXPECT_EQ(q[0].bucket, 3);
  EXPECT_EQ(q[0].map, "maps/dao/arena2.map");
  EXPECT_NEAR(q[0].optimal_length, 3.82842712, 1e-5 * 3.83);
  EXPECT_EQ(q[0].line, 3);
  EXPECT_EQ(q[1].start, q[1].goal);
  EXPECT_EQ(q[1].optimal_length, 0.0);
  EXPECT_EQ(q[1].line, 5);
  EXPECT_EQ(q[2].map, "my maps/a b.map");
  EXPECT_DOUBLE_EQ(q[2].optimal_length, 12.7279);
  EXPECT_TRUE(parse_scen_text("version 1\n").empty());
}

TEST(MovingAi, MalformedScenariosNameTheLine) {
  const std::string ok = "0\ta.map\t10\t10\t1\t2\t3\t4\t5.5\n";
  const BadInput cases[] = {
      {"", 1, "version"},
      {"version 2\n", 1, "version 1"},
      {"0\ta.map\t10\t10\t1\t2\t3\t4\t5.5\n", 1, "version 1"},
      {"version 1\n0\ta.map\t10\t10\t1\t2\t3\t4\n", 2, "found 8"},
      {"version 1\n\n0\ta.map\t10\t10\tx\t2\t3\t4\t5\n", 3, "start x 'x'"},
      {"version 1\n0\ta.map\t10\t10\t1\t2\t3\t4\tfast\n", 2, "optimal length"},
      {"version 1\n0\ta.map\t10\t10\t1\t2\t3\t4\t-1\n", 2, "optimal length"},
      {"version 1\n0\ta.map\t10\t10\t1\t2\t3\t4\tnan\n", 2, "optimal length"},
      {"version 1\n0\ta.map\t10\t10\t10\t2\t3\t4\t5\n", 2, "start x 10 is outside"},
      {"version 1\n0\ta.map\t10\t10\t1\t2\t3\t-4\t5\n", 2, "goal y -4"},
      {"version 1\n0\ta.map\t0\t10\t0\t0\t0\t0\t0\n", 2, "map width 0"},
      {"version 1\n-1\ta.map\t10\t10\t1\t2\t3\t4\t5\n", 2, "bucket"},
      {"version 1\n0\ta.map\t10\t10\t1.0\t2\t3\t4\t5\n", 2, "start x"},
      // From (1, 2) to (7, 6) no path is shorter than sqrt(52) = 7.21.
      {"version 1\n0\ta.map\t10\t10\t1\t2\t7\t6\t7.2\n", 2, "shorter than the straight line"},
  };
  for (const BadInput& c : cases) {
    try {
      parse_scen_text(c.text);
      ADD_FAILURE() << "no error for: " << c.text;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("test.scen:" + std::to_string(c.line) + ": ", 0), 0U) << what;
      EXPECT_NE(what.find(c.what), std::string::npos) << what;
    }
  }
  EXPECT_EQ(parse_scen_text("version 1\n" + ok).size(), 1U);
}

TEST(MovingAi, ScenarioMustFitTheMap) {
  Grid g(10, 8);
  g.set_blocked(3, 4, true);
  const auto q = parse_scen_text(
      "version 1\n"
      "0\ta.map\t10\t8\t1\t2\t5\t5\t5\n"     // fine
      "0\ta.map\t10\t8\t3\t4\t5\t5\t5\n"     // start on an obstacle
      "0\ta.map\t10\t8\t1\t2\t3\t4\t5\n"     // goal on an obstacle
      "0\ta.map\t10\t10\t1\t2\t5\t5\t5\n"    // declared size differs
      "0\ta.map\t12\t8\t11\t2\t5\t5\t7\n");  // declared size differs (and start outside)
  ASSERT_EQ(q.size(), 5U);
  EXPECT_NO_THROW(check_scenario_fits(g, q[0], "s.scen"));
  const char* expected[] = {"s.scen:3: start (3, 4) is on an obstacle",
                            "s.scen:4: goal (3, 4) is on an obstacle", "s.scen:5: declares",
                            "s.scen:6: declares"};
  for (int i = 1; i < 5; ++i) {
    try {
      check_scenario_fits(g, q[i], "s.scen");
      ADD_FAILURE() << i;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(expected[i - 1], 0), 0U) << e.what();
    }
  }
  // Queries for the map they are checked against: its file name, whatever folders the column
  // names before it.
  EXPECT_NO_THROW(check_scenario_fits(g, q[0], "s.scen", "/data/maps/a.map"));
  try {
    check_scenario_fits(g, q[0], "s.scen", "b.map");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "s.scen:2: names map 'a.map', not b.map");
  }
  ScenarioQuery outside = q[0];
  outside.start = {10, 0};
  try {
    check_scenario_fits(g, outside, "s.scen");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("outside the 10x8 map"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace agv
