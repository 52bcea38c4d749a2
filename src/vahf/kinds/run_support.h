// What the kinds' checks and runs share: what `vahf check` says of a scene,
// the files a run read, and the lines a run prints when its output is written.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "vahf/kinds/kind.h"
#include "vahf/report/run_output.h"
#include "vahf/scene/scene.h"

namespace vahf::kinds {

// The scene's description and its trial models, built as a run builds them
// before its first trial (what only building can reject is rejected now).
std::string DescribeSceneModels(const scene::Scene& scene);
// The check of a kind that runs the file's one scene (table1, assembly_time,
// fatigue): DescribeSceneModels of it.
std::string CheckOneScene(const scene::ExperimentFile& file);

// The section of a kind with a run of its own, named by its kind (the key of
// its part of summary.json).
report::Section KindSection(const RunContext& context, report::Section section);

double SecondsSince(std::chrono::steady_clock::time_point start);
// What the output records of a run with these settings started at `start`.
report::RunInfo RunInfoOf(const experiment::RunSettings& settings,
                          std::chrono::steady_clock::time_point start);

// Prints "NAME: KIND, seed S, X s on T thread(s)[ x R ranks][, detail]", the results
// digest and the report's path, then any plot that failed (on stderr);
// returns the exit status: 1 when a plot failed (the results are kept), else 0.
int FinishRun(const scene::ExperimentFile& file, const RunContext& context,
              double seconds, const report::RunOutput& written,
              const std::string& detail = "");

}  // namespace vahf::kinds
