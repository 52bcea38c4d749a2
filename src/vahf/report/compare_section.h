// The report of a comparison of a virtual design with a lab dataset
// (compare/comparison.h): per quantity the lab's and the virtual value with
// their 95 % intervals, the difference with its 95 % and 90 % intervals, the
// equivalence test against the stated margin and its verdict in a sentence,
// the area validation metric and the KS test; the virtual cycles with their
// numerical health and cost; a plot of lab and virtual side by side.
#pragma once

#include "vahf/compare/comparison.h"
#include "vahf/data/lab_dataset.h"
#include "vahf/report/section.h"
#include "vahf/scene/experiment_file.h"

namespace vahf::report {

Section ComparisonSection(const scene::ExperimentFile& file, const data::LabDataset& lab,
                          const compare::ComparisonResult& result);

}  // namespace vahf::report
