// Map sources (generators/map_files.h): the user's MovingAI maps with their .scen queries and
// occupancy images (map_server .yaml + .pgm, .png) swept like generated maps.
#include <gtest/gtest.h>
#include <png.h>
#include <stdlib.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/rng.h"
#include "engine/outputs/report.h"
#include "engine/plan/config_loader.h"
#include "engine/plan/sweep_config.h"
#include "engine/plan/sweep_plan.h"
#include "engine/sweep/sweep_runner.h"
#include "generators/movingai.h"
#include "generators/occupancy_image.h"
#include "tests/address_space_limit.h"
#include "tests/movingai_data.h"
#include "tests/test_size.h"

namespace agv {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A fresh folder under the system's temporary one, removed with the object.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "agv_map_files_XXXXXX").string();
    path_ = ::mkdtemp(pattern.data());
  }
  ~TempDir() { fs::remove_all(path_); }
  std::string operator/(const std::string& name) const { return path_ + "/" + name; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  ASSERT_TRUE(out.good()) << path;
}

// Grey values around both of map_server's default thresholds (free below 0.196, occupied above
// 0.65 of (255 - grey) / 255) and of the .yaml's own (0.3 / 0.7), black and white included.
constexpr unsigned char kGreys[] = {0, 30, 76, 77, 89, 90, 150, 178, 179, 204, 205, 230, 254, 255};

// `background` is the free grey (255 plain, 0 negated).
std::vector<unsigned char> random_greys(int w, int h, std::uint64_t seed,
                                        unsigned char background = 255) {
  Rng rng(seed, 3);
  std::vector<unsigned char> g(static_cast<std::size_t>(w) * h);
  for (auto& v : g) {
    // Mostly free (white), so that random endpoints connect.
    v = rng.below(3) == 0 ? kGreys[rng.below(std::size(kGreys))] : background;
  }
  return g;
}

// The grid map_server's trinary rule makes of `greys`, computed here from its definition: a
// cell is free only when its occupancy probability is below free_thresh.
Grid expected_grid(const std::vector<unsigned char>& greys, int w, int h, double free_thresh,
                   bool negate, double cell_edge) {
  Grid g(w, h, cell_edge);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const double v = greys[static_cast<std::size_t>(y) * w + x];
      const double p = negate ? v / 255.0 : (255.0 - v) / 255.0;
      if (!(p < free_thresh)) g.set_blocked(x, y, true);
    }
  }
  return g;
}

void write_pgm(const std::string& path, const std::vector<unsigned char>& g, int w, int h,
               bool ascii) {
  std::ostringstream out;
  out << (ascii ? "P2" : "P5") << "\n# written by test_map_files\n" << w << " " << h << "\n255\n";
  if (ascii) {
    for (std::size_t i = 0; i < g.size(); ++i) out << int{g[i]} << ((i + 1) % w ? " " : "\n");
  } else {
    out.write(reinterpret_cast<const char*>(g.data()), static_cast<std::streamsize>(g.size()));
  }
  write_text(path, out.str());
}

void write_png(const std::string& path, const std::vector<unsigned char>& g, int w, int h) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(w);
  image.height = static_cast<png_uint_32>(h);
  image.format = PNG_FORMAT_GRAY;
  ASSERT_NE(png_image_write_to_file(&image, path.c_str(), 0, g.data(), 0, nullptr), 0)
      << image.message;
}

json image_sweep(const std::vector<std::string>& files) {
  return {{"name", "images"},
          {"seed", 9},
          {"generators", {{{"name", "image"}, {"params", {{"files", files}}}}}},
          {"maps_per_cell", 12},
          {"map", {{"endpoints", "random"}, {"min_distance", 6}, {"cell_edge", 0.5}}},
          {"planners", {"astar", "dijkstra", "ma_star"}},
          {"report", "unused.json"}};
}

const RunSlot* find_slot(const SweepResults& r, std::int64_t task, const std::string& label) {
  for (std::size_t p = 0; p < r.labels.size(); ++p)
    if (r.labels[p] == label) return &r.run(task, p);
  return nullptr;
}

std::size_t metric(std::string_view name) {
  for (std::size_t i = 0; i < kRunMetricNames.size(); ++i)
    if (kRunMetricNames[i] == name) return i;
  ADD_FAILURE() << name;
  return 0;
}

// Every `every`-th .scen query of each map matching `glob` through A* and Dijkstra, each path as
// long as the scenario's optimum; `expected_maps` queries in all. Without the any-angle
// reference, whose cost grows with the start's component (the whole 512x512 maze: seconds per
// query), as configs/movingai.json does.
void expect_scen_optima(const std::string& glob, int every, std::int64_t expected_maps) {
  const json j = {{"name", "scen"},
                  {"generators",
                   {{{"name", "movingai"},
                     {"params", {{"files", {glob}}, {"queries", "scen"}, {"scen_every", every}}}}}},
                  {"planners", {"astar", "dijkstra"}},
                  {"references", {{"any_angle", false}}},
                  {"report", "unused.json"}};
  const SweepConfig config = parse_config(j);
  const SweepPlan plan = plan_sweep(config);
  ASSERT_GE(plan.cells.size(), 2u);
  std::int64_t maps = 0;
  for (const auto& cell : plan.cells) {
    ASSERT_NE(cell.file, nullptr);
    EXPECT_EQ(cell.key, "movingai/" + fs::path(cell.file->path).filename().string());
    EXPECT_EQ(static_cast<std::size_t>(cell.maps),
              (read_scen(cell.file->path + ".scen").size() + every - 1) / every)
        << cell.key;
    maps += cell.maps;
  }
  EXPECT_EQ(plan.map_tasks(), maps);
  EXPECT_EQ(maps, expected_maps);
  SweepOptions options;
  options.threads = 2;
  const SweepResults r = run_sweep(config, options);
  const std::size_t scen = metric("scen_ratio");
  const std::size_t any_angle = metric("any_angle_ratio");
  std::int64_t checked = 0;
  for (std::int64_t t = 0; t < r.plan.map_tasks(); ++t) {
    for (std::size_t p = 0; p < r.labels.size(); ++p) {
      const RunSlot& s = r.run(t, p);
      ASSERT_TRUE(s.done);
      ASSERT_EQ(s.outcome, Outcome::success)
          << r.plan.cell_of(t).key << " query " << r.plan.map_index_of(t) << " " << r.labels[p];
      EXPECT_NEAR(s.metrics[scen], 1.0, 1e-6)
          << r.plan.cell_of(t).key << " query " << r.plan.map_index_of(t) << " " << r.labels[p];
      EXPECT_TRUE(std::isnan(s.metrics[any_angle]));
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2 * maps);
  // And the report aggregates it like any metric.
  const json report = build_report(config, r);
  for (const auto& cell : report["cells"])
    for (const auto& pl : cell["planners"]) {
      EXPECT_NEAR(pl["metrics"]["scen_ratio"]["max"].get<double>(), 1.0, 1e-6) << cell["cell"];
      EXPECT_EQ(pl["metrics"]["any_angle_ratio"]["count"], 0) << cell["cell"];
    }
  EXPECT_EQ(report["config"]["references"], json({{"any_angle", false}}));
}

// The acceptance check of issue 16: every 20th .scen query of every map of the full sets (942 of
// 18,820).
TEST(MapFiles, FullSetsScenQueriesMatchTheirOptimum) {
  AGV_MOVINGAI_SETS_OR_SKIP(sets);
  expect_scen_optima(sets + "/*.map", 20, 942);
}

// A scenario optimum assumes MovingAI's convention; under another collision model scen_ratio is
// not defined (and a bucket range selects only its queries).
TEST(MapFiles, FullSetsScenRatioOnlyUnderTheScenariosConvention) {
  AGV_MOVINGAI_SETS_OR_SKIP(sets);
  json j = {{"generators",
             {{{"name", "movingai"},
               {"params",
                {{"files", {sets + "/random512-10-0.map"}},
                 {"queries", "scen"},
                 {"scen_buckets", {3, 4}}}}}}},
            {"planners", {"astar"}},
            {"report", "unused.json"}};
  const auto queries = read_scen(sets + "/random512-10-0.map.scen");
  std::size_t in_range = 0;
  for (const auto& q : queries) in_range += q.bucket >= 3 && q.bucket <= 4;
  ASSERT_GT(in_range, 0u);
  for (const bool model : {true, false}) {
    if (!model) j["collision"] = {{"corner_rule", "no_corner_cut"}, {"clearance", 0.3}};
    const SweepConfig config = parse_config(j);
    SweepOptions options;
    options.threads = 2;
    const SweepResults r = run_sweep(config, options);
    ASSERT_EQ(r.plan.map_tasks(), static_cast<std::int64_t>(in_range));
    for (std::int64_t t = 0; t < r.plan.map_tasks(); ++t) {
      const RunSlot& s = r.run(t, 0);
      if (s.outcome != Outcome::success) continue;
      if (model) {
        EXPECT_NEAR(s.metrics[metric("scen_ratio")], 1.0, 1e-6);
      } else {
        EXPECT_TRUE(std::isnan(s.metrics[metric("scen_ratio")]));
      }
    }
  }
}

// Occupancy images written here are read back cell for cell (thresholds, negate, resolution as
// the cell edge), and swept: every path validates.
TEST(MapFiles, OccupancyImagesAreReadAsWrittenAndSwept) {
  TempDir dir;
  struct Case {
    std::string file;
    int w, h;
    Grid expected;
  };
  std::vector<Case> cases;
  for (std::uint64_t seed = 0; seed < 4; ++seed) {
    const int w = 17 + static_cast<int>(seed) * 5, h = 23 - static_cast<int>(seed) * 2;
    const bool negate = seed >= 2;
    const auto greys = random_greys(w, h, seed, negate ? 0 : 255);
    const std::string stem = "map" + std::to_string(seed);
    // A .yaml with thresholds, negate and resolution of its own, over a binary or ascii PGM.
    write_pgm(dir / (stem + ".pgm"), greys, w, h, seed % 2 == 1);
    write_text(dir / (stem + ".yaml"),
               "image: " + stem + ".pgm\nresolution: 0.05\norigin: [-1.0, 2.5, 0.0]\nnegate: " +
                   std::string(negate ? "1" : "0") +
                   "\noccupied_thresh: 0.7\nfree_thresh: 0.3\nmode: trinary\n");
    cases.push_back({stem + ".yaml", w, h, expected_grid(greys, w, h, 0.3, negate, 0.05)});
    // A bare PNG: map_server's defaults, the config's cell edge.
    const auto png_greys = random_greys(h, w, seed + 10);
    write_png(dir / ("img" + std::to_string(seed) + ".png"), png_greys, h, w);
    cases.push_back({"img" + std::to_string(seed) + ".png", h, w,
                     expected_grid(png_greys, h, w, 0.196, false, 0.5)});
  }
  for (const auto& c : cases) {
    const bool yaml = c.file.ends_with(".yaml");
    const OccupancyImage read = read_occupancy_image(dir / c.file, 0.5);
    EXPECT_TRUE(read.grid.same_cells(c.expected)) << c.file;
    EXPECT_EQ(read.grid.cell_edge(), yaml ? 0.05 : 0.5) << c.file;
    EXPECT_GT(c.expected.obstacle_count(), 0) << c.file;
  }

  const SweepConfig config = parse_config(image_sweep({"*.yaml", "img*.png"}), dir.path());
  const SweepPlan plan = plan_sweep(config);
  ASSERT_EQ(plan.cells.size(), cases.size());
  // Each pattern's matches sorted, the patterns in order: map0..3.yaml, then img0..3.png.
  for (std::size_t i = 0; i < plan.cells.size(); ++i) {
    const auto& cell = plan.cells[i];
    const Case& c = cases[i < 4 ? 2 * i : 2 * (i - 4) + 1];
    EXPECT_EQ(cell.key, "image/" + c.file);
    EXPECT_TRUE(cell.file->grid.same_cells(c.expected)) << cell.key;
    EXPECT_EQ(cell.size.width, c.w);
    EXPECT_EQ(cell.maps, 12);
  }
  SweepOptions options;
  options.threads = 2;
  const SweepResults r = run_sweep(config, options);
  const std::size_t length = metric("path_length"), length_m = metric("path_length_m");
  for (std::int64_t t = 0; t < r.plan.map_tasks(); ++t) {
    const SweepCell& cell = r.plan.cell_of(t);
    for (const std::string label : {"astar", "dijkstra", "ma_star"}) {
      const RunSlot& s = *find_slot(r, t, label);
      // require_solvable (the default) drew connected endpoints: every planner finds a path,
      // and its path passed the validator (an invalid one would be invalid_path).
      ASSERT_EQ(s.outcome, Outcome::success) << cell.key << " map " << t << " " << label;
      EXPECT_NEAR(s.metrics[length_m], s.metrics[length] * cell.file->grid.cell_edge(), 1e-9);
      if (label != "ma_star") {
        EXPECT_NEAR(s.metrics[metric("optimality_ratio")], 1.0, 1e-9);
      }
      EXPECT_TRUE(std::isnan(s.metrics[metric("scen_ratio")]));
    }
  }
}

// MovingAI maps with the sweep's own endpoint rule: maps_per_cell queries per file, the same
// report on one thread and two.
TEST(MapFiles, FileMapSweepIsIdenticalOnOneAndTwoThreads) {
  TempDir dir;
  const auto greys = random_greys(31, 29, 77);
  write_pgm(dir / "a.pgm", greys, 31, 29, false);
  Rng rng(78, 78);
  Grid random_map(97, 83);
  for (int y = 0; y < random_map.height(); ++y)
    for (int x = 0; x < random_map.width(); ++x) random_map.set_blocked(x, y, rng.chance(0.1));
  write_map_file(random_map, dir / "r.map");
  const json j = {{"name", "files"},
                  {"seed", 4},
                  {"generators",
                   {"uniform",
                    {{"name", "movingai"}, {"params", {{"files", {"r.map"}}}}},
                    {{"name", "image"}, {"params", {{"files", {"a.pgm"}}}}}}},
                  {"sizes", {16}},
                  {"maps_per_cell", 6},
                  {"map", {{"endpoints", "random"}, {"min_distance", 10}}},
                  {"planners", {"astar", "ma_star", "rrt"}},
                  {"report", "unused.json"}};
  const SweepConfig config = parse_config(j, dir.path());
  std::string text[2];
  for (int threads : {1, 2}) {
    SweepOptions options;
    options.threads = threads;
    const SweepResults r = run_sweep(config, options);
    EXPECT_EQ(r.plan.cells.size(), 3u);
    EXPECT_EQ(r.plan.map_tasks(), 18);
    text[threads - 1] = deterministic_part(build_report(config, r)).dump(1);
  }
  EXPECT_EQ(text[0], text[1]);
  EXPECT_NE(text[0].find("\"movingai/r.map\""), std::string::npos);
  EXPECT_NE(text[0].find("\"image/a.pgm\""), std::string::npos);
}

std::string load_error(const json& j, const std::string& dir) {
  try {
    parse_config(j, dir);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(MapFiles, BadFilesAreRefusedByNameAndLine) {
  TempDir dir;
  const auto with = [](const std::string& source, json params) {
    return json{{"generators", {{{"name", source}, {"params", params}}}},
                {"planners", {"astar"}},
                {"report", "unused.json"}};
  };
  std::string e = load_error(with("movingai", {{"files", {"nothing*.map"}}}), dir.path());
  EXPECT_TRUE(contains(e, "generators[0].params.files[0]: \"nothing*.map\" matches no file")) << e;
  e = load_error(with("movingai", {{"files", {"missing.map"}}}), dir.path());
  EXPECT_TRUE(contains(e, "\"missing.map\" matches no file (no such file)")) << e;

  write_text(dir / "bad.map", "type octile\nheight 2\nwidth 3\nmap\n...\n.x.\n");
  e = load_error(with("movingai", {{"files", {"bad.map"}}}), dir.path());
  EXPECT_TRUE(contains(e, "bad.map:6:")) << e;

  write_text(dir / "ok.map", "type octile\nheight 2\nwidth 3\nmap\n...\n...\n");
  e = load_error(with("movingai", {{"files", {"ok.map"}}, {"queries", "scen"}}), dir.path());
  EXPECT_TRUE(contains(e, "ok.map.scen")) << e;
  e = load_error(with("movingai", {{"files", {"ok.map"}}, {"scen_every", 2}}), dir.path());
  EXPECT_TRUE(contains(e, "generators[0].params.scen_every: applies to queries \"scen\" only"))
      << e;
  e = load_error(with("movingai", {{"files", {"ok.map"}}, {"quries", "scen"}}), dir.path());
  EXPECT_TRUE(contains(e, "generators[0].params.quries: unknown field")) << e;
  write_text(dir / "ok.map.scen",
             "version 1\n0\tok.map\t3\t2\t0\t0\t2\t1\t2.41421356\n"
             "0\tok.map\t3\t2\t0\t0\t9\t1\t9\n");
  e = load_error(with("movingai", {{"files", {"ok.map"}}, {"queries", "scen"}}), dir.path());
  EXPECT_TRUE(contains(e, "ok.map.scen:3:")) << e;

  const std::vector<unsigned char> grey(12, 255);
  write_pgm(dir / "ok.pgm", grey, 4, 3, false);
  write_text(dir / "unknown.yaml", "image: ok.pgm\nresolution: 0.1\nthreshold: 0.5\n");
  e = load_error(with("image", {{"files", {"unknown.yaml"}}}), dir.path());
  EXPECT_TRUE(contains(e, "unknown.yaml:3: unknown key \"threshold\"")) << e;
  write_text(dir / "broken.yaml", "image: ok.pgm\nresolution: [0.1\n");
  e = load_error(with("image", {{"files", {"broken.yaml"}}}), dir.path());
  EXPECT_TRUE(contains(e, "broken.yaml:") && contains(e, "malformed YAML")) << e;
  write_text(dir / "twice.yaml", "image: ok.pgm\nresolution: 0.1\nresolution: 0.2\n");
  e = load_error(with("image", {{"files", {"twice.yaml"}}}), dir.path());
  EXPECT_TRUE(contains(e, "twice.yaml:3: resolution: given twice (first at line 2)")) << e;
  write_text(dir / "nores.yaml", "image: ok.pgm\n");
  e = load_error(with("image", {{"files", {"nores.yaml"}}}), dir.path());
  EXPECT_TRUE(contains(e, "nores.yaml:1: resolution: missing")) << e;
  write_text(dir / "short.pgm", "P2\n# c\n3 2\n255\n0 0 0\n0 0\n");
  e = load_error(with("image", {{"files", {"short.pgm"}}}), dir.path());
  EXPECT_TRUE(contains(e, "short.pgm:6: the samples end after 5 of 3x2")) << e;
  write_text(dir / "big.pgm", "P2\n2 1\n15\n3 16\n");
  e = load_error(with("image", {{"files", {"big.pgm"}}}), dir.path());
  EXPECT_TRUE(contains(e, "big.pgm:4: pixel value 16 is above the maximum value 15")) << e;
  write_text(dir / "fake.png", "not a png");
  e = load_error(with("image", {{"files", {"fake.png"}}}), dir.path());
  EXPECT_TRUE(contains(e, "fake.png: not a readable PNG image")) << e;
  // A file whose corners are obstacles cannot give "corners" endpoints.
  write_text(dir / "corner.map", "type octile\nheight 2\nwidth 3\nmap\n..@\n...\n");
  e = load_error(with("movingai", {{"files", {"corner.map"}}}), dir.path());
  EXPECT_TRUE(contains(e, "corner.map: map.endpoints \"corners\": the goal corner (2, 0)")) << e;
}

// A small PNG that declares the largest image (8192x8192, about 400 MiB decoded) under an
// address-space limit it does not fit: one line naming the file, not a bare bad_alloc. Not under a
// sanitizer, whose reserved address space such a limit would starve.
TEST(MapFiles, AnImageTooLargeToDecodeIsNamed) {
  if (test::kSanitized) return;
  TempDir dir;
  const int side = kMaxMapSide;
  write_png(dir / "huge.png", std::vector<unsigned char>(std::size_t(side) * side, 255), side,
            side);
  std::string e;
  {
    const test::AddressSpaceLimit limit(128.0 * 1024 * 1024);
    ASSERT_FALSE(limit.failed());
    if (!limit.active()) return;  // a tighter limit already: nothing to prove here
    try {
      (void)read_occupancy_image(dir / "huge.png", 0.05);
    } catch (const std::runtime_error& err) {
      e = err.what();
    }
  }
  EXPECT_TRUE(contains(e, "huge.png: decoding the image needs more memory than this process can"))
      << e;
}

// The config hash covers the files' contents: a changed map file is another sweep, and a config
// as run (a worker's, a report's) names the file that changed.
TEST(MapFiles, TheConfigHashCoversTheFilesContents) {
  TempDir dir;
  write_text(dir / "m.map", "type octile\nheight 3\nwidth 3\nmap\n...\n...\n...\n");
  const json j = {{"generators", {{{"name", "movingai"}, {"params", {{"files", {"m.map"}}}}}}},
                  {"planners", {"astar"}},
                  {"report", "unused.json"}};
  const SweepConfig before = parse_config(j, dir.path());
  const json as_run = config_as_run(before);
  EXPECT_EQ(config_as_run(parse_config(as_run, dir.path())).dump(), as_run.dump());
  write_text(dir / "m.map", "type octile\nheight 3\nwidth 3\nmap\n...\n.@.\n...\n");
  const SweepConfig after = parse_config(j, dir.path());
  EXPECT_NE(config_hash(before), config_hash(after));
  const std::string e = load_error(as_run, dir.path());
  EXPECT_TRUE(contains(e, "generators[0]: map file " + dir.path() + "/m.map changed")) << e;
}

}  // namespace
}  // namespace agv
