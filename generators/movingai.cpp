#include "generators/movingai.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>
#include <string_view>

#include "core/printable.h"
#include "core/str_cat.h"
#include "core/text_file.h"

namespace agv {
namespace {

// Lines with their 1-based numbers; a trailing '\r' (CRLF files) is dropped.
class LineReader {
 public:
  LineReader(std::istream& in, const std::string& name) : in_(in), name_(name) {}
  bool next(std::string& text) {
    if (!std::getline(in_, text)) return false;
    ++line_;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    return true;
  }
  int line() const { return line_; }
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw InputError(str_cat(name_, ":", line, ": ", what));
  }
  [[noreturn]] void fail(const std::string& what) const { fail(line_, what); }

 private:
  std::istream& in_;
  const std::string& name_;
  int line_ = 0;
};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

bool blank(std::string_view s) {
  for (char c : s) {
    if (!is_space(c)) return false;
  }
  return true;
}

// Whitespace-separated tokens, as views into `s`.
std::vector<std::string_view> tokens(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && is_space(s[i])) ++i;
    const std::size_t start = i;
    while (i < s.size() && !is_space(s[i])) ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

bool parse_int(std::string_view s, long long& value) {
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, value);
  return ec == std::errc() && ptr == end;
}

bool parse_double(std::string_view s, double& value) {
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, value);
  return ec == std::errc() && ptr == end && std::isfinite(value);
}

// "height 512" -> 512, checked against [1, kMaxMapSide].
int parse_size_line(LineReader& reader, const std::string& text, std::string_view key) {
  const auto t = tokens(text);
  if (t.size() != 2 || t[0] != key)
    reader.fail(str_cat("expected '", key, " N', found '", printable(text), "'"));
  long long v = 0;
  if (!parse_int(t[1], v))
    reader.fail(str_cat(key, " '", printable(t[1]), "' is not a whole number"));
  if (v < 1 || v > kMaxMapSide)
    reader.fail(str_cat(key, " ", v, " is outside [1, ", kMaxMapSide, "]"));
  return static_cast<int>(v);
}

std::string describe(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u >= 0x21 && u < 0x7f) return str_cat("'", c, "'");
  return str_cat("byte 0x", std::hex, static_cast<int>(u));
}

}  // namespace

Grid parse_map(std::istream& in, const std::string& name) {
  LineReader reader(in, name);
  std::string text;
  auto header = [&](std::string_view what) {
    if (!reader.next(text))
      reader.fail(reader.line() + 1, str_cat("file ends before '", what, "'"));
  };
  header("type octile");
  if (const auto t = tokens(text); t.size() != 2 || t[0] != "type" || t[1] != "octile") {
    reader.fail(str_cat("expected 'type octile', found '", printable(text), "'"));
  }
  header("height");
  const int height = parse_size_line(reader, text, "height");
  header("width");
  const int width = parse_size_line(reader, text, "width");
  header("map");
  if (const auto t = tokens(text); t.size() != 1 || t[0] != "map") {
    reader.fail(str_cat("expected 'map', found '", printable(text), "'"));
  }

  Grid grid(width, height);
  for (int y = 0; y < height; ++y) {
    if (!reader.next(text)) {
      reader.fail(reader.line() + 1,
                  str_cat("file ends after ", y, " map rows, expected ", height));
    }
    if (std::ssize(text) != width) {
      reader.fail(str_cat("map row ", y, " has ", text.size(), " characters, expected ", width));
    }
    for (int x = 0; x < width; ++x) {
      switch (text[x]) {
        case '.':
        case 'G':
          break;
        case '@':
        case 'O':
        case 'T':
        case 'S':
        case 'W':
          grid.set_blocked(x, y, true);
          break;
        default:
          reader.fail(str_cat("unknown map character ", describe(text[x]), " at column ", x + 1));
      }
    }
  }
  while (reader.next(text)) {
    if (!blank(text)) reader.fail(str_cat("unexpected content after the ", height, " map rows"));
  }
  return grid;
}

Grid read_map(const std::string& path) {
  std::istringstream in(read_text_file(path, "map file"));
  return parse_map(in, path);
}

void write_map(const Grid& grid, std::ostream& out) {
  out << "type octile\nheight " << grid.height() << "\nwidth " << grid.width() << "\nmap\n";
  std::string row(static_cast<std::size_t>(grid.width()) + 1, '\n');
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) row[x] = grid.blocked(x, y) ? '@' : '.';
    out << row;
  }
}

void write_map_file(const Grid& grid, const std::string& path) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(str_cat(path, ": cannot open for writing"));
  write_map(grid, out);
  out.flush();
  if (!out) throw InputError(str_cat(path, ": write failed"));
}

std::vector<ScenarioQuery> parse_scen(std::istream& in, const std::string& name) {
  LineReader reader(in, name);
  std::string text;
  bool have_version = false;
  std::vector<ScenarioQuery> out;
  while (reader.next(text)) {
    if (blank(text)) continue;
    const auto t = tokens(text);
    if (!have_version) {
      if (t.size() != 2 || t[0] != "version" || (t[1] != "1" && t[1] != "1.0")) {
        reader.fail(str_cat("expected 'version 1', found '", printable(text), "'"));
      }
      have_version = true;
      continue;
    }
    // bucket, map, width, height, start x, start y, goal x, goal y, length. The map column is
    // everything between the bucket and the last seven fields, so a path with spaces survives.
    if (t.size() < 9) {
      reader.fail(
          str_cat("expected 9 fields (bucket, map, map width, map height, start x, start y,"
                  " goal x, goal y, optimal length), found ",
                  t.size()));
    }
    const std::size_t n = t.size();
    ScenarioQuery q;
    q.line = reader.line();
    const std::string_view first = t[1];
    const std::string_view last = t[n - 8];
    q.map.assign(first.data(), static_cast<std::size_t>(last.data() + last.size() - first.data()));
    static constexpr std::string_view kIntNames[] = {
        "bucket", "map width", "map height", "start x", "start y", "goal x", "goal y"};
    const std::string_view int_fields[] = {t[0],     t[n - 7], t[n - 6], t[n - 5],
                                           t[n - 4], t[n - 3], t[n - 2]};
    long long v[7] = {};
    for (int i = 0; i < 7; ++i) {
      if (!parse_int(int_fields[i], v[i])) {
        reader.fail(
            str_cat(kIntNames[i], " '", printable(int_fields[i]), "' is not a whole number"));
      }
    }
    if (v[0] < 0 || v[0] > 1'000'000'000) reader.fail(str_cat("bucket ", v[0], " is out of range"));
    for (int i = 1; i <= 2; ++i) {
      if (v[i] < 1 || v[i] > kMaxMapSide) {
        reader.fail(str_cat(kIntNames[i], " ", v[i], " is outside [1, ", kMaxMapSide, "]"));
      }
    }
    for (int i = 3; i <= 6; ++i) {
      const long long limit = (i % 2 == 1) ? v[1] : v[2];  // x against width, y against height
      if (v[i] < 0 || v[i] >= limit) {
        reader.fail(
            str_cat(kIntNames[i], " ", v[i], " is outside the declared ", v[1], "x", v[2], " map"));
      }
    }
    if (!parse_double(t[n - 1], q.optimal_length) || q.optimal_length < 0.0) {
      reader.fail(
          str_cat("optimal length '", printable(t[n - 1]), "' is not a non-negative number"));
    }
    // No path is shorter than the straight line (the octile optimum is at least as long): a
    // smaller figure is a damaged file, and every planner would seem to beat it. The margin is
    // the rounding of lengths written with 6 significant digits (some published files).
    const double straight =
        std::hypot(static_cast<double>(v[5] - v[3]), static_cast<double>(v[6] - v[4]));
    if (q.optimal_length < straight - 1e-5 * std::max(1.0, straight)) {
      reader.fail(str_cat("optimal length ", t[n - 1], " is shorter than the straight line from (",
                          v[3], ", ", v[4], ") to (", v[5], ", ", v[6], "), ", straight));
    }
    q.bucket = static_cast<int>(v[0]);
    q.map_width = static_cast<int>(v[1]);
    q.map_height = static_cast<int>(v[2]);
    q.start = {static_cast<int>(v[3]), static_cast<int>(v[4])};
    q.goal = {static_cast<int>(v[5]), static_cast<int>(v[6])};
    out.push_back(std::move(q));
  }
  if (!have_version) reader.fail(reader.line() + 1, "no 'version 1' line");
  return out;
}

std::vector<ScenarioQuery> read_scen(const std::string& path) {
  std::istringstream in(read_text_file(path, "scenario file"));
  return parse_scen(in, path);
}

void check_scenario_fits(const Grid& grid, const ScenarioQuery& query, const std::string& scen_name,
                         const std::string& map_path) {
  auto fail = [&](const std::string& what) {
    throw InputError(str_cat(scen_name, ":", query.line, ": ", what));
  };
  if (!map_path.empty()) {
    const std::string named = std::filesystem::path(query.map).filename().string();
    const std::string given = std::filesystem::path(map_path).filename().string();
    if (named != given) fail(str_cat("names map '", printable(query.map), "', not ", given));
  }
  if (query.map_width != grid.width() || query.map_height != grid.height()) {
    fail(str_cat("declares a ", query.map_width, "x", query.map_height, " map but the map is ",
                 grid.width(), "x", grid.height()));
  }
  const std::pair<const char*, Cell> ends[] = {{"start", query.start}, {"goal", query.goal}};
  for (const auto& [what, c] : ends) {
    if (!grid.in_bounds(c)) {
      fail(str_cat(what, " (", c.x, ", ", c.y, ") is outside the ", grid.width(), "x",
                   grid.height(), " map"));
    }
    if (grid.blocked(c)) fail(str_cat(what, " (", c.x, ", ", c.y, ") is on an obstacle"));
  }
}

}  // namespace agv
