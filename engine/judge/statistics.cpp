#include "engine/judge/statistics.h"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace agv {

void CompensatedSum::add(double x) {
  const double t = sum_ + x;
  // Neumaier: recover the low-order bits of whichever operand was smaller.
  compensation_ += std::abs(sum_) >= std::abs(x) ? (sum_ - t) + x : (x - t) + sum_;
  sum_ = t;
}

double compensated_sum(std::span<const double> values) {
  CompensatedSum s;
  for (double x : values) s.add(x);
  return s.value();
}

namespace {

struct MeanSd {
  double mean = kNaN;
  double sd = kNaN;
};

// Two passes: the mean, then the compensated sum of squared deviations (no cancellation).
MeanSd mean_sd(std::span<const double> values) {
  const std::size_t n = values.size();
  MeanSd r;
  if (n == 0) return r;
  r.mean = compensated_sum(values) / static_cast<double>(n);
  if (n < 2) return r;
  CompensatedSum ss;
  for (double x : values) ss.add((x - r.mean) * (x - r.mean));
  r.sd = std::sqrt(ss.value() / static_cast<double>(n - 1));
  return r;
}

double t_quantile(double p, std::size_t df) {
  const boost::math::students_t_distribution<double> t(static_cast<double>(df));
  return boost::math::quantile(t, p);
}

Interval t_interval(const MeanSd& m, std::size_t n, double confidence) {
  if (n < 2 || !std::isfinite(m.sd)) return {};
  const double half =
      t_quantile(1.0 - (1.0 - confidence) / 2.0, n - 1) * m.sd / std::sqrt(static_cast<double>(n));
  return {m.mean - half, m.mean + half};
}

}  // namespace

double quantile_sorted(std::span<const double> sorted, double p) {
  if (sorted.empty()) return kNaN;
  const double h = static_cast<double>(sorted.size() - 1) * std::clamp(p, 0.0, 1.0);
  const auto lo = static_cast<std::size_t>(std::floor(h));
  if (lo + 1 >= sorted.size()) return sorted.back();
  const double frac = h - static_cast<double>(lo);
  return sorted[lo] + frac * (sorted[lo + 1] - sorted[lo]);
}

Interval mean_interval(std::span<const double> values, double confidence) {
  return t_interval(mean_sd(values), values.size(), confidence);
}

Summary summarize(std::span<const double> values) {
  Summary s;
  s.count = values.size();
  if (values.empty()) return s;
  const MeanSd m = mean_sd(values);
  s.mean = m.mean;
  s.stddev = m.sd;
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  s.min = sorted.front();
  s.max = sorted.back();
  s.p5 = quantile_sorted(sorted, 0.05);
  s.median = quantile_sorted(sorted, 0.5);
  s.p95 = quantile_sorted(sorted, 0.95);
  s.ci95 = t_interval(m, values.size(), 0.95);
  return s;
}

Interval wilson_interval(std::int64_t successes, std::int64_t n, double confidence) {
  if (n <= 0) return {};
  const boost::math::normal_distribution<double> normal;
  const double z = boost::math::quantile(normal, 1.0 - (1.0 - confidence) / 2.0);
  const double nn = static_cast<double>(n);
  const double p = static_cast<double>(successes) / nn;
  const double z2n = z * z / nn;
  const double centre = (p + z2n / 2.0) / (1.0 + z2n);
  const double half = z / (1.0 + z2n) * std::sqrt(p * (1.0 - p) / nn + z2n / (4.0 * nn));
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

WilcoxonResult wilcoxon_signed_rank(std::span<const double> differences,
                                    double rank_tie_tolerance) {
  WilcoxonResult r;
  struct Signed {
    double abs;
    bool positive;
  };
  std::vector<Signed> d;
  d.reserve(differences.size());
  for (double x : differences)
    if (x != 0.0) d.push_back({std::abs(x), x > 0.0});  // zeros dropped
  const std::size_t n = d.size();
  r.n = n;
  if (n == 0) return r;
  std::stable_sort(d.begin(), d.end(),
                   [](const Signed& a, const Signed& b) { return a.abs < b.abs; });

  // Doubled mid-ranks (i + 1 + j for the group [i, j), an integer), V and the tie correction
  // sum(t^3 - t) in one pass.
  std::vector<std::size_t> doubled(n);
  std::size_t doubled_v = 0;
  double tie_term = 0.0;
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i + 1;
    while (j < n && d[j].abs - d[j - 1].abs <= rank_tie_tolerance * d[j].abs) ++j;
    for (std::size_t k = i; k < j; ++k) {
      doubled[k] = i + 1 + j;
      if (d[k].positive) doubled_v += doubled[k];
    }
    const double t = static_cast<double>(j - i);
    tie_term += t * t * t - t;
    i = j;
  }
  r.v = static_cast<double>(doubled_v) / 2.0;
  const double nn = static_cast<double>(n);

  if (n <= kWilcoxonExactMaxN) {
    // count[s]: sign assignments whose positive doubled ranks sum to s. The doubled ranks sum
    // to n(n+1), so the distribution is symmetric about n(n+1)/2. Counts stay below 2^50,
    // exact in a double.
    r.exact = true;
    const std::size_t total = n * (n + 1);
    std::vector<double> count(total + 1, 0.0);
    count[0] = 1.0;
    std::size_t reach = 0;
    for (std::size_t k = 0; k < n; ++k) {
      reach += doubled[k];
      for (std::size_t s = reach; s >= doubled[k]; --s) count[s] += count[s - doubled[k]];
    }
    // Both tails: |2 V' - total| >= |2 v - total| (integers, so no rounding question).
    const std::size_t deviation = doubled_v >= total - doubled_v ? doubled_v - (total - doubled_v)
                                                                 : (total - doubled_v) - doubled_v;
    CompensatedSum tail;
    for (std::size_t s = 0; s <= total; ++s) {
      const std::size_t dev = s >= total - s ? s - (total - s) : (total - s) - s;
      if (dev >= deviation) tail.add(count[s]);
    }
    r.p = std::min(1.0, std::ldexp(tail.value(), -static_cast<int>(n)));
    return r;
  }

  const double centre = nn * (nn + 1.0) / 4.0;
  const double sigma = std::sqrt(nn * (nn + 1.0) * (2.0 * nn + 1.0) / 24.0 - tie_term / 48.0);
  double z = r.v - centre;
  const double correction = z > 0.0 ? 0.5 : z < 0.0 ? -0.5 : 0.0;
  z = (z - correction) / sigma;
  const boost::math::normal_distribution<double> normal;
  const double lower = boost::math::cdf(normal, z);
  const double upper = boost::math::cdf(boost::math::complement(normal, z));
  r.p = std::min(1.0, 2.0 * std::min(lower, upper));
  return r;
}

MannWhitneyResult mann_whitney_u(std::span<const double> x, std::span<const double> y) {
  MannWhitneyResult r;
  r.nx = x.size();
  r.ny = y.size();
  if (x.empty() || y.empty()) return r;
  struct Value {
    double v;
    bool from_x;
  };
  std::vector<Value> all;
  all.reserve(x.size() + y.size());
  for (double v : x) all.push_back({v, true});
  for (double v : y) all.push_back({v, false});
  std::stable_sort(all.begin(), all.end(),
                   [](const Value& a, const Value& b) { return a.v < b.v; });
  const std::size_t n = all.size();
  CompensatedSum rank_sum_x;
  double tie_term = 0.0;
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i + 1;
    while (j < n && all[j].v == all[i].v) ++j;
    const double mid_rank = (static_cast<double>(i + 1) + static_cast<double>(j)) / 2.0;
    for (std::size_t k = i; k < j; ++k)
      if (all[k].from_x) rank_sum_x.add(mid_rank);
    const double t = static_cast<double>(j - i);
    tie_term += t * t * t - t;
    i = j;
  }
  const double nx = static_cast<double>(r.nx), ny = static_cast<double>(r.ny);
  const double nn = nx + ny;
  r.u = rank_sum_x.value() - nx * (nx + 1.0) / 2.0;
  const double variance = nx * ny / 12.0 * ((nn + 1.0) - tie_term / (nn * (nn - 1.0)));
  if (!(variance > 0.0)) {
    r.p = 1.0;  // every value tied: no evidence either way
    return r;
  }
  double z = r.u - nx * ny / 2.0;
  const double correction = z > 0.0 ? 0.5 : z < 0.0 ? -0.5 : 0.0;
  z = (z - correction) / std::sqrt(variance);
  const boost::math::normal_distribution<double> normal;
  const double lower = boost::math::cdf(normal, z);
  const double upper = boost::math::cdf(boost::math::complement(normal, z));
  r.p = std::min(1.0, 2.0 * std::min(lower, upper));
  return r;
}

PairedComparison compare_paired(std::span<const double> candidate, std::span<const double> baseline,
                                Better better, RatioKind ratio, double tie_tolerance) {
  if (candidate.size() != baseline.size())
    throw std::invalid_argument("compare_paired: candidate and baseline differ in length");
  const double shift = ratio == RatioKind::shifted ? 1.0 : 0.0;
  PairedComparison r;
  std::vector<double> differences;  // tied pairs as 0, for the Wilcoxon test
  std::vector<double> raw;          // c - b, for the mean difference
  std::vector<double> logs;
  differences.reserve(candidate.size());
  raw.reserve(candidate.size());
  logs.reserve(candidate.size());
  for (std::size_t i = 0; i < candidate.size(); ++i) {
    const double c = candidate[i];
    const double b = baseline[i];
    if (std::isnan(c) || std::isnan(b)) continue;
    ++r.pairs;
    const bool tie = std::abs(c - b) <= tie_tolerance * std::max(std::abs(c), std::abs(b));
    if (tie) {
      ++r.ties;
    } else if ((c < b) == (better == Better::smaller)) {
      ++r.wins;
    } else {
      ++r.losses;
    }
    differences.push_back(tie ? 0.0 : c - b);
    raw.push_back(c - b);
    const double cs = c + shift;
    const double bs = b + shift;
    if (cs > 0.0 && bs > 0.0) {
      logs.push_back(std::log(cs / bs));
    } else if (cs == 0.0 && bs == 0.0) {
      logs.push_back(0.0);
    } else {
      ++r.ratio_excluded;
    }
  }
  r.ratio_count = logs.size();
  if (!logs.empty()) {
    const MeanSd m = mean_sd(logs);
    r.geo_mean_ratio = std::exp(m.mean);
    const Interval li = t_interval(m, logs.size(), 0.95);
    if (li.defined()) r.geo_mean_ci95 = {std::exp(li.lo), std::exp(li.hi)};
  }
  const MeanSd md = mean_sd(raw);
  r.mean_difference = md.mean;
  r.mean_difference_ci95 = t_interval(md, raw.size(), 0.95);
  r.wilcoxon = wilcoxon_signed_rank(differences, tie_tolerance);
  return r;
}

}  // namespace agv
