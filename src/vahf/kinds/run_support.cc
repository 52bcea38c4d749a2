#include "vahf/kinds/run_support.h"

#include <fmt/format.h>

#include <cstdio>

#include "vahf/scene/scene_loader.h"
#include "vahf/sim/trial_model.h"

namespace vahf::kinds {

std::string DescribeSceneModels(const scene::Scene& scene) {
  std::string out = scene::DescribeScene(scene);
  for (const auto& m : sim::BuildSequenceModels(scene)) {
    out += fmt::format("  trial model '{}': ", m->part->name);
    if (!m->contact.model)
      out += "nothing to touch";
    else
      out += fmt::format("contact {}, {} shell points", scene.params.contact.model,
                         static_cast<long long>(m->contact.shell_points));
    if (m->clearance > 0)
      out += fmt::format(", radial clearance {:.3g} um, penetration bound {:.3g} um",
                         m->clearance * 1e6, m->penetration_bound * 1e6);
    out += m->visibility ? ", V by ray casting\n" : "\n";
  }
  return out;
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int FinishRun(const scene::ExperimentFile& file, const RunContext& context, double seconds,
              const report::RunOutput& written, const std::string& detail) {
  std::printf("%s: %s, seed %llu, %.1f s on %d thread(s)%s%s\nresults digest %s\n"
              "report: %s/report.md\n",
              file.name.c_str(), file.kind.c_str(),
              static_cast<unsigned long long>(context.settings.seed), seconds,
              context.settings.threads, detail.empty() ? "" : ", ", detail.c_str(),
              written.results_digest.c_str(), context.directory->path().c_str());
  for (const std::string& failure : written.failed_plots)
    std::fprintf(stderr, "vahf: error: plot not rendered (results kept): %s\n",
                 failure.c_str());
  return written.failed_plots.empty() ? 0 : 1;
}

}  // namespace vahf::kinds
