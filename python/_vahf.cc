// vahf._vahf: the library under Python (docs/python.md). Every function calls
// the library entry point the command calls (kinds/, sim/, scene/); the
// Python files beside it (vahf/__init__.py) turn the results into pandas
// DataFrames. The work runs on a worker thread without the GIL while the
// calling thread waits with it, waking every kPollInterval to deliver Python's
// pending signals (Ctrl-C: the run stops as the command's does, then
// KeyboardInterrupt) and the progress callback. The module installs no signal
// handler of its own, and a failed internal check raises InternalError.
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "vahf/core/error.h"
#include "vahf/core/warnings.h"
#include "vahf/data/lab_dataset.h"
#include "vahf/experiment/interrupt.h"
#include "vahf/experiment/progress.h"
#include "vahf/kinds/check_file.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/replay.h"
#include "vahf/kinds/run_support.h"
#include "vahf/kinds/synthesize.h"
#include "vahf/kinds/trial_request.h"
#include "vahf/kinds/verify.h"
#include "vahf/report/output_directory.h"
#include "vahf/scene/experiment_file.h"
#include "vahf/scene/parameter_table.h"
#include "vahf/scene/scene_loader.h"
#include "vahf/sim/trace_csv.h"

namespace py = pybind11;

namespace {

// How often the waiting thread looks for signals and progress (at most
// 100 ms, docs/python.md).
constexpr std::chrono::milliseconds kPollInterval{50};

using vahf::experiment::ProgressSink;

// Runs work(sink) on a worker thread and waits for it with the GIL released,
// taking the GIL back every kPollInterval to check Python's signals and to
// call `progress(label, unit, done, total)` when the sink changed. A pending
// signal's handler that raises (KeyboardInterrupt) requests a stop, waits
// for the worker (running trials finish, none starts) and raises it; so does
// a callback that raises. The worker's own exception is rethrown here, where
// the registered translator turns it into the module's.
template <class R>
R Watched(const std::function<R(ProgressSink*)>& work, const py::object& progress) {
  vahf::experiment::ClearStop();
  ProgressSink sink;
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::optional<R> result;
  std::exception_ptr error;
  std::thread worker([&] {
    try {
      result.emplace(work(&sink));
    } catch (...) {
      error = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(mutex);
    done = true;
    finished.notify_all();
  });
  const auto join = [&] {
    py::gil_scoped_release release;
    worker.join();
  };
  const auto stop_and_rethrow = [&] {
    vahf::experiment::RequestStop();
    join();
    vahf::experiment::ClearStop();
  };
  std::size_t seen_batches = 0, seen_done = 0;
  const auto report = [&] {
    if (progress.is_none()) return;
    const ProgressSink::State s = sink.Get();
    if (s.batches == 0 || (s.batches == seen_batches && s.done == seen_done)) return;
    seen_batches = s.batches;
    seen_done = s.done;
    progress(s.label, s.unit, s.done, s.total);
  };
  for (;;) {
    bool over = false;
    {
      py::gil_scoped_release release;
      std::unique_lock<std::mutex> lock(mutex);
      over = finished.wait_for(lock, kPollInterval, [&] { return done; });
    }
    if (over) break;
    if (PyErr_CheckSignals() != 0) {
      stop_and_rethrow();
      throw py::error_already_set();
    }
    try {
      report();
    } catch (...) {
      stop_and_rethrow();
      throw;
    }
  }
  join();
  if (error) std::rethrow_exception(error);
  report();
  return std::move(*result);
}

// The module's exception classes live in vahf/_errors.py.
[[noreturn]] void Raise(const char* name, const py::tuple& args) {
  const py::object type = py::module_::import("vahf._errors").attr(name);
  const py::object value = type(*args);
  PyErr_SetObject(type.ptr(), value.ptr());
  throw py::error_already_set();
}

const char* ReasonName(vahf::ComputationError::Reason reason) {
  using R = vahf::ComputationError::Reason;
  switch (reason) {
    case R::kTooFewValues:
      return "too_few_values";
    case R::kZeroVariance:
      return "zero_variance";
    case R::kOutOfDomain:
      return "out_of_domain";
    case R::kRefused:
      return "refused";
  }
  return "refused";
}

void Translate(std::exception_ptr p) {
  try {
    if (p) std::rethrow_exception(p);
  } catch (const vahf::InputError& e) {
    Raise("InputError",
          py::make_tuple(e.what(), e.file(), e.where(), e.value(), e.rule()));
  } catch (const vahf::InternalError& e) {
    Raise("InternalError",
          py::make_tuple(e.what(), e.file(), e.line(), e.condition(), e.message()));
  } catch (const vahf::ComputationError& e) {
    Raise("ComputationError", py::make_tuple(e.what(), ReasonName(e.reason())));
  } catch (const vahf::experiment::Interrupted& e) {
    PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
  }
}

// A scene file as read (vahf.load_scene).
struct SceneHandle {
  std::string path;
  vahf::scene::Scene scene;
};

// An experiment file as read, with its overrides (vahf.load_experiment).
struct ExperimentHandle {
  std::string path;
  std::string overrides;
  vahf::scene::ExperimentFile file;
};

// {"group/key": value} from Python as the library's parameter values: a
// bool, an integer, a float (NaN too: its rule refuses it, named) or a name.
using PySets = std::vector<std::pair<std::string, py::object>>;
vahf::kinds::ParameterSets Sets(const PySets& sets) {
  vahf::kinds::ParameterSets out;
  for (const auto& [name, v] : sets) {
    nlohmann::json value;
    if (py::isinstance<py::bool_>(v)) {
      value = v.cast<bool>();
    } else if (py::isinstance<py::str>(v)) {
      value = v.cast<std::string>();
    } else if (py::isinstance<py::int_>(v) && !py::isinstance<py::float_>(v)) {
      try {
        value = v.cast<long long>();
      } catch (const py::cast_error&) {
        throw vahf::InputError("set", "/" + name, py::str(v).cast<std::string>(),
                               "must be a number of the parameter's rule");
      }
    } else {
      try {
        value = py::float_(v).cast<double>();
      } catch (const py::error_already_set&) {
        throw vahf::InputError("set", "/" + name, py::repr(v).cast<std::string>(),
                               "must be a number or a name");
      }
    }
    out.emplace_back(name, std::move(value));
  }
  return out;
}

py::dict Row(const vahf::sim::TrialResult& r) {
  py::dict d;
  d["status"] = vahf::sim::StatusName(r.status);
  d["detail"] = r.detail;
  d["end_time"] = r.end_time;
  d["completion_time"] = r.completion_time;
  d["first_contact_time"] = r.first_contact_time;
  d["part"] = r.part;
  d["integrator"] = r.integrator;
  d["accuracy"] = r.accuracy;
  d["seed"] = r.key.seed;
  d["trial"] = r.key.trial;
  d["work"] = r.work;
  d["max_penetration"] = r.max_penetration;
  d["penetration_bound"] = r.penetration_bound;
  d["clearance"] = r.clearance;
  d["stiffness"] = r.stiffness;
  d["line_stiffness"] = r.line_stiffness;
  d["wall_seconds"] = r.wall_seconds;
  d["cpu_seconds"] = r.cpu_seconds;
  const vahf::sim::TrialCounters& c = r.counters;
  py::dict counters;
  counters["decisions"] = c.decisions;
  counters["steps_taken"] = c.steps_taken;
  counters["steps_attempted"] = c.steps_attempted;
  counters["error_test_failures"] = c.error_test_failures;
  counters["realizations"] = c.realizations;
  counters["jacobian_evaluations"] = c.jacobian_evaluations;
  counters["convergence_failures"] = c.convergence_failures;
  counters["contact_evaluations"] = c.contact_evaluations;
  counters["contact_point_queries"] = c.contact_point_queries;
  counters["contact_tests"] = c.contact_tests;
  counters["broad_phase_skips"] = c.broad_phase_skips;
  counters["clusters_skipped"] = c.clusters_skipped;
  counters["rays_cast"] = c.rays_cast;
  counters["shell_points"] = c.shell_points;
  d["counters"] = counters;
  py::dict rests;
  rests["count"] = r.rests.count;
  rests["total_time"] = r.rests.total_time;
  rests["longest"] = r.rests.longest;
  d["rests"] = rests;
  py::dict warnings;
  for (int k = 0; k < vahf::kWarningKinds; ++k) {
    const auto kind = static_cast<vahf::WarningKind>(k);
    const vahf::WarningEntry& e = r.warnings.at(kind);
    py::dict w;
    w["count"] = e.count;
    w["first_time"] = e.first_time;
    w["detail"] = e.detail;
    warnings[vahf::WarningName(kind)] = w;
  }
  d["warnings"] = warnings;
  d["warnings_summary"] = r.warnings.Summary();
  d["summary"] = r.BriefReport();
  d["trace_csv"] = r.trace.empty() && r.samples.empty() ? "" : vahf::sim::TraceCsv(r);
  d["trace_rows"] = r.trace.size();
  d["sample_rows"] = r.samples.size();
  return d;
}

py::dict Trial(const SceneHandle& scene, std::uint64_t seed, std::uint64_t trial,
               int position, const std::string& integrator, const PySets& sets,
               double sample, bool trace, const py::object& progress) {
  vahf::kinds::TrialRequest request;
  request.seed = seed;
  request.trial = trial;
  request.position = position;
  request.integrator = integrator;
  request.sets = Sets(sets);
  request.names = {"set", "position", "sample", "needs trace=True to hold the rows"};
  request.record_trace = trace;
  request.sample = sample;
  const vahf::sim::TrialResult r = Watched<vahf::sim::TrialResult>(
      [&](ProgressSink*) {
        return vahf::kinds::RunTrialRequest(scene.scene, scene.path, request);
      },
      progress);
  return Row(r);
}

// `vahf run`: the output directory staged before any simulation, the run,
// and the directory written; returns {"out", "status"}. A stop (Ctrl-C)
// leaves what finished journaled for resume=True, as the command does.
py::dict Run(const ExperimentHandle& experiment, std::optional<std::uint64_t> seed,
             int trials, int threads, const std::string& out, bool resume,
             bool progress_line, const py::object& progress) {
  vahf::kinds::RunContext context;
  context.settings.seed = seed ? *seed : experiment.file.seed;
  context.settings.trials = trials;
  context.settings.threads = threads;
  context.settings.progress = progress_line;
  const std::string dir = out.empty() ? vahf::kinds::DefaultRunDirectory(
                                            experiment.file, context.settings.seed)
                                      : out;
  vahf::report::OutputDirectory directory(dir, resume);
  context.directory = &directory;
  const int status = Watched<int>(
      [&](ProgressSink* sink) {
        context.settings.progress_sink = sink;
        return vahf::kinds::RunExperiment(experiment.file, context);
      },
      progress);
  py::dict d;
  d["out"] = dir;
  d["status"] = status;
  d["reused"] = directory.Journaled().reused;
  d["computed"] = directory.Journaled().written;
  return d;
}

py::list Params() {
  const vahf::scene::Parameters defaults;
  py::list rows;
  for (const vahf::scene::ParamSpec& s : vahf::scene::ParameterTable()) {
    py::dict row;
    row["name"] = vahf::scene::ParamName(s);
    row["unit"] = s.unit;
    row["rule"] = vahf::scene::RuleText(s);
    row["default"] = vahf::scene::ParamValueText(s, defaults);
    row["description"] = s.meaning;
    rows.append(row);
  }
  return rows;
}

void FailInternalCheck() {
  VAHF_CHECK(1 + 1 == 3, "a check made to fail, to test InternalError");
}

}  // namespace

PYBIND11_MODULE(_vahf, m) {
  m.doc() =
      "vahf's library under Python: the compiled part of the vahf package "
      "(use the package's functions; docs/python.md).";
  vahf::ThrowOnInternalCheck();
  py::register_exception_translator(&Translate);

  py::class_<SceneHandle>(m, "Scene", "A scene file as read and validated (load_scene).")
      .def_readonly("path", &SceneHandle::path, "The file it was read from.")
      .def_property_readonly(
          "name", [](const SceneHandle& s) { return s.scene.name; }, "The scene's name.")
      .def_property_readonly(
          "description", [](const SceneHandle& s) { return s.scene.description; },
          "The scene's description.")
      .def_property_readonly(
          "sequence",
          [](const SceneHandle& s) {
            std::vector<std::string> names;
            for (int i : s.scene.sequence) names.push_back(s.scene.parts[i].name);
            return names;
          },
          "The parts in assembly order (position 0 first).")
      .def(
          "describe",
          [](const SceneHandle& s) { return vahf::kinds::DescribeSceneModels(s.scene); },
          "What `vahf check` says of it: its parts and their trial models.")
      .def("__repr__", [](const SceneHandle& s) {
        return "<vahf.Scene '" + s.scene.name + "' from " + s.path + ">";
      });

  py::class_<ExperimentHandle>(m, "Experiment",
                               "An experiment file as read and validated "
                               "(load_experiment), with its override file if any.")
      .def_readonly("path", &ExperimentHandle::path, "The file it was read from.")
      .def_readonly("overrides", &ExperimentHandle::overrides,
                    "The parameter-override file applied ('' for none).")
      .def_property_readonly(
          "name", [](const ExperimentHandle& e) { return e.file.name; }, "Its name.")
      .def_property_readonly(
          "kind", [](const ExperimentHandle& e) { return e.file.kind; },
          "Its kind (`vahf kinds`).")
      .def_property_readonly(
          "seed", [](const ExperimentHandle& e) { return e.file.seed; },
          "The file's seed.")
      .def(
          "check",
          [](const ExperimentHandle& e) { return vahf::kinds::CheckExperiment(e.file); },
          "What `vahf check` says of it.")
      .def("__repr__", [](const ExperimentHandle& e) {
        return "<vahf.Experiment '" + e.file.name + "' (" + e.file.kind + ") from " +
               e.path + ">";
      });

  m.def(
      "load_scene",
      [](const std::string& path, const PySets& sets) {
        SceneHandle s{path, vahf::kinds::LoadSceneFile(path)};
        vahf::kinds::SetParameters("set", Sets(sets), &s.scene);
        if (const std::string v = vahf::scene::ParameterViolation(s.scene); !v.empty())
          throw vahf::InputError("set", "", "applied to " + path, v);
        return s;
      },
      py::arg("path"), py::arg("sets"),
      "Reads a scene file, then (GROUP/KEY, JSON text).");
  m.def(
      "load_experiment",
      [](const std::string& path, const std::string& overrides) {
        return ExperimentHandle{path, overrides,
                                vahf::kinds::LoadExperiment(path, overrides)};
      },
      py::arg("path"), py::arg("overrides"),
      "Reads an experiment file and applies an override file ('' for none).");
  m.def("trial", &Trial, py::arg("scene"), py::arg("seed"), py::arg("trial"),
        py::arg("position"), py::arg("integrator"), py::arg("sets"), py::arg("sample"),
        py::arg("trace"), py::arg("progress"),
        "One seeded trial; a dict of the summary's fields and the trace as CSV text.");
  m.def("run", &Run, py::arg("experiment"), py::arg("seed"), py::arg("trials"),
        py::arg("threads"), py::arg("out"), py::arg("resume"), py::arg("progress_line"),
        py::arg("progress"), "`vahf run`: writes the run directory; {'out', 'status'}.");
  m.def(
      "check",
      [](const std::string& path) {
        return Watched<std::string>(
            [&](ProgressSink*) { return vahf::kinds::CheckFile(path); }, py::none());
      },
      py::arg("path"), "`vahf check FILE`: what the file holds, or an InputError.");
  m.def(
      "verify",
      [](const std::string& run_dir, int threads, const std::string& keep,
         const py::object& progress) {
        vahf::kinds::VerifyOptions o{run_dir, threads, keep};
        return Watched<int>([&](ProgressSink*) { return vahf::kinds::Verify(o); },
                            progress);
      },
      py::arg("run_dir"), py::arg("threads"), py::arg("keep"), py::arg("progress"),
      "`vahf verify RUN_DIR`: 0 when every result file is identical, 1 otherwise.");
  m.def(
      "replay",
      [](const std::string& run_dir, const std::string& cycle, const std::string& trace,
         double sample) {
        vahf::kinds::ReplayOptions o{run_dir,  cycle,
                                     trace,    sample,
                                     "sample", "needs trace=FILE to write the rows to"};
        return Watched<int>([&](ProgressSink*) { return vahf::kinds::Replay(o); },
                            py::none());
      },
      py::arg("run_dir"), py::arg("cycle"), py::arg("trace"), py::arg("sample"),
      "`vahf replay RUN_DIR --cycle TABLE:ROW`: 0 when the rows are the table's.");
  m.def(
      "synthesize",
      [](const std::string& generator, const std::string& out, int threads,
         const py::object& progress) {
        return Watched<std::string>(
            [&](ProgressSink* sink) {
              vahf::experiment::RunnerOptions o;
              o.threads = threads;
              o.progress = false;
              o.progress_sink = sink;
              return vahf::kinds::Synthesize(generator, out, o);
            },
            progress);
      },
      py::arg("generator"), py::arg("out"), py::arg("threads"), py::arg("progress"),
      "`vahf synthesize GENERATOR --out DIR`: the line the command prints.");
  m.def(
      "lab_files",
      [](const std::string& path) {
        const vahf::data::LabDataset lab = vahf::data::LoadLabDataset(path);
        py::dict d;
        d["name"] = lab.name;
        d["description"] = lab.description;
        d["folder"] = lab.folder;
        d["trials"] = lab.trials_file;
        d["segments"] = lab.segments_file;
        d["summaries"] = lab.summaries_file;
        std::vector<std::string> tracks;
        for (const auto& t : lab.tracks) tracks.push_back(t.file);
        d["tracks"] = tracks;
        d["describe"] = vahf::data::DescribeLabDataset(lab);
        return d;
      },
      py::arg("path"), "Loads and checks a lab dataset; its files and description.");
  m.def("params", &Params,
        "The parameter table: name, unit, rule, default, description.");
  m.def("_fail_internal_check", &FailInternalCheck,
        "Fails an internal check (VAHF_CHECK), for the tests of InternalError.");
}
