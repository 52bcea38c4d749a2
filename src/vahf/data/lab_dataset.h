// A lab dataset (docs/lab-data.md): what a lab records in the paper's Sec. 5
// — assembly trials, fatigue segments, reported statistics and sensor tracks —
// as a folder with a manifest (format "vahf-lab/1") naming CSV files with
// their units and provenance. Loaded into SI units (segment bounds in
// minutes); any violation of the format is one vahf::InputError naming the
// file, "line L, column NAME" (or the manifest's JSON pointer), the value and
// the rule.
#pragma once

#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "vahf/data/track.h"

namespace vahf::data {

// One assembly trial (trials.csv).
struct LabTrial {
  std::string operator_id;  // "male 1"
  std::string sex;          // "male" or "female"
  double height = 0;        // stature, m
  double arm_length = 0;    // m
  std::string condition;    // the lab's working condition ("good", "standard")
  std::string part;         // a part of the scene, or "all" for the whole sequence
  int repetition = 0;       // >= 1
  double time = std::numeric_limits<double>::quiet_NaN();  // s; NaN: not recorded
  int success = 0;                                         // 0 or 1
  std::string source, note;                                // free text, may be empty
  int line = 0;                                            // in its file, for messages
};

// Fatigue counts over one segment of continuous work (segments.csv; Sec. 5.4).
struct LabSegment {
  int segment = 0;       // 1, 2, ... within its condition
  double start_min = 0;  // min from the start of work
  double end_min = 0;    // min
  int attempts = 0;      // >= 1
  int successes = 0;     // 0 .. attempts
  double mean_time = std::numeric_limits<double>::quiet_NaN();  // s, of the successes
  std::string condition;  // the series ("real", "virtual"); empty: one series
  std::string source, note;
  int line = 0;
};

// A statistic reported without the samples behind it (summaries.csv).
struct LabSummary {
  std::string quantity;   // assembly_time (s), success_rate, eta, lambda_c, V, f, r, g
  std::string part;       // may be empty; "all": the whole assembly
  std::string condition;  // may be empty
  int segment = 0;        // 0: none
  double instant = std::numeric_limits<double>::quiet_NaN();  // s; NaN: none
  double value = 0;  // in the quantity's unit (s or 1)
  double sd = std::numeric_limits<double>::quiet_NaN();           // NaN: not given
  int n = 0;                                                      // 0: not given
  double uncertainty = std::numeric_limits<double>::quiet_NaN();  // reading half-width
  std::string source;  // the sentence, table or figure it comes from
  std::string note;
  int line = 0;
};

struct LabDataset {
  std::string file;  // the manifest, as given
  std::string
      folder;  // the manifest's folder, which the file names below are relative to
  std::string name;
  std::string description;
  nlohmann::json provenance;  // an object with a non-empty string "source"
  // The tables' files as the manifest names them; empty: the dataset has none.
  std::string trials_file, segments_file, summaries_file;
  std::vector<LabTrial> trials;
  std::vector<LabSegment> segments;
  std::vector<LabSummary> summaries;
  // Each track's `file` is the manifest's name joined to `folder`.
  std::vector<SensorTrack> tracks;
};

// The quantities summaries.csv accepts; all but assembly_time are in [0, 1].
const std::vector<std::string>& LabQuantities();

// Loads the manifest and every file it names, checking every rule.
LabDataset LoadLabDataset(const std::string& manifest_path);
// The same for a manifest already parsed from `manifest_path`.
LabDataset ParseLabDataset(const nlohmann::json& manifest,
                           const std::string& manifest_path);

// The manifest and every file it names (its tables, then its tracks), as a
// run that reads the dataset records them (manifest.json) and checks them
// before it resumes (the journal's identity).
std::vector<std::string> LabDatasetFiles(const LabDataset& dataset);

// Writes `dataset` into `folder` (created if need be): the CSV files, in SI
// units (segment bounds in minutes) with numbers in their shortest round-trip
// form, then dataset.json, each file atomically. The files are checked by
// the loader's rules before any is written, so a dataset the loader would
// refuse is refused here (InputError) and nothing is written;
// LoadLabDataset(folder + "/dataset.json") then equals `dataset` but for
// file paths and line numbers. Tables without rows are left out; an empty
// file name becomes "trials.csv", "segments.csv", "summaries.csv"; a track's
// file keeps its name relative to dataset.folder (tracks/N.csv if it has none).
void WriteLabDataset(const LabDataset& dataset, const std::string& folder);

// What `vahf check` prints: name, provenance, and counts of trials,
// operators, parts, conditions, segments, summaries, tracks and samples.
std::string DescribeLabDataset(const LabDataset& dataset);

}  // namespace vahf::data
