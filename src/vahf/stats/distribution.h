// Comparing two distributions (the precision experiment: completion times
// under a setting against the reference): sample quantiles, the two-sample
// Kolmogorov-Smirnov distance with its asymptotic p-value, and the location
// shift of a normal distribution that a KS distance amounts to.
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
  double distance = 0;   // D = sup_x |F_a(x) - F_b(x)| of the empirical CDFs
  double p_value = 1;    // P(D' >= D) for independent samples of one distribution
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

// The shift delta between two normal distributions of standard deviation sd
// whose Kolmogorov-Smirnov distance is D: sup_x |Phi((x - mu)/sd) -
// Phi((x - mu - delta)/sd)| is taken at the midpoint x = mu + delta/2, where it
// is 2 Phi(delta / (2 sd)) - 1; so delta = 2 sd Phi^-1((1 + D) / 2). It puts
// a KS distance in the unit of the completion time, to set it against the
// Monte Carlo noise. D in [0, 1], sd >= 0; D = 0 gives 0, and D = 1 or sd = 0
// with D > 0 (distributions no normal shift explains) infinity.
double NormalShiftForKsDistance(double distance, double sd);

// The inverse: the KS distance 2 Phi(delta / (2 sd)) - 1 of two normal
// distributions of standard deviation sd > 0 whose means differ by delta >= 0.
double KsDistanceOfNormalShift(double delta, double sd);

}  // namespace vahf::stats
