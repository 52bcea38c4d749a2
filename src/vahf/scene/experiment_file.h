// An experiment file names a kind of experiment, the scene it runs on, the seed
// and the number of trials (docs/scene-format.md, "Experiment files").
#pragma once

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "vahf/core/clone_ptr.h"
#include "vahf/core/error.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/scene.h"

namespace vahf::scene {

inline constexpr const char* kExperimentFormat = "vahf-experiment/1";
// A lab dataset's manifest (data/lab_dataset.h reads it; named here so that
// FormatOf can tell it without the data layer).
inline constexpr const char* kLabFormat = "vahf-lab/1";
// A parameter-override file (overrides.h) and a synthetic lab generator
// (calibrate/synthetic_lab.h): named here so that FormatOf tells every vahf
// file apart.
inline constexpr const char* kOverridesFormat = "vahf-overrides/1";
inline constexpr const char* kSyntheticFormat = "vahf-synthetic/1";

struct ExperimentFile;
struct ParameterOverrides;  // overrides.h

// What an experiment file holds for its kind besides the common fields: each
// kind's own struct derives from this (through KindInputOf), lives with the
// kind, and is read by the kind's registered reader (kinds/kind.h).
class KindInput {
 public:
  virtual ~KindInput() = default;
  virtual std::unique_ptr<KindInput> Clone() const = 0;
  // An override file reaching the scenes the input holds (overrides.h), after
  // the file's own `scene` got it; what the kind's own settings set (a
  // precision setting, a stability case's integrator) stays its own. May set
  // `file->scene` to the first scene the kind runs.
  virtual void ApplyOverrides(const ParameterOverrides&, ExperimentFile*) {}
  // Parameters the kind sets itself in its file's scene (a calibration's
  // fitted ones): an override file does not set them there (the kind's
  // ApplyOverrides decides what its value means).
  virtual std::vector<std::string> OwnParameters() const { return {}; }
  // Files read besides the experiment file, its scene and an override file, for
  // the run's manifest, in the order read.
  virtual std::vector<std::string> InputFiles() const { return {}; }

 protected:
  KindInput() = default;
  KindInput(const KindInput&) = default;
  KindInput& operator=(const KindInput&) = default;
};

// The Clone of a kind's input struct `Derived`.
template <class Derived>
class KindInputOf : public KindInput {
 public:
  std::unique_ptr<KindInput> Clone() const override {
    return std::make_unique<Derived>(static_cast<const Derived&>(*this));
  }
};

struct ExperimentFile {
  std::string file;
  std::string name;
  std::string description;
  std::string kind;
  std::string scene_path;  // resolved against the experiment file's folder
  Scene scene;
  std::uint64_t seed = 1;
  int trials = 1;  // cycles per condition (operator, working condition, segment)
  // The parameter-override file applied to every scene (overrides.h), if any.
  std::string overrides_path;
  // The kind's own keys as its reader read them; null for a kind with none.
  core::ClonePtr<KindInput> input;

  // The kind's input as its struct; a program error for another kind's.
  template <class T>
  const T& Input() const {
    const T* p = dynamic_cast<const T*>(input.get());
    VAHF_CHECK(p != nullptr, "the input of experiment '" + name + "' (kind " + kind +
                                 ") read as another kind's");
    return *p;
  }
  template <class T>
  T& UpdInput() {
    return const_cast<T&>(std::as_const(*this).Input<T>());
  }
};

// A file named in `node`, relative to `experiment_path`'s folder (or
// absolute); an InputError at the node when no such file exists. `what`
// names the kind of file in the message ("scene").
std::string ResolvePath(const JsonNode& node, const std::string& experiment_path,
                        const char* what);

// Reading an experiment file (kinds/kind.h parses it: the common fields, then
// the keys of its kind through the kind's registered reader, which lives with
// the kind); errors name whichever file holds the fault.

// format, name, description, kind (one of `kinds`), seed and trials.
ExperimentFile ReadExperimentHeader(const JsonNode& root, const std::string& path,
                                    const std::vector<std::string>& kinds);
// "scene": the file it names, loaded.
void ReadExperimentScene(const JsonNode& root, const std::string& path,
                         ExperimentFile* e);
// "scene", "experiment", "lab", "overrides" or "synthetic" by the document's "format"
// field; an InputError naming `file` otherwise.
std::string FormatOf(const nlohmann::json& document, const std::string& file);
// The same, reading the file.
std::string FileFormatOf(const std::string& path);

}  // namespace vahf::scene
