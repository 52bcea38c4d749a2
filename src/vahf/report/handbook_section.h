// The handbooks beside the model (docs/handbooks.md): each part of a paper
// run's assembly_time experiment classed by Boothroyd-Dewhurst's manual
// insertion chart and MTM-1's Position element from the scene's geometry
// (data/handbook_classification.h), with the handbook's time and its source,
// beside the part's virtual insertion time in the run: from the part's first
// contact with a fixed part to its completion (sim::TrialResult), mean and
// spread over the completed trials. Markdown, handbooks.csv and summary.json's
// "handbooks" (no claims: the handbooks are a yardstick, not the paper's).
#pragma once

#include "vahf/data/handbook.h"
#include "vahf/experiment/design.h"
#include "vahf/report/section.h"

namespace vahf::report {

// `run` is a paper run: the section reads its first part of kind
// "assembly_time" (and says so when there is none).
Section HandbookSection(const experiment::ExperimentRun& run,
                        const data::BdInsertionTable& bd,
                        const data::MtmPositionTable& mtm);

}  // namespace vahf::report
