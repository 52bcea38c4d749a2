// The report of a comparison of a virtual design with a lab dataset
// (compare/comparison.h): per quantity the lab's and the virtual value with
// their 95 % intervals and where the lab's comes from (trials or a reported
// value), the difference with its 95 % and 90 % intervals, the equivalence
// test against the stated margin and its verdict in a sentence, the area
// validation metric and the KS test (or why there is none); a table and a
// plot of lab beside virtual per unit (times in s, rates); every virtual
// cycle (the lab operators' design, the fatigue pilot and segments) with its
// numerical health and cost. `trials`: the cycles per condition the run used.
#pragma once

#include "vahf/compare/comparison.h"
#include "vahf/data/lab_dataset.h"
#include "vahf/report/section.h"
#include "vahf/scene/experiment_file.h"

namespace vahf::report {

Section ComparisonSection(const scene::ExperimentFile& file, const data::LabDataset& lab,
                          const compare::ComparisonResult& result, int trials);

}  // namespace vahf::report
