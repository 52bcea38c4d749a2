// A virtual design against a lab dataset, quantity by quantity (issue 12's
// `compare` kind; docs/experiments.md, "compare"): the design mirrors the
// lab's operators (calibrate::LabConditions) and each quantity - a part's mean
// assembly time or success rate, over all operators or per operator - is
// compared with the lab's by
//   - the difference (virtual - lab) with its 95 % interval (Welch for times,
//     the normal interval on Laplace-smoothed proportions for rates),
//   - an equivalence test against the margin the experiment file states
//     (TOST, stats/equivalence.h): "agree" only when shown within it,
//   - the area validation metric between the two empirical distributions, in
//     the quantity's unit (Ferson, Oberkampf and Ginzburg 2008),
//   - the two-sample KS test where both sides have times.
// The lab's and the virtual side's samples are independent (different people,
// other keys), so the tests are the unpaired ones.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vahf/calibrate/targets.h"
#include "vahf/data/lab_dataset.h"
#include "vahf/experiment/design.h"
#include "vahf/scene/experiment_file.h"
#include "vahf/stats/distribution.h"
#include "vahf/stats/summary.h"

namespace vahf::compare {

struct QuantityComparison {
  calibrate::Target target;          // label, unit, the lab's statistic
  double margin = 0;                 // the equivalence margin, in the unit
  calibrate::TargetSamples lab, virt;
  calibrate::Statistic virtual_stat;
  stats::Interval lab_ci, virtual_ci;  // 95 % of each side's mean or rate
  bool testable = false;
  std::string untestable_reason;     // when not testable: why, in a sentence
  double difference = 0;             // virtual - lab
  stats::Interval ci95, ci90;        // of the difference
  double tost_p = 1;
  bool agree = false;                // equivalence shown at the 5 % level
  double area_metric = 0;            // in the unit
  std::optional<stats::KolmogorovSmirnov> ks;  // times on both sides
  std::string verdict;               // "agree: ..." / "not shown to agree: ..." / "untestable: ..."
};

struct ComparisonResult {
  experiment::DesignRun run;  // the virtual design, for its cycles, health and cost
  std::vector<QuantityComparison> quantities;
};

// Runs the virtual design (`trials` cycles per lab operator, `seed`) and
// compares each quantity. An InputError naming `experiment_file` when the lab
// has no trials for a quantity.
ComparisonResult Compare(const scene::Scene& scene, const data::LabDataset& lab,
                         const scene::ComparisonDesign& design,
                         const std::string& experiment_file, std::uint64_t seed, int trials,
                         const experiment::RunnerOptions& options);

// The comparison of one quantity from its two samples (for tests).
QuantityComparison CompareSamples(const calibrate::Target& target, double margin,
                                  const calibrate::TargetSamples& lab,
                                  const calibrate::TargetSamples& virt);

}  // namespace vahf::compare
