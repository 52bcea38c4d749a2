#include "vahf/kinds/run_support.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>

#include "vahf/core/error.h"
#include "vahf/scene/scene_loader.h"
#include "vahf/sim/trial_model.h"

namespace vahf::kinds {

namespace {

// The assembly torque's impedance about the part's transverse x axis, where
// it tips (guidance/torque_law; Psi = 1): stiffness, damping, and the
// natural frequency and damping ratio they give the moving body.
std::string DescribeHand(const sim::TrialModel& m) {
  const auto& g = m.params.guidance;
  const double w = m.torque_params.torque_frequency;
  const double i_law = m.torque_inertia_body(0, 0);
  const double k = i_law * w * w,
               b = i_law * 2 * m.torque_params.torque_damping_ratio * w;
  const double inertia = m.inertia_body(0, 0);
  return fmt::format(
      "    hand: {} torque law, rotational stiffness {:.3g} N m/rad, damping {:.3g} N m "
      "s/rad about the part's x axis (inertia {:.3g} kg m^2): natural frequency {:.3g} "
      "rad/s, damping ratio {:.3g}; in contact the push acts at the {}\n",
      g.torque_law, k, b, inertia, std::sqrt(k / inertia),
      b / (2 * std::sqrt(k * inertia)),
      m.compliance_at_leading_end ? "part's leading end" : "grasp");
}

}  // namespace

std::string DescribeSceneModels(const scene::Scene& scene) {
  std::string out = scene::DescribeScene(scene);
  for (const auto& m : sim::BuildSequenceModels(scene)) {
    out += fmt::format("  trial model '{}': ", m->part_name);
    if (!m->contact.model)
      out += "nothing to touch";
    else
      out += fmt::format("contact {}, {} shell points", scene.params.contact.model,
                         static_cast<long long>(m->contact.shell_points));
    if (m->clearance > 0)
      out += fmt::format(", radial clearance {:.3g} um, penetration bound {:.3g} um",
                         m->clearance * 1e6, m->penetration_bound * 1e6);
    out += m->casters ? ", V by ray casting\n" : "\n";
    if (m->operator_acts) out += DescribeHand(*m);
  }
  return out;
}

std::string CheckOneScene(const scene::ExperimentFile& file) {
  return DescribeSceneModels(file.scene);
}

report::Section KindSection(const RunContext& context, report::Section section) {
  VAHF_CHECK(context.kind != nullptr, "a kind's own run without its kind");
  section.kind = context.kind->name;
  return section;
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

report::RunInfo RunInfoOf(const experiment::RunSettings& settings,
                          std::chrono::steady_clock::time_point start) {
  report::RunInfo info;
  info.threads = settings.threads;
  info.wall_seconds = SecondsSince(start);
  info.trials_option = settings.trials;
  info.ranks = settings.RankCount();
  return info;
}

int FinishRun(const scene::ExperimentFile& file, const RunContext& context,
              double seconds, const report::RunOutput& written,
              const std::string& detail) {
  std::printf(
      "%s: %s, seed %llu, %.1f s on %d thread(s)%s%s%s\nresults digest %s\n"
      "report: %s/report.md\n",
      file.name.c_str(), file.kind.c_str(),
      static_cast<unsigned long long>(context.settings.seed), seconds,
      context.settings.threads,
      context.settings.RankCount() > 1
          ? fmt::format(" x {} ranks", context.settings.RankCount()).c_str()
          : "",
      detail.empty() ? "" : ", ", detail.c_str(), written.results_digest.c_str(),
      context.directory->path().c_str());
  for (const std::string& failure : written.failed_plots)
    std::fprintf(stderr, "vahf: error: plot not rendered (results kept): %s\n",
                 failure.c_str());
  return written.failed_plots.empty() ? 0 : 1;
}

}  // namespace vahf::kinds
