// Descriptive statistics of a sample and the Student-t confidence interval for
// its mean, on GSL (gsl_stats_*, gsl_cdf_tdist_Pinv).
//
// Undefined quantities are never NaN: the plain functions throw
// vahf::ComputationError (a mean of no values, a standard deviation of one:
// kTooFewValues; a value not finite: kOutOfDomain), and Summarize() leaves
// them empty. Every value must be finite.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace vahf::stats {

// A closed interval [lower, upper].
struct Interval {
  double lower = 0.0;
  double upper = 0.0;
};

// The arithmetic mean; n >= 1.
double Mean(const std::vector<double>& xs);

// The sample standard deviation (divisor n - 1); n >= 2. Identical values give 0.
double SampleStandardDeviation(const std::vector<double>& xs);

// The two-sided Student-t interval mean +- t(n-1, (1+level)/2) * sd / sqrt(n)
// for the population mean; n >= 2, level in (0, 1). Zero variance gives the
// single point [mean, mean].
Interval MeanConfidenceInterval(const std::vector<double>& xs, double level = 0.95);

// All of the above for a sample of any size: what a sample cannot define is
// empty (mean for n = 0; sd, standard error and interval for n < 2).
struct Summary {
  std::size_t n = 0;
  double level = 0.95;  // of `ci`
  std::optional<double> mean;
  std::optional<double> sd;              // sample standard deviation
  std::optional<double> standard_error;  // sd / sqrt(n)
  std::optional<Interval> ci;            // MeanConfidenceInterval
};
Summary Summarize(const std::vector<double>& xs, double level = 0.95);

// The quantile t such that P(|T| <= t) = level for Student's t with df degrees
// of freedom (df > 0, level in (0, 1)): the half-width factor of a two-sided
// interval.
double TwoSidedStudentT(double df, double level);

}  // namespace vahf::stats
