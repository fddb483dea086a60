// Exact statistics on known vectors. Expected numbers: by hand, or from the named R / Python
// computation (Python's `statistics` module: stdev is the n-1 form, quantiles(method=
// "inclusive") is R type 7; t quantiles are R's qt()).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include "engine/judge/statistics.h"

namespace agv {
namespace {

TEST(Statistics, CompensatedSumKeepsSmallTerms) {
  std::vector<double> v = {1e16, 1.0, -1e16, 1.0};
  EXPECT_EQ(compensated_sum(v), 2.0);  // naive left-to-right gives 1 (or 0)
  std::vector<double> tenths(1000, 0.1);
  EXPECT_EQ(compensated_sum(tenths), 100.0);
}

TEST(Statistics, SummaryOfKnownVector) {
  // x = 2 4 4 4 5 5 7 9: mean 5, sd sqrt(32/7) = 2.138089935299395; type 7 quantiles:
  // p5: h = 7 * 0.05 = 0.35 -> 2 + 0.35 * 2 = 2.7; median 4.5; p95: h = 6.65 -> 7 + 0.65 * 2 =
  // 8.3. ci95: 5 -+ qt(0.975, 7) * sd / sqrt(8), qt(0.975, 7) = 2.364624251592785 ->
  // [3.2125120817637898, 6.78748791823621].
  const std::vector<double> x = {5, 2, 4, 9, 4, 7, 4, 5};  // unsorted on purpose
  const Summary s = summarize(x);
  EXPECT_EQ(s.count, 8U);
  EXPECT_DOUBLE_EQ(s.mean, 5.0);
  EXPECT_NEAR(s.stddev, 2.138089935299395, 1e-14);
  EXPECT_EQ(s.min, 2.0);
  EXPECT_EQ(s.max, 9.0);
  EXPECT_NEAR(s.p5, 2.7, 1e-14);
  EXPECT_NEAR(s.median, 4.5, 1e-14);
  EXPECT_NEAR(s.p95, 8.3, 1e-14);
  EXPECT_NEAR(s.ci95.lo, 3.2125120817637898, 1e-9);
  EXPECT_NEAR(s.ci95.hi, 6.78748791823621, 1e-9);
}

TEST(Statistics, QuantileType7) {
  // numpy.percentile([1, 2, 3, 4], [0, 10, 50, 100]) = 1, 1.3, 2.5, 4.
  const std::vector<double> v = {1, 2, 3, 4};
  EXPECT_DOUBLE_EQ(quantile_sorted(v, 0.0), 1.0);
  EXPECT_NEAR(quantile_sorted(v, 0.1), 1.3, 1e-15);
  EXPECT_DOUBLE_EQ(quantile_sorted(v, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(quantile_sorted(v, 1.0), 4.0);
  EXPECT_TRUE(std::isnan(quantile_sorted({}, 0.5)));
}

TEST(Statistics, DegenerateSummaries) {
  const Summary none = summarize({});
  EXPECT_EQ(none.count, 0U);
  EXPECT_TRUE(std::isnan(none.mean));
  EXPECT_TRUE(std::isnan(none.median));
  EXPECT_FALSE(none.ci95.defined());

  const std::vector<double> one = {3.5};
  const Summary s1 = summarize(one);
  EXPECT_EQ(s1.count, 1U);
  EXPECT_EQ(s1.mean, 3.5);
  EXPECT_EQ(s1.min, 3.5);
  EXPECT_EQ(s1.p5, 3.5);
  EXPECT_EQ(s1.p95, 3.5);
  EXPECT_TRUE(std::isnan(s1.stddev));
  EXPECT_FALSE(s1.ci95.defined());

  const std::vector<double> same(5, 0.1);
  const Summary s = summarize(same);
  EXPECT_DOUBLE_EQ(s.mean, 0.1);
  EXPECT_EQ(s.stddev, 0.0);
  EXPECT_DOUBLE_EQ(s.ci95.lo, 0.1);
  EXPECT_DOUBLE_EQ(s.ci95.hi, 0.1);
}

TEST(Statistics, MeanIntervalByHand) {
  // x = 1 2 3: mean 2, sd 1, qt(0.975, 2) = 4.302652729911275: 2 -+ 4.302652729911275 / sqrt(3).
  const std::vector<double> x = {1, 2, 3};
  const Interval i = mean_interval(x);
  EXPECT_NEAR(i.lo, 2.0 - 4.302652729911275 / std::sqrt(3.0), 1e-9);
  EXPECT_NEAR(i.hi, 2.0 + 4.302652729911275 / std::sqrt(3.0), 1e-9);
}

TEST(Statistics, WilsonInterval) {
  // 8/10 at 95%: [0.4902, 0.9433] (e.g. R binom::binom.wilson); full digits from the formula
  // with z = 1.959963984540054.
  Interval i = wilson_interval(8, 10);
  EXPECT_NEAR(i.lo, 0.49016247153664183, 1e-9);
  EXPECT_NEAR(i.hi, 0.9433178485456247, 1e-9);
  i = wilson_interval(0, 10);
  EXPECT_NEAR(i.lo, 0.0, 1e-12);
  EXPECT_NEAR(i.hi, 0.27753279986288915, 1e-9);
  i = wilson_interval(10, 10);
  EXPECT_NEAR(i.lo, 0.7224672001371109, 1e-9);
  EXPECT_NEAR(i.hi, 1.0, 1e-12);
  i = wilson_interval(37, 120);
  EXPECT_NEAR(i.lo, 0.23272736988916304, 1e-9);
  EXPECT_NEAR(i.hi, 0.3958299772380068, 1e-9);
  EXPECT_FALSE(wilson_interval(0, 0).defined());
}

// R's ?wilcox.test example (Hollander & Wolfe, depression scale).
const std::vector<double> kX = {1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30};
const std::vector<double> kY = {0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29};

std::vector<double> minus(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> d;
  for (std::size_t i = 0; i < a.size(); ++i) d.push_back(a[i] - b[i]);
  return d;
}

TEST(Statistics, WilcoxonExactMatchesR) {
  // R: wilcox.test(x, y, paired = TRUE) -> V = 40, p-value = 0.03906 (= 2 * 10 / 512).
  const WilcoxonResult w = wilcoxon_signed_rank(minus(kX, kY));
  EXPECT_TRUE(w.exact);
  EXPECT_EQ(w.n, 9U);
  EXPECT_EQ(w.v, 40.0);
  EXPECT_NEAR(w.p, 20.0 / 512.0, 1e-15);
  // Swapping the arguments mirrors V and keeps p.
  const WilcoxonResult m = wilcoxon_signed_rank(minus(kY, kX));
  EXPECT_EQ(m.v, 5.0);
  EXPECT_NEAR(m.p, 20.0 / 512.0, 1e-15);
  // Five positive differences: R gives p-value = 0.0625 (= 2 / 32).
  const WilcoxonResult five = wilcoxon_signed_rank(std::vector<double>{1, 2, 3, 4, 5});
  EXPECT_EQ(five.v, 15.0);
  EXPECT_NEAR(five.p, 0.0625, 1e-15);
  // Balanced: p capped at 1.
  EXPECT_EQ(wilcoxon_signed_rank(std::vector<double>{1, -2, -3, 4}).p, 1.0);
}

// Independent of the dynamic programme: every one of the 2^n sign assignments of the mid-ranks
// (zeros dropped), counted when |V - n(n+1)/4| is at least the observed one.
double brute_force_p(const std::vector<double>& differences) {
  std::vector<double> d;
  for (double x : differences)
    if (x != 0.0) d.push_back(x);
  std::sort(d.begin(), d.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
  const std::size_t n = d.size();
  std::vector<double> rank(n);
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    while (j < n && std::abs(d[j]) == std::abs(d[i])) ++j;
    for (std::size_t k = i; k < j; ++k) rank[k] = (static_cast<double>(i + j) + 1.0) / 2.0;
    i = j;
  }
  double v = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    if (d[k] > 0) v += rank[k];
  const double centre = static_cast<double>(n * (n + 1)) / 4.0;
  std::uint64_t extreme = 0;
  for (std::uint64_t signs = 0; signs < (std::uint64_t{1} << n); ++signs) {
    double s = 0.0;
    for (std::size_t k = 0; k < n; ++k)
      if (signs >> k & 1U) s += rank[k];
    if (std::abs(s - centre) >= std::abs(v - centre) - 1e-9) ++extreme;
  }
  return std::ldexp(static_cast<double>(extreme), -static_cast<int>(n));
}

TEST(Statistics, WilcoxonExactWithTiesAndZeros) {
  // Zeros are dropped before ranking, so a zero pair no longer forces the normal
  // approximation: the example data plus one zero is the example's exact p, 20 / 512 (the
  // normal approximation gave 0.04401098).
  std::vector<double> d = minus(kX, kY);
  d.push_back(0.0);
  const WilcoxonResult w = wilcoxon_signed_rank(d);
  EXPECT_TRUE(w.exact);
  EXPECT_EQ(w.n, 9U);
  EXPECT_EQ(w.v, 40.0);
  EXPECT_NEAR(w.p, 20.0 / 512.0, 1e-15);

  // Ties and a zero: d = 1 2 2 3 -1 4 4 4 -2 5 0 6 -3. n = 12; sorted |d| 1 1 2 2 2 3 3 4 4 4
  // 5 6 get mid-ranks 1.5 4 6.5 9 11 12; V = 1.5 + 4 + 4 + 6.5 + 3 * 9 + 11 + 12 = 66. The
  // exact conditional p is 138 / 4096 (enumerated by hand-written Python over the 4096 sign
  // sets); R's normal approximation gives 0.0368996.
  const std::vector<double> tied = {1, 2, 2, 3, -1, 4, 4, 4, -2, 5, 0, 6, -3};
  const WilcoxonResult t = wilcoxon_signed_rank(tied);
  EXPECT_TRUE(t.exact);
  EXPECT_EQ(t.n, 12U);
  EXPECT_EQ(t.v, 66.0);
  EXPECT_EQ(t.p, 138.0 / 4096.0);
  EXPECT_EQ(t.p, brute_force_p(tied));

  // Issue 14's kind of case: 13 non-zero integer differences (turn counts), heavily tied,
  // among many tied pairs. V = 73; the normal approximation says 0.04256 (significant), the
  // exact distribution 490 / 8192 = 0.0598 (not).
  std::vector<double> turns = {-1, -1, -1, 1, 1, 1, 1, 1, 1, 1, 1, 2, 3};
  turns.insert(turns.end(), 7, 0.0);
  const WilcoxonResult e = wilcoxon_signed_rank(turns);
  EXPECT_TRUE(e.exact);
  EXPECT_EQ(e.n, 13U);
  EXPECT_EQ(e.v, 73.0);
  EXPECT_EQ(e.p, 490.0 / 8192.0);
  EXPECT_EQ(e.p, brute_force_p(turns));

  // Random integer differences (many ties and zeros) against the enumeration.
  std::mt19937_64 rng(14);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> r(1 + rng() % 16);
    for (double& x : r) x = static_cast<double>(static_cast<int>(rng() % 9) - 3);
    const WilcoxonResult x = wilcoxon_signed_rank(r);
    if (x.n == 0) {
      EXPECT_TRUE(std::isnan(x.p));
      continue;
    }
    EXPECT_TRUE(x.exact);
    EXPECT_NEAR(x.p, brute_force_p(r), 1e-15) << "trial " << trial;
  }

  // The exact range ends at kWilcoxonExactMaxN non-zero differences.
  std::vector<double> edge;
  for (std::size_t i = 0; i < kWilcoxonExactMaxN; ++i) edge.push_back(i % 3 == 0 ? -1.0 : 2.0);
  EXPECT_TRUE(wilcoxon_signed_rank(edge).exact);
  edge.push_back(1.0);
  EXPECT_FALSE(wilcoxon_signed_rank(edge).exact);
}

TEST(Statistics, WilcoxonNormalApproximation) {
  // n = 60 without ties: above kWilcoxonExactMaxN, the normal approximation; V = 1228,
  // p = 0.0214199 by R's formula (continuity correction, as wilcox.test(exact = FALSE)).
  std::vector<double> big;
  for (int i = 0; i < 60; ++i) big.push_back(((i * 37) % 101 - 40) + 0.001 * i);
  const WilcoxonResult b = wilcoxon_signed_rank(big);
  EXPECT_FALSE(b.exact);
  EXPECT_EQ(b.v, 1228.0);
  EXPECT_NEAR(b.p, 0.021419856207744115, 1e-9);

  // Ties and zeros above the exact range: d_i = (7 i mod 11) - 4, i < 70: 6 zeros dropped,
  // n = 64, V = 1407; sigma^2 = n(n+1)(2n+1)/24 - sum(t^3 - t)/48 -> p = 0.0138513 (the same
  // formula in Python).
  std::vector<double> tied;
  for (int i = 0; i < 70; ++i) tied.push_back((i * 7) % 11 - 4);
  const WilcoxonResult t = wilcoxon_signed_rank(tied);
  EXPECT_FALSE(t.exact);
  EXPECT_EQ(t.n, 64U);
  EXPECT_EQ(t.v, 1407.0);
  EXPECT_NEAR(t.p, 0.013851297834244672, 1e-9);

  EXPECT_TRUE(std::isnan(wilcoxon_signed_rank(std::vector<double>{0, 0}).p));
}

TEST(Statistics, PairedComparisonCountsAndGeometricMean) {
  // Ratios 0.5, 1, 2: geometric mean 1; log ratios -ln2, 0, ln2, sd ln2, qt(0.975, 2) =
  // 4.302652729911275 -> exp(-+4.302652729911275 * ln2 / sqrt(3)) = [0.178731, 5.594998].
  const std::vector<double> c = {1, 2, 4};
  const std::vector<double> b = {2, 2, 2};
  const PairedComparison p = compare_paired(c, b);
  EXPECT_EQ(p.pairs, 3U);
  EXPECT_EQ(p.wins, 1U);
  EXPECT_EQ(p.ties, 1U);
  EXPECT_EQ(p.losses, 1U);
  EXPECT_EQ(p.ratio_count, 3U);
  EXPECT_NEAR(p.geo_mean_ratio, 1.0, 1e-15);
  EXPECT_NEAR(p.geo_mean_ci95.lo, 0.17873106178316348, 1e-9);
  EXPECT_NEAR(p.geo_mean_ci95.hi, 5.5949983736637785, 1e-9);
  // The tie is a zero difference: dropped, leaving d = -1, +2: V = 2; exact: of the four sign
  // sets, V in {0, 1, 2, 3}, |V - 1.5| >= 0.5 always: p = 1.
  EXPECT_EQ(p.wilcoxon.n, 2U);
  EXPECT_EQ(p.wilcoxon.v, 2.0);
  EXPECT_TRUE(p.wilcoxon.exact);
  EXPECT_EQ(p.wilcoxon.p, 1.0);
  // Differences 1 - 2, 0, 2: mean 1/3, sd sqrt(7/3) (by hand).
  EXPECT_NEAR(p.mean_difference, 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(p.mean_difference_ci95.hi - p.mean_difference,
              4.302652729911275 * std::sqrt(7.0 / 3.0) / std::sqrt(3.0), 1e-9);
}

TEST(Statistics, PairedComparisonMissingZerosAndTolerance) {
  const double nan = kNaN;
  // NaN = a failed run: the pair is skipped. (0,0): ratio 1, a tie. (0,3): a win with no log
  // ratio; (2,0): a loss with no log ratio. 1 vs 1 + 1e-12: a tie within the tolerance.
  const std::vector<double> c = {nan, 0, 0, 2, 1 + 1e-12, 3, 5};
  const std::vector<double> b = {1, 0, 3, 0, 1, nan, 4};
  const PairedComparison p = compare_paired(c, b, Better::smaller, RatioKind::plain, 1e-9);
  EXPECT_EQ(p.pairs, 5U);
  EXPECT_EQ(p.wins, 1U);
  EXPECT_EQ(p.ties, 2U);
  EXPECT_EQ(p.losses, 2U);
  EXPECT_EQ(p.ratio_count, 3U);  // (0,0), (1+1e-12,1), (5,4)
  EXPECT_EQ(p.ratio_excluded, 2U);
  EXPECT_NEAR(p.geo_mean_ratio, std::cbrt(1.25), 1e-12);
  EXPECT_EQ(p.wilcoxon.n, 3U);

  // Degenerate: no pairs, one pair, all ratios equal.
  const PairedComparison none = compare_paired(std::vector<double>{nan}, std::vector<double>{1});
  EXPECT_EQ(none.pairs, 0U);
  EXPECT_TRUE(std::isnan(none.geo_mean_ratio));
  EXPECT_FALSE(none.geo_mean_ci95.defined());
  EXPECT_TRUE(std::isnan(none.wilcoxon.p));
  const PairedComparison one = compare_paired(std::vector<double>{2}, std::vector<double>{4});
  EXPECT_DOUBLE_EQ(one.geo_mean_ratio, 0.5);
  EXPECT_FALSE(one.geo_mean_ci95.defined());
  const PairedComparison flat =
      compare_paired(std::vector<double>{2, 3, 5}, std::vector<double>{4, 6, 10});
  EXPECT_DOUBLE_EQ(flat.geo_mean_ratio, 0.5);
  EXPECT_DOUBLE_EQ(flat.geo_mean_ci95.lo, 0.5);
  EXPECT_DOUBLE_EQ(flat.geo_mean_ci95.hi, 0.5);

  EXPECT_THROW(compare_paired(std::vector<double>{1}, std::vector<double>{1, 2}),
               std::invalid_argument);
}

TEST(Statistics, PairedComparisonFollowsTheMetricDirection) {
  // Clearance: larger is better, so a larger candidate wins.
  const std::vector<double> c = {1.0, 0.5, 2.0, 2.0};
  const std::vector<double> b = {0.5, 1.0, 1.0, 2.0};
  const PairedComparison larger = compare_paired(c, b, Better::larger);
  EXPECT_EQ(larger.wins, 2U);
  EXPECT_EQ(larger.losses, 1U);
  EXPECT_EQ(larger.ties, 1U);
  const PairedComparison smaller = compare_paired(c, b, Better::smaller);
  EXPECT_EQ(smaller.wins, 1U);
  EXPECT_EQ(smaller.losses, 2U);
  // The ratio, the difference and the (two-sided) test do not depend on the direction.
  EXPECT_EQ(larger.geo_mean_ratio, smaller.geo_mean_ratio);
  EXPECT_EQ(larger.mean_difference, smaller.mean_difference);
  EXPECT_EQ(larger.wilcoxon.p, smaller.wilcoxon.p);
}

TEST(Statistics, ShiftedRatioKeepsZeroCounts) {
  // Turn counts with zeros on both sides: the plain ratio loses every pair with one zero side,
  // exactly the most extreme maps; the shifted (c + 1) / (b + 1) keeps them all.
  const std::vector<double> c = {3, 2, 0, 4, 1};
  const std::vector<double> b = {0, 0, 0, 1, 1};
  const PairedComparison plain = compare_paired(c, b, Better::smaller, RatioKind::plain);
  EXPECT_EQ(plain.pairs, 5U);
  EXPECT_EQ(plain.ratio_count, 3U);  // (0,0) = 1, 4/1, 1/1
  EXPECT_EQ(plain.ratio_excluded, 2U);
  EXPECT_NEAR(plain.geo_mean_ratio, std::cbrt(4.0), 1e-12);
  const PairedComparison shifted = compare_paired(c, b, Better::smaller, RatioKind::shifted);
  EXPECT_EQ(shifted.ratio_count, 5U);
  EXPECT_EQ(shifted.ratio_excluded, 0U);
  // (4/1 * 3/1 * 1/1 * 5/2 * 2/2) ^ (1/5) = 30^(1/5).
  EXPECT_NEAR(shifted.geo_mean_ratio, std::pow(30.0, 0.2), 1e-12);
  // The difference uses every pair: (3 + 2 + 0 + 3 + 0) / 5.
  EXPECT_NEAR(shifted.mean_difference, 1.6, 1e-15);
  EXPECT_TRUE(shifted.mean_difference_ci95.defined());
  EXPECT_EQ(shifted.wins, 0U);
  EXPECT_EQ(shifted.ties, 2U);
  EXPECT_EQ(shifted.losses, 3U);
}

}  // namespace
}  // namespace agv
