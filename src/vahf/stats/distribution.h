// Comparing two distributions (the precision experiment: completion times
// under a setting against the reference): sample quantiles, the two-sample
// Kolmogorov-Smirnov distance with its asymptotic p-value, and the shift of a
// sample that a KS distance amounts to.
#pragma once

#include <cstddef>
#include <vector>

namespace vahf::stats {

// The p-quantile of the sample, p in [0, 1], n >= 1: linear interpolation
// between order statistics, x_(floor(h)) + (h - floor(h)) (x_(floor(h)+1) -
// x_(floor(h))) with h = (n - 1) p on 0-based order statistics (Hyndman and
// Fan 1996, Am. Stat. 50:361-365, definition 7; R's default and GSL's
// gsl_stats_quantile_from_sorted_data). The median is p = 0.5.
double Quantile(const std::vector<double>& xs, double p);

struct KolmogorovSmirnov {
  double distance = 0;     // D = sup_x |F_a(x) - F_b(x)| of the empirical CDFs
  double p_value = 1;      // P(D' >= D) for independent samples of one distribution
  double effective_n = 0;  // n_a n_b / (n_a + n_b)
};

// The two-sample Kolmogorov-Smirnov statistic (Smirnov 1939; Conover,
// Practical Nonparametric Statistics, 3rd ed., 1999, Sec. 6.3): the largest
// gap between the two empirical distribution functions, evaluated after each
// distinct value of the pooled sample (ties move both functions at once).
// p_value is the asymptotic one, KolmogorovQ(lambda) with Stephens' small-
// sample correction lambda = (sqrt(n_e) + 0.12 + 0.11 / sqrt(n_e)) D
// (Stephens 1970, JRSS B 32:115-122; Press et al., Numerical Recipes, 3rd ed.,
// 2007, Sec. 14.3.3). It assumes independent samples: for samples paired by
// common random numbers, which are positively dependent, D is smaller than
// independence would make it and the p-value is conservative. Each sample
// needs n >= 1 finite values.
KolmogorovSmirnov KolmogorovSmirnovTest(const std::vector<double>& a,
                                        const std::vector<double>& b);

// The Kolmogorov distribution's upper tail Q(lambda) = P(K > lambda) =
// 2 sum_{j>=1} (-1)^(j-1) exp(-2 j^2 lambda^2) (Kolmogorov 1933), for
// lambda >= 1.18, and 1 - (sqrt(2 pi) / lambda) sum_{j>=1}
// exp(-(2j-1)^2 pi^2 / (8 lambda^2)) below, where that series converges faster
// (Numerical Recipes, 3rd ed., Sec. 6.14.12). Q(0) = 1; lambda >= 0.
double KolmogorovQ(double lambda);

// The KS distance between the sample and itself shifted by delta >= 0:
// sup_x F(x) - F(x - delta), the largest share of the sample in a window
// (x - delta, x]. It is k/n once delta exceeds the smallest span
// x_(i+k-1) - x_(i) of k consecutive order statistics. n >= 1.
double KsDistanceOfShift(const std::vector<double>& xs, double delta);

// A KS distance D in the unit of the data: the smallest shift of the sample
// xs whose KS distance from xs itself reaches D, inf {delta : KsDistanceOfShift
// (xs, delta) >= D}; with k = ceil(n D), that is 0 for k <= 1 and the
// smallest span of k consecutive order statistics otherwise. D is the
// distance of two samples of xs's size n (a multiple of 1/n), in [0, 1].
//
// It is read off the sample rather than a model (a normal distribution would
// give 2 sd Phi^-1((1 + D)/2)), so it respects the resolution of a small
// sample: a distance of 1/n, which any difference at all produces, is worth no
// shift, and a distance the sample cannot tell from a shift of delta is worth
// less than delta. Use: is the KS distance of a setting's completion times from
// the reference's more than a shift by the Monte Carlo noise would make?
double KsEquivalentShift(const std::vector<double>& xs, double distance);

}  // namespace vahf::stats
