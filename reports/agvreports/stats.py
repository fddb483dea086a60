"""The few statistics the scripts need, without scipy: Student t quantiles (through the
regularized incomplete beta function), exactly mergeable moments and their rebuilding from a
report's summaries, and Wilson intervals of a success rate.
"""

import math
from statistics import NormalDist


def _betacf(a, b, x):
    # Continued fraction for the incomplete beta function (modified Lentz).
    tiny = 1e-300
    qab, qap, qam = a + b, a + 1.0, a - 1.0
    c, d = 1.0, 1.0 - qab * x / qap
    d = 1.0 / (d if abs(d) > tiny else tiny)
    h = d
    for m in range(1, 400):
        m2 = 2 * m
        aa = m * (b - m) * x / ((qam + m2) * (a + m2))
        d = 1.0 + aa * d
        d = 1.0 / (d if abs(d) > tiny else tiny)
        c = 1.0 + aa / c
        c = c if abs(c) > tiny else tiny
        h *= d * c
        aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2))
        d = 1.0 + aa * d
        d = 1.0 / (d if abs(d) > tiny else tiny)
        c = 1.0 + aa / c
        c = c if abs(c) > tiny else tiny
        delta = d * c
        h *= delta
        if abs(delta - 1.0) < 1e-15:
            break
    return h


def betainc(a, b, x):
    """Regularized incomplete beta I_x(a, b)."""
    if x <= 0.0:
        return 0.0
    if x >= 1.0:
        return 1.0
    lbt = math.lgamma(a + b) - math.lgamma(a) - math.lgamma(b) + a * math.log(x) + b * math.log1p(-x)
    if x < (a + 1.0) / (a + b + 2.0):
        return math.exp(lbt) * _betacf(a, b, x) / a
    return 1.0 - math.exp(lbt) * _betacf(b, a, 1.0 - x) / b


def t_cdf(t, df):
    x = df / (df + t * t)
    tail = 0.5 * betainc(df / 2.0, 0.5, x)
    return 1.0 - tail if t > 0 else tail


def t_quantile(p, df):
    """Quantile of Student's t with df degrees of freedom (df >= 1)."""
    if df <= 0:
        return float("nan")
    if df > 1e7:
        return NormalDist().inv_cdf(p)
    if p == 0.5:
        return 0.0
    if p < 0.5:
        return -t_quantile(1.0 - p, df)
    lo, hi = 0.0, 1.0
    while t_cdf(hi, df) < p:
        hi *= 2.0
        if hi > 1e12:
            return float("inf")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if t_cdf(mid, df) < p:
            lo = mid
        else:
            hi = mid
        if hi - lo < 1e-13 * max(1.0, hi):
            break
    return 0.5 * (lo + hi)


def t_interval(mean, sd, n, confidence=0.95):
    """Interval of the mean, or (None, None) for fewer than two values."""
    if n < 2 or sd is None or not math.isfinite(sd):
        return (None, None)
    half = t_quantile(1.0 - (1.0 - confidence) / 2.0, n - 1) * sd / math.sqrt(n)
    return (mean - half, mean + half)


class Moments:
    """Count, mean and sum of squared deviations; merges exactly (Chan et al.)."""

    __slots__ = ("n", "mean", "m2")

    def __init__(self, n=0, mean=0.0, m2=0.0):
        self.n, self.mean, self.m2 = n, mean, m2

    @classmethod
    def of(cls, values):
        m = cls()
        for v in values:
            m.add(v)
        return m

    def add(self, x):
        self.n += 1
        d = x - self.mean
        self.mean += d / self.n
        self.m2 += d * (x - self.mean)

    def merge(self, other):
        if other.n == 0:
            return self
        if self.n == 0:
            self.n, self.mean, self.m2 = other.n, other.mean, other.m2
            return self
        n = self.n + other.n
        d = other.mean - self.mean
        self.mean += d * other.n / n
        self.m2 += other.m2 + d * d * self.n * other.n / n
        self.n = n
        return self

    @property
    def sd(self):
        return math.sqrt(self.m2 / (self.n - 1)) if self.n >= 2 else None

    def interval(self, confidence=0.95):
        return t_interval(self.mean, self.sd, self.n, confidence)


def moments_from_summary(n, mean, ci, confidence=0.95):
    """Rebuild (n, mean, M2) of a sample from its mean and its two-sided t interval of the mean
    (the engine's SUMMARY / COMPARISON ci95). Exact up to rounding: sd = half * sqrt(n) / t."""
    if n <= 0 or mean is None:
        return Moments()
    if n == 1:
        return Moments(1, mean, 0.0)
    if not ci or ci[0] is None or ci[1] is None:
        return None
    half = (ci[1] - ci[0]) / 2.0
    t = t_quantile(1.0 - (1.0 - confidence) / 2.0, n - 1)
    sd = half * math.sqrt(n) / t
    return Moments(n, mean, sd * sd * (n - 1))


def wilson(successes, n, confidence=0.95):
    if n <= 0:
        return (None, None)
    z = NormalDist().inv_cdf(1.0 - (1.0 - confidence) / 2.0)
    p = successes / n
    z2n = z * z / n
    centre = (p + z2n / 2.0) / (1.0 + z2n)
    half = z / (1.0 + z2n) * math.sqrt(p * (1.0 - p) / n + z2n / (4.0 * n))
    return (max(0.0, centre - half), min(1.0, centre + half))
