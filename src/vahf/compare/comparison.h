// A virtual design against a lab dataset, quantity by quantity (the
// `compare` kind; docs/experiments.md, "compare"). A quantity is a part's
// mean assembly time or success rate, or its mean eta (Eq. 2) or lambda_c
// (Eq. 3) at an instant of its trials, over all operators or per operator, of
// a lab condition and (but eta and lambda_c) of a segment of the hour of work. The
// virtual side runs the design that mirrors the lab's operators
// (calibrate::LabConditions) for quantities without a segment, and the fatigue design
// (experiment:: RunFatigue) for segment quantities, each only when a quantity needs it.
//
// Against the lab's trials (tracks for eta and lambda_c), each quantity is
// compared by
//   - the difference (virtual - lab) with its 95 % interval (Welch for means,
//     the normal interval on Laplace-smoothed proportions for rates),
//   - an equivalence test against the margin the experiment file states
//     (TOST, Schuirmann 1987; stats/equivalence.h): "agree" only when shown
//     within it,
//   - the area validation metric between the two empirical distributions, in
//     the quantity's unit (Ferson, Oberkampf and Ginzburg 2008),
//   - the two-sample KS test where both sides have samples of a mean.
// Against what the lab reports without its trials (a summary, a segment's
// counts: calibrate::LabTargets), by the normal approximation: the difference
// virtual - lab with se = sqrt(virtual variance + lab variance), the TOST on
// it, and the area metric against a point value (CompareReported); no KS.
// The lab's and the virtual side's samples are independent (different people,
// other keys), so the tests are the unpaired ones.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vahf/calibrate/targets.h"
#include "vahf/compare/comparison_input.h"
#include "vahf/data/lab_dataset.h"
#include "vahf/experiment/design.h"
#include "vahf/scene/experiment_file.h"
#include "vahf/stats/distribution.h"
#include "vahf/stats/summary.h"

namespace vahf::compare {

// The lab's side of one quantity, read before any simulation.
struct LabQuantity {
  calibrate::Target target;          // label, unit, the lab's statistic
  double margin = 0;                 // the equivalence margin, in the unit
  calibrate::TargetSamples samples;  // the lab's trials; none when reported
  bool reported = false;             // the statistic is what the lab reports
};

// Every quantity of `design` with the lab's side, in file order and, by
// operator, in the order operators first appear in the lab's trials. A
// quantity the lab has trials for takes them; otherwise what the lab reports
// (calibrate::LabTargets: a segment's counts or a summary; a value reported
// without any spread is kept as a point). eta and lambda_c at an instant
// take the lab's sensor tracks (calibrate::TrackSamples, measured with the
// curves `scene` builds for each operator) when it has any for the quantity,
// else what it reports. An InputError naming `experiment_file` and the
// quantity's pointer when the lab has neither.
std::vector<LabQuantity> LabSide(const scene::Scene& scene, const data::LabDataset& lab,
                                 const ComparisonDesign& design,
                                 const std::string& experiment_file);

// How the lab's side of `q` was obtained, for reports: "trials", "tracks", "reported",
// "reported once, no spread (a single draw)", "reported, no spread".
std::string LabBasis(const calibrate::Target& target, bool reported);

struct QuantityComparison {
  calibrate::Target target;            // label, unit, the lab's statistic
  double margin = 0;                   // the equivalence margin, in the unit
  bool reported = false;               // the lab side is a reported statistic, not trials
  calibrate::TargetSamples lab, virt;  // lab: empty when reported
  calibrate::Statistic virtual_stat;
  // The variance of the lab's statistic as the test used it (LabVariance:
  // for a single draw, the virtual per-sample variance); NaN: none.
  double lab_variance = 0;
  // 95 % of each side's mean or rate; for a reported statistic, value +-
  // 1.96 sqrt(lab_variance), within [0, 1] for a rate, NaN without a variance.
  stats::Interval lab_ci, virtual_ci;
  bool testable = false;
  std::string untestable_reason;  // when not testable: why, in a sentence
  double difference = 0;          // virtual - lab
  stats::Interval ci95, ci90;     // of the difference
  double tost_p = 1;
  bool agree = false;                          // equivalence shown at the 5 % level
  double area_metric = 0;                      // in the unit
  std::optional<stats::KolmogorovSmirnov> ks;  // times on both sides
  std::string ks_unavailable;                  // when no KS: why
  std::string verdict;  // "agree: ..." / "not shown to agree: ..." / "untestable: ..."
};

struct ComparisonResult {
  // The virtual designs, for their cycles, health and cost: the lab's
  // operators (no conditions when no quantity needs it) and the hour of work
  // (no conditions when no quantity names a segment).
  experiment::DesignRun run;
  experiment::FatigueRun fatigue;
  std::vector<QuantityComparison> quantities;
};

// Runs the virtual designs the quantities need (`trials` cycles per lab
// operator and per segment, `seed`) and compares each quantity. The fatigue
// pilot reports its progress with `pilot_options`.
ComparisonResult Compare(const scene::Scene& scene, const data::LabDataset& lab,
                         const ComparisonDesign& design,
                         const std::string& experiment_file, std::uint64_t seed,
                         int trials, const experiment::RunnerOptions& options,
                         const experiment::RunnerOptions& pilot_options);

// The comparison of one quantity from its two samples (for tests).
QuantityComparison CompareSamples(const calibrate::Target& target, double margin,
                                  const calibrate::TargetSamples& lab,
                                  const calibrate::TargetSamples& virt);

// The comparison of one quantity against the statistic the lab reports,
// target.lab, by the normal approximation: d = virtual - lab, se =
// sqrt(virtual variance + calibrate::LabVariance), the 95 % and 90 %
// intervals d +- z se and the TOST p = max(Q((d + margin) / se),
// P((d - margin) / se)) (Schuirmann 1987 on the normal statistic). The area
// validation metric against a point value x (Ferson, Oberkampf and Ginzburg
// 2008, Eq. 8, with the lab's distribution a step at x): for a time the mean
// |v_i - x| over the virtual times, for a rate |p_v - p_l|. Untestable
// without a lab variance (a value reported without any spread), with fewer
// than two virtual times, or with no virtual attempt.
QuantityComparison CompareReported(const calibrate::Target& target, double margin,
                                   const calibrate::TargetSamples& virt);

}  // namespace vahf::compare
