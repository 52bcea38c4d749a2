// The handbooks beside the model (docs/handbooks.md): each part of a paper
// run's experiment that times the parts (assembly_time) classed by Boothroyd-Dewhurst's
// manual insertion chart and MTM-1's Position element from the scene's geometry
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

// `times`: the experiment of a paper run whose cycles time each part for its
// operators (an assembly_time experiment; the kind registry says which);
// null when the run has none, which the section says.
Section HandbookSection(const experiment::ExperimentRun* times,
                        const data::BdInsertionTable& bd,
                        const data::MtmPositionTable& mtm);

}  // namespace vahf::report
