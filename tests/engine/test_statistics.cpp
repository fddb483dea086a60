// Exact statistics on known vectors. Expected numbers: by hand, or from the named R / Python
// computation (Python's `statistics` module: stdev is the n-1 form, quantiles(method=
// "inclusive") is R type 7; t quantiles are R's qt()).

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "engine/statistics.h"

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

TEST(Statistics, WilcoxonNormalApproximation) {
  // A zero forces R's normal approximation (wilcox.test's code: exact only without ties and
  // zeros). The example data plus one zero pair: V = 40, n = 9, sigma = sqrt(9*10*19/24),
  // z = (40 - 22.5 - 0.5) / sigma -> p = 2 * (1 - pnorm(z)) = 0.04401098 (what
  // wilcox.test(x, y, paired = TRUE, exact = FALSE) computes).
  std::vector<double> d = minus(kX, kY);
  d.push_back(0.0);
  const WilcoxonResult w = wilcoxon_signed_rank(d);
  EXPECT_FALSE(w.exact);
  EXPECT_EQ(w.n, 9U);
  EXPECT_EQ(w.v, 40.0);
  EXPECT_NEAR(w.p, 0.04401098401295145, 1e-9);

  // Ties and a zero: d = 1 2 2 3 -1 4 4 4 -2 5 0 6 -3. n = 12; sorted |d| 1 1 2 2 2 3 3 4 4 4
  // 5 6 get mid-ranks 1.5 4 6.5 9 11 12; V = 1.5 + 4 + 4 + 6.5 + 3 * 9 + 11 + 12 = 66;
  // sigma^2 = 12*13*25/24 - (6 + 24 + 6 + 24) / 48 = 161.25; z = (66 - 39 - 0.5) / sigma ->
  // p = 0.0368996 (R's formula, as wilcox.test(d) applies it).
  const WilcoxonResult t =
      wilcoxon_signed_rank(std::vector<double>{1, 2, 2, 3, -1, 4, 4, 4, -2, 5, 0, 6, -3});
  EXPECT_FALSE(t.exact);
  EXPECT_EQ(t.n, 12U);
  EXPECT_EQ(t.v, 66.0);
  EXPECT_NEAR(t.p, 0.036899619555973207, 1e-9);

  // n = 60 without ties: normal approximation (R uses it from n = 50); V = 1228,
  // p = 0.0214199 by the same formula.
  std::vector<double> big;
  for (int i = 0; i < 60; ++i) big.push_back(((i * 37) % 101 - 40) + 0.001 * i);
  const WilcoxonResult b = wilcoxon_signed_rank(big);
  EXPECT_FALSE(b.exact);
  EXPECT_EQ(b.v, 1228.0);
  EXPECT_NEAR(b.p, 0.021419856207744115, 1e-9);

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
  // The tie is a zero difference: dropped, leaving d = -1, +2: V = 2, normal approximation.
  EXPECT_EQ(p.wilcoxon.n, 2U);
  EXPECT_EQ(p.wilcoxon.v, 2.0);
  EXPECT_FALSE(p.wilcoxon.exact);
}

TEST(Statistics, PairedComparisonMissingZerosAndTolerance) {
  const double nan = kNaN;
  // NaN = a failed run: the pair is skipped. (0,0): ratio 1, a tie. (0,3): a win with no log
  // ratio; (2,0): a loss with no log ratio. 1 vs 1 + 1e-12: a tie within the tolerance.
  const std::vector<double> c = {nan, 0, 0, 2, 1 + 1e-12, 3, 5};
  const std::vector<double> b = {1, 0, 3, 0, 1, nan, 4};
  const PairedComparison p = compare_paired(c, b, 1e-9);
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

}  // namespace
}  // namespace agv
