// Tests for samples paired by common random numbers: cycle j of two
// conditions runs on the same streams (experiment/design.h), so the two
// outcomes of one cycle are a pair and the test is on their differences
// (Student's paired t) or their discordant outcomes (McNemar's exact test).
// Pairing removes the variation the conditions share, which the independent-
// sample tests (welch.h, proportion.h) count as noise.
#pragma once

#include <cstdint>
#include <vector>

#include "vahf/stats/summary.h"

namespace vahf::stats {

struct PairedTResult {
  std::size_t n = 0;             // pairs
  double mean_difference = 0.0;  // mean of a_i - b_i
  double standard_error = 0.0;   // sd of the differences / sqrt(n)
  double t = 0.0;                // mean_difference / standard_error
  double df = 0.0;               // n - 1
  double p_two_sided = 1.0;      // H1: the mean difference != 0
  double p_less = 0.5;           // H1: a < b, P(T <= t)
  double p_greater = 0.5;        // H1: a > b, P(T >= t)
  double level = 0.95;
  Interval ci;  // for the mean difference at `level`
};

// Student's paired t test ("Student" 1908, Biometrika 6:1-25) of a_i - b_i,
// on GSL's Student-t distribution. a and b have the same size n >= 2, finite
// values, and differences that are not all equal (else t is undefined:
// vahf::ComputationError, kZeroVariance).
PairedTResult PairedTTest(const std::vector<double>& a, const std::vector<double>& b,
                          double level = 0.95);

// One-sided p-value of McNemar's exact test (McNemar 1947, Psychometrika
// 12:153-157) for H1: the success rate fell from the first to the second
// outcome of each pair. Only discordant pairs count: `fell` pairs succeeded
// then failed, `rose` pairs failed then succeeded; under H0 each is a fair
// coin, so p = P(X >= fell), X ~ Binomial(fell + rose, 1/2). p = 1 when no
// pair is discordant.
double McNemarRateFellP(std::int64_t fell, std::int64_t rose);

}  // namespace vahf::stats
