// A parameter declared by the code that reads it (a contact model's own
// keys), so that the parameter table (scene) lists and reads it without a row
// of its own, and the values a scene sets for such parameters.
#pragma once

#include <map>
#include <string>

namespace vahf::core {

// Every number has finite bounds [lo, hi]: a value the code cannot honour
// (one that overflows its arithmetic or stalls its integration) is refused
// when the file is read, not met in the middle of a run.
enum class ParamRule {
  kClosed,     // lo <= x <= hi
  kOpenBelow,  // lo < x <= hi (lo is usually 0: "positive")
  kCount,      // an integer, lo <= n <= hi
  kChoice,     // one of the table's `choices` (lo, hi unused)
};

// One numeric parameter: its key under its group, unit, rule (kClosed,
// kOpenBelow or kCount: a count's bounds and default are integers), bounds,
// default and the one line `vahf params` prints. Declare it once (an inline
// constexpr beside the code that reads it): two users of one key share the
// object.
struct ParamDecl {
  const char* key;
  const char* unit;
  ParamRule rule;
  double lo, hi;
  double default_value;
  const char* meaning;
};

// The values a scene sets for declared parameters; a parameter it does not
// set reads as its declaration's default. Read when a model is built, never
// on the hot path.
class ParamValues {
 public:
  double Get(const ParamDecl& decl) const {
    const auto it = values_.find(decl.key);
    return it == values_.end() ? decl.default_value : it->second;
  }
  // A count's value (kCount): stored as a double, exact for any integer
  // below 2^53, so the cast gives back the integer the scene set.
  int Count(const ParamDecl& decl) const { return static_cast<int>(Get(decl)); }
  // The value to write through (the parameter table's accessor): the default
  // until written.
  double& Upd(const ParamDecl& decl) {
    return values_.try_emplace(decl.key, decl.default_value).first->second;
  }

 private:
  std::map<std::string, double> values_;
};

}  // namespace vahf::core
