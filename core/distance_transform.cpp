#include "core/distance_transform.h"

// Exact clearance of a point or segment, using the transform to bound the search.
//
// Let S be the query set (a point or a segment) and C the closed cells covering it. For a point
// q in cell c and an obstacle square o: |q - centre(c)| <= r and |centre(o) - q| - r <=
// dist(q, o) <= |centre(o) - q| + r with r = sqrt(2)/2. Hence
//   (1) every q in c has clearance >= sqrt(D(c)) - sqrt(2)   (D = squared centre distance), and
//   (2) an obstacle o with dist(q, o) < best for some q in c has its centre within
//       best + sqrt(2) of centre(c), and (by definition of D) not closer than sqrt(D(c)).
// So: take the covering cells in ascending D; keep best = the smallest exact set-to-square
// distance seen (seeded with each cell's feature-transform obstacle); stop at the first cell
// whose bound (1) reaches best; otherwise test every obstacle square in the annulus (2) around
// that cell's centre with the exact convex distance (segment vs. box: 0 if they intersect, else
// the least of the endpoint-to-box and box-corner-to-segment distances). No sampling anywhere.
// Cost per examined cell is the annulus area, O(sqrt(D)); for a segment, O(length) cells at most,
// usually far fewer once best is tight.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/cell_geometry.h"

namespace agv {
namespace {

constexpr double kSqrt2 = 1.4142135623730951;

std::int64_t floor_div(std::int64_t a, std::int64_t b) {  // b > 0
  std::int64_t q = a / b;
  if ((a % b != 0) && (a < 0)) --q;
  return q;
}

// Smallest integer k >= 0 with k * k >= v (v >= 0).
std::int64_t ceil_sqrt(std::int64_t v) {
  if (v <= 0) return 0;
  auto k = static_cast<std::int64_t>(std::sqrt(static_cast<double>(v)));
  while (k * k < v) ++k;
  while (k > 0 && (k - 1) * (k - 1) >= v) --k;
  return k;
}

}  // namespace

DistanceTransform::DistanceTransform(const Grid& grid)
    : width_(grid.width()), height_(grid.height()), stride_(grid.stride()) {
  const int cols = stride_;
  const int rows = height_ + 2;
  const auto size = static_cast<std::size_t>(grid.padded_size());
  blocked_.assign(grid.occupancy(), grid.occupancy() + size);
  squared_.assign(size, 0);
  nearest_.assign(size, 0);

  // Column pass: squared vertical distance to the nearest obstacle in the same padded column
  // (the border rows guarantee one above and one below), and that obstacle's row (kept in
  // nearest_ until the row pass replaces it with the full index).
  std::vector<int> above(static_cast<std::size_t>(rows));
  for (int x = 0; x < cols; ++x) {
    int last = 0;
    for (int y = 0; y < rows; ++y) {
      if (blocked_[static_cast<std::size_t>(y) * cols + x]) last = y;
      above[y] = last;
    }
    int next = rows - 1;
    for (int y = rows - 1; y >= 0; --y) {
      const std::size_t i = static_cast<std::size_t>(y) * cols + x;
      if (blocked_[i]) next = y;
      const int up = y - above[y];
      const int down = next - y;
      const int row = up <= down ? above[y] : next;
      const std::int64_t dy = y - row;
      squared_[i] = dy * dy;
      nearest_[i] = row;
    }
  }

  // Row pass: lower envelope of the parabolas (x - u)^2 + g(u) (Meijster's phase 2, integer
  // separators), reading the column results of the row from copies.
  std::vector<std::int64_t> g(static_cast<std::size_t>(cols));
  std::vector<int> feature_row(static_cast<std::size_t>(cols));
  std::vector<int> s(static_cast<std::size_t>(cols));
  std::vector<int> t(static_cast<std::size_t>(cols));
  for (int y = 0; y < rows; ++y) {
    const std::size_t base = static_cast<std::size_t>(y) * cols;
    std::copy_n(squared_.begin() + base, cols, g.begin());
    std::copy_n(nearest_.begin() + base, cols, feature_row.begin());
    auto f = [&](std::int64_t x, int u) { return (x - u) * (x - u) + g[u]; };
    auto sep = [&](std::int64_t i, std::int64_t u) {
      return floor_div(u * u - i * i + g[u] - g[i], 2 * (u - i));
    };
    int q = 0;
    s[0] = 0;
    t[0] = 0;
    for (int u = 1; u < cols; ++u) {
      while (q >= 0 && f(t[q], s[q]) > f(t[q], u)) --q;
      if (q < 0) {
        q = 0;
        s[0] = u;
      } else {
        const std::int64_t w = 1 + sep(s[q], u);
        if (w < cols) {
          ++q;
          s[q] = u;
          t[q] = static_cast<int>(w);
        }
      }
    }
    for (int u = cols - 1; u >= 0; --u) {
      squared_[base + u] = f(u, s[q]);
      nearest_[base + u] = feature_row[s[q]] * cols + s[q];
      if (u == t[q]) --q;
    }
  }
}

double DistanceTransform::centre_distance(int x, int y) const {
  return std::sqrt(static_cast<double>(squared_centre_distance(x, y)));
}

double DistanceTransform::search(Point a, Point b, Candidate* cells, int count,
                                 double below) const {
  // No obstacle near any candidate can come closer than `below`: nothing to search.
  std::int64_t nearest = std::numeric_limits<std::int64_t>::max();
  for (int k = 0; k < count; ++k) nearest = std::min(nearest, cells[k].squared);
  if (count > 0 && std::sqrt(static_cast<double>(nearest)) - kSqrt2 >= below) return below;
  std::sort(cells, cells + count, [](const Candidate& l, const Candidate& r) {
    return l.squared != r.squared ? l.squared < r.squared : l.index < r.index;
  });
  const int rows = height_ + 2;
  double best = below;
  for (int k = 0; k < count; ++k) {
    const std::int64_t d2 = cells[k].squared;
    const int cx = cells[k].index % stride_;  // padded coordinates
    const int cy = cells[k].index / stride_;
    const int f = nearest_[cells[k].index];
    best = std::min(best, segment_cell_distance(a, b, Cell{f % stride_ - 1, f / stride_ - 1}));
    if (best == 0.0 || std::sqrt(static_cast<double>(d2)) - kSqrt2 >= best) break;
    const double reach = best + kSqrt2 + 1e-9;
    const auto r = static_cast<int>(std::floor(reach));
    const double reach2 = reach * reach;
    for (int dy = -r; dy <= r; ++dy) {
      const int oy = cy + dy;
      if (oy < 0 || oy >= rows) continue;
      const double rem = reach2 - static_cast<double>(dy) * dy;
      if (rem < 0.0) continue;
      const auto dx_max = static_cast<int>(std::floor(std::sqrt(rem)));
      const auto dx_min = static_cast<int>(ceil_sqrt(d2 - static_cast<std::int64_t>(dy) * dy));
      for (int dx = dx_min; dx <= dx_max; ++dx) {
        for (int sign = (dx == 0 ? 1 : -1); sign <= 1; sign += 2) {
          const int ox = cx + sign * dx;
          if (ox < 0 || ox >= stride_) continue;
          if (!blocked_[static_cast<std::size_t>(oy) * stride_ + ox]) continue;
          best = std::min(best, segment_cell_distance(a, b, Cell{ox - 1, oy - 1}));
        }
      }
    }
  }
  return best;
}

// An obstacle square closer than `below` to the segment meets its bounding box grown by `below`.
// When that box is small (a polyline's later segments, once its least clearance so far is
// tight), scanning it costs less than the candidate cells' sort and annuli; false when it is
// not small. The margins (one cell low, kBoxSlack high) only ever add squares, and a square
// whose box gap exceeds the best so far by kBoxSlack cannot beat it whatever the rounding: the
// result is the exact min(below, clearance) that search() gives.
bool DistanceTransform::box_search(Point a, Point b, double below, double& best) const {
  constexpr double kMaxReach = 4.0;
  constexpr int kMaxBoxCells = 36;
  constexpr double kBoxSlack = 1e-6;
  if (!(below < kMaxReach)) return false;
  const double min_x = std::min(a.x, b.x);
  const double max_x = std::max(a.x, b.x);
  const double min_y = std::min(a.y, b.y);
  const double max_y = std::max(a.y, b.y);
  const double reach = below + kBoxSlack;
  const int x0 = std::max(-1, static_cast<int>(std::floor(min_x - reach)) - 1);
  const int x1 = std::min(width_, static_cast<int>(std::floor(max_x + reach)));
  const int y0 = std::max(-1, static_cast<int>(std::floor(min_y - reach)) - 1);
  const int y1 = std::min(height_, static_cast<int>(std::floor(max_y + reach)));
  if ((x1 - x0 + 1) * (y1 - y0 + 1) > kMaxBoxCells) return false;
  best = below;
  for (int y = y0; y <= y1; ++y) {
    const std::uint8_t* row = blocked_.data() + static_cast<std::size_t>(index(0, y));
    const double gap_y = std::max({y - max_y, 0.0, min_y - (y + 1.0)});
    for (int x = x0; x <= x1; ++x) {
      if (!row[x]) continue;
      const double gap_x = std::max({x - max_x, 0.0, min_x - (x + 1.0)});
      if (std::max(gap_x, gap_y) > best + kBoxSlack) continue;
      best = std::min(best, segment_cell_distance(a, b, Cell{x, y}));
    }
  }
  return true;
}

double DistanceTransform::clearance(Point p) const { return segment_clearance(p, p); }

double DistanceTransform::segment_clearance(Point a, Point b, double below) const {
  if (!(below > 0.0)) return below;
  auto inside = [this](Point p) {
    return p.x >= 0.0 && p.y >= 0.0 && p.x <= width_ && p.y <= height_;
  };
  if (!inside(a) || !inside(b)) return 0.0;  // also catches NaN
  if (double best = below; box_search(a, b, below, best)) return best;
  // The closed cells meeting the segment, column by column (a little generous at cell
  // boundaries: an extra cell costs time, never correctness).
  constexpr double kEps = 1e-9;
  std::array<Candidate, 256> small;
  std::vector<Candidate> big;
  int count = 0;
  auto add = [&](int x, int y) {
    const Candidate c{squared_[index(x, y)], index(x, y)};
    if (count < static_cast<int>(small.size())) {
      small[count] = c;
    } else {
      if (big.empty()) big.assign(small.begin(), small.end());
      big.push_back(c);
    }
    ++count;
  };
  const double min_x = std::min(a.x, b.x);
  const double max_x = std::max(a.x, b.x);
  const int x_first = std::max(-1, static_cast<int>(std::ceil(min_x - kEps)) - 1);
  const int x_last = std::min(width_, static_cast<int>(std::floor(max_x + kEps)));
  for (int x = x_first; x <= x_last; ++x) {
    double y_lo = std::min(a.y, b.y);
    double y_hi = std::max(a.y, b.y);
    if (a.x != b.x) {
      const double lo = std::max(min_x, static_cast<double>(x));
      const double hi = std::min(max_x, x + 1.0);
      const double slope = (b.y - a.y) / (b.x - a.x);
      const double y0 = a.y + (lo - a.x) * slope;
      const double y1 = a.y + (hi - a.x) * slope;
      y_lo = std::min(y0, y1);
      y_hi = std::max(y0, y1);
    }
    const int y_first = std::max(-1, static_cast<int>(std::ceil(y_lo - kEps)) - 1);
    const int y_last = std::min(height_, static_cast<int>(std::floor(y_hi + kEps)));
    for (int y = y_first; y <= y_last; ++y) add(x, y);
  }
  Candidate* cells = big.empty() ? small.data() : big.data();
  return search(a, b, cells, count, below);
}

}  // namespace agv
