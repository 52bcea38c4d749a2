// The parts of an experiment file that several kinds read the same way: an
// operator (assembly_time's operators, a synthetic lab's), the hour of work
// in segments (fatigue, and the segment targets of calibrate and compare) and
// a lab summary to fit or compare (calibrate, compare).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "vahf/scene/json_reader.h"
#include "vahf/scene/scene.h"

namespace vahf::scene {

// An operator of an assembly_time experiment: the scene's operator with this
// stature and arm length (standing where the scene's operator stands).
struct OperatorEntry {
  std::string name;
  std::string sex;        // "male" or "female"
  double height = 0;      // m
  double arm_length = 0;  // m
  std::string source;     // where the dimensions come from
};

// Operators as an experiment file lists them (assembly_time's "operators":
// name, sex, height, arm_length, source), checked against the scene's reach
// rule; names unique.
std::vector<OperatorEntry> ReadOperators(const JsonNode& node, const Scene& scene);

// One hour of continuous cycles in segments (fatigue, paper Sec. 5.4).
struct FatigueDesign {
  double duration_min = 60.0;
  int segments = 4;
  int pilot_cycles = 0;  // cycles from A = 0 that measure the work rate; 0: `trials`
};

// "fatigue" of the file's root object; the defaults when it has none.
FatigueDesign ReadFatigue(const JsonNode& root);
// A fatigue object {"duration_min", "segments", "pilot_cycles"}, which may
// also hold the keys `also` (read by the caller).
FatigueDesign ReadFatigueObject(const JsonNode& f, const std::vector<std::string>& also);

// A lab summary a calibration fits (calibrate/targets.h): a quantity of one
// part ("all": whole cycles), over all the lab's operators or each one's.
struct FitTarget {
  std::string quantity;      // one of FitQuantities()
  std::string part;          // a part of the scene's sequence, or "all"
  bool by_operator = false;  // one target per lab operator instead of one over all
  std::string pointer;       // where the experiment file states it
  // compare: the equivalence margin, in the quantity's unit (s, or 1 for a
  // rate): virtual and lab agree when their difference is shown within it.
  double margin = 0;
  // A segment of the hour of work (1-based; 0: none): the lab's value of that
  // segment, against a fatigue design's (FatigueDesign of the same file).
  int segment = 0;
  // The lab's condition (series) to read, e.g. "real"; empty: any.
  std::string condition;
  // eta and lambda_c (AtInstant): the instant, s from the trial's start, at
  // which the factor is read (calibrate/targets.h); NaN for the others.
  double instant = std::numeric_limits<double>::quiet_NaN();
  // One target per repetition the lab's trials record (1, 2, ...), over all
  // operators: the learning curve (human/learning.h).
  bool by_repetition = false;
  // calibrate, a mean of one operator's trials (by operator; assembly_time,
  // eta, lambda_c): each operator's variance s_o^2 / n_o uses the pooled
  // s^2 of all the spec's operators instead of their own s_o^2
  // (calibrate::PoolVariances), on the lab's side and the virtual one.
  bool pooled_variance = false;
};

// The quantities a target may name, the one list (calibrate::TargetQuantities):
// assembly_time, success_rate, and the vision and comfort coefficients eta
// (Eq. 2) and lambda_c (Eq. 3) at an instant of the trial.
const std::vector<std::string>& FitQuantities();

// Whether `quantity` is read at an instant of a trial (eta, lambda_c).
bool AtInstant(const std::string& quantity);

// Lab summaries as a calibration's targets or a comparison's quantities name
// them: quantity, part (of the scene's sequence, or "all"), by ("operator",
// "repetition" or "all"), segment (1-based) and condition (the lab's, not empty: without
// it, any), for eta and lambda_c the instant (s, finite and >= 0; no other quantity takes
// one, and they take no segment), and for a comparison
// (`margin`) the equivalence margin.
std::vector<FitTarget> ReadTargets(const JsonNode& list, const Scene& scene, bool margin);

// Segment targets or quantities lie within the fatigue design's hour; an
// InputError naming `path` otherwise.
void CheckSegments(const std::vector<FitTarget>& targets, const FatigueDesign& fatigue,
                   const std::string& path);

}  // namespace vahf::scene
