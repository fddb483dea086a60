#pragma once
// Exact statistics over per-run scalars kept in task order (docs/METRICS.md "Aggregation"). Every
// function reads its input in the order given and sums with Neumaier's compensated summation,
// so a report is identical whatever the thread count that produced the values.
//
// Undefined results are NaN (the report writer prints them as null): see each function.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

namespace agv {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Neumaier's variant of Kahan summation: error independent of n for ordinary data.
class CompensatedSum {
 public:
  void add(double x);
  double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0.0;
  double compensation_ = 0.0;
};
double compensated_sum(std::span<const double> values);

struct Interval {
  double lo = kNaN;
  double hi = kNaN;
  bool defined() const { return lo == lo && hi == hi; }
};

// Quantile of SORTED values, R type 7 / numpy "linear" / Python "inclusive": h = (n-1) p,
// x[floor h] + (h - floor h) (x[floor h + 1] - x[floor h]). NaN when empty.
double quantile_sorted(std::span<const double> sorted, double p);

// Student t interval of the mean: mean +- t(1 - (1-confidence)/2, n-1) * sd / sqrt(n).
// NaN for n < 2; [mean, mean] when every value is equal.
Interval mean_interval(std::span<const double> values, double confidence = 0.95);

struct Summary {
  std::size_t count = 0;
  double mean = kNaN;
  double stddev = kNaN;  // sample (n - 1)
  double min = kNaN;
  double p5 = kNaN;  // quantiles: type 7 (quantile_sorted)
  double median = kNaN;
  double p95 = kNaN;
  double max = kNaN;
  Interval ci95;  // of the mean (mean_interval)
};

// Precondition: no NaN in values (the caller passes metrics of successful runs).
// n = 0: count 0, everything else NaN. n = 1: mean, min, quantiles and max = the value;
// stddev and ci95 NaN. All values equal: stddev 0, ci95 = [mean, mean].
Summary summarize(std::span<const double> values);

// Wilson score interval of a proportion, z from the normal quantile. NaN for n = 0.
Interval wilson_interval(std::int64_t successes, std::int64_t n, double confidence = 0.95);

// Two-sided Wilcoxon signed-rank test on paired differences (docs/METRICS.md "Statistics
// conventions", reports/SCHEMA.md):
// - zero differences are dropped (Wilcoxon's convention, R's default; not Pratt's);
// - |d| are ranked with mid-ranks for ties; in sorted order a value within
//   rank_tie_tolerance * (its magnitude) of the previous one joins its tie group (0 = exact);
// - n <= kWilcoxonExactMaxN: the exact null distribution of V GIVEN those mid-ranks, each sign
//   +-1 with probability 1/2, enumerated by dynamic programming over doubled ranks (integers),
//   also with ties and after zeros were dropped; p = P(|V - n(n+1)/4| >= |v - n(n+1)/4|), which is
//   R's 2 min(P(V <= v), P(V >= v)) capped at 1 (the distribution is symmetric);
// - above: the normal approximation with tie correction
//   sigma^2 = n(n+1)(2n+1)/24 - sum(t^3 - t)/48 and continuity correction 0.5.
// n = 0: v 0, p NaN. Precondition: no NaN.
inline constexpr std::size_t kWilcoxonExactMaxN = 50;
struct WilcoxonResult {
  std::size_t n = 0;  // non-zero differences used
  double v = 0.0;     // R's V: sum of the ranks of the positive differences
  double p = kNaN;
  bool exact = false;
};
WilcoxonResult wilcoxon_signed_rank(std::span<const double> differences,
                                    double rank_tie_tolerance = 0.0);

// Two-sided Mann-Whitney U (Wilcoxon rank-sum) test of two independent samples: U = the rank
// sum of x minus nx(nx+1)/2, mid-ranks for ties, p from the normal approximation with tie
// correction sigma^2 = nx ny / 12 ((n + 1) - sum(t^3 - t) / (n (n - 1))) and continuity
// correction 0.5 (R's wilcox.test(x, y, exact = FALSE, correct = TRUE)). p NaN when either
// sample is empty; 1 when every value is tied. Precondition: no NaN.
struct MannWhitneyResult {
  std::size_t nx = 0;
  std::size_t ny = 0;
  double u = 0.0;  // R's W
  double p = kNaN;
};
MannWhitneyResult mann_whitney_u(std::span<const double> x, std::span<const double> y);

// Which way a metric improves (docs/METRICS.md "Metric directions").
enum class Better { smaller, larger };

// How a paired comparison forms its per-map ratio (docs/METRICS.md "Statistics conventions"):
// plain c / b for metrics that are positive on every sensible path (lengths, times), or the
// shifted (c + 1) / (b + 1) for counts, which are 0 on many maps (a straight path has 0 turns)
// and would otherwise leave exactly the most extreme maps out of the ratio.
enum class RatioKind { plain, shifted };

struct PairedComparison {
  std::size_t pairs = 0;  // positions where neither value is NaN (both runs succeeded)
  // Win = candidate better in the metric's direction. Tie when
  // |c - b| <= tie_tolerance * max(|c|, |b|).
  std::size_t wins = 0;
  std::size_t ties = 0;
  std::size_t losses = 0;
  // Geometric mean of the per-pair ratio (RatioKind) over the pairs where it has a finite
  // logarithm; both sides 0 count as ratio 1. A plain ratio with exactly one side 0, or any
  // ratio with a non-positive side, has none: such pairs are counted in ratio_excluded, never
  // silently lost. Interval: t interval of the mean log ratio, exponentiated (NaN for fewer
  // than 2 ratios; geo_mean NaN for none).
  std::size_t ratio_count = 0;
  std::size_t ratio_excluded = 0;
  double geo_mean_ratio = kNaN;
  Interval geo_mean_ci95;
  // Mean of d = candidate - baseline over every pair (no pair is dropped), with its t interval
  // (NaN for fewer than 2 pairs; NaN mean for none).
  double mean_difference = kNaN;
  Interval mean_difference_ci95;
  // On d, with tied pairs (as above) as zeros and the same tolerance for tied ranks.
  WilcoxonResult wilcoxon;
};

// candidate and baseline must have the same length, aligned by task; NaN marks a missing run.
// Throws std::invalid_argument on a length mismatch.
PairedComparison compare_paired(std::span<const double> candidate, std::span<const double> baseline,
                                Better better = Better::smaller, RatioKind ratio = RatioKind::plain,
                                double tie_tolerance = 1e-9);

}  // namespace agv
