// A plain A* to time ours against (perf/README.md "A* side by side", issue 47 stage e): the
// textbook search a newcomer would write, on its own (no agvbench code): a byte grid, a
// std::priority_queue binary heap with stale entries skipped, g-values reset per query,
// 8-connected moves of cost 1 and sqrt(2) without corner cutting (MovingAI's rules), the octile
// heuristic. Reads a MovingAI .map and .scen; prints one line: queries, mismatches against the
// scenario optima (relative 1e-5) and the searches' total time by its own clock.
// Usage: plain_astar MAP SCEN
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <queue>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

struct Map {
  int w = 0, h = 0;
  std::vector<char> free;  // row-major
  bool open(int x, int y) const { return x >= 0 && y >= 0 && x < w && y < h && free[y * w + x]; }
};

Map read_map(const char* path) {
  std::ifstream in(path);
  std::string word, line;
  Map m;
  in >> word >> word >> word >> m.h >> word >> m.w >> word;  // type octile height H width W map
  std::getline(in, line);
  for (int y = 0; y < m.h && std::getline(in, line); ++y)
    for (int x = 0; x < m.w; ++x) m.free.push_back(line[x] == '.' || line[x] == 'G');
  return m;
}

double octile(int dx, int dy) {
  dx = std::abs(dx), dy = std::abs(dy);
  return std::max(dx, dy) + (std::sqrt(2.0) - 1.0) * std::min(dx, dy);
}

double astar(const Map& m, int sx, int sy, int tx, int ty, std::vector<double>& g) {
  using Entry = std::pair<double, int>;  // f, cell
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  g.assign(m.free.size(), std::numeric_limits<double>::infinity());
  const int start = sy * m.w + sx, goal = ty * m.w + tx;
  g[start] = 0.0;
  open.push({octile(sx - tx, sy - ty), start});
  while (!open.empty()) {
    const auto [f, c] = open.top();
    open.pop();
    const int x = c % m.w, y = c / m.w;
    if (f > g[c] + octile(x - tx, y - ty) + 1e-9) continue;  // stale entry
    if (c == goal) return g[c];
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || !m.open(x + dx, y + dy)) continue;
        if (dx != 0 && dy != 0 && (!m.open(x + dx, y) || !m.open(x, y + dy))) continue;
        const int n = c + dy * m.w + dx;
        const double ng = g[c] + (dx != 0 && dy != 0 ? std::sqrt(2.0) : 1.0);
        if (ng < g[n]) {
          g[n] = ng;
          open.push({ng + octile(x + dx - tx, y + dy - ty), n});
        }
      }
  }
  return -1.0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: plain_astar MAP SCEN\n");
    return 2;
  }
  const Map m = read_map(argv[1]);
  std::ifstream scen(argv[2]);
  std::string line;
  std::getline(scen, line);  // version 1
  std::vector<double> g;
  long queries = 0, mismatches = 0;
  std::chrono::nanoseconds total{0};
  while (std::getline(scen, line)) {
    std::istringstream f(line);
    std::string bucket, name;
    int w, h, sx, sy, tx, ty;
    double optimal;
    if (!(f >> bucket >> name >> w >> h >> sx >> sy >> tx >> ty >> optimal)) continue;
    const auto t0 = std::chrono::steady_clock::now();
    const double length = astar(m, sx, sy, tx, ty, g);
    total += std::chrono::steady_clock::now() - t0;
    ++queries;
    mismatches += std::abs(length - optimal) > 1e-5 * std::max(1.0, optimal);
  }
  std::printf("queries %ld mismatches %ld total_ns %lld\n", queries, mismatches,
              static_cast<long long>(total.count()));
  return mismatches == 0 ? 0 : 1;
}
