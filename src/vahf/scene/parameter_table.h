// The one table of every model parameter: its place in the scene file
// ("parameters"/GROUP/KEY), unit, rule, meaning and default. The loader reads
// overrides through it, `vahf params` prints it, and docs/parameters.md is its
// output, checked by a test.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "vahf/core/param_decl.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/parameters.h"

namespace vahf::scene {

// Every number has finite bounds (core/param_decl.h).
using ParamRule = core::ParamRule;

struct ParamSpec {
  const char* group;
  const char* key;
  const char* unit;
  ParamRule rule;
  double lo, hi;
  const char* meaning;
  // Exactly one accessor is set, by the kind of value. A real one may carry
  // its declaration (a contact model's key in ContactParams::values, a
  // stepper's in SimulationParams::stepper_values): a declared count
  // (kCount) is read through it too, stored as an exact double.
  std::function<double&(Parameters&)> real = nullptr;
  int& (*count)(Parameters&) = nullptr;
  std::string& (*text)(Parameters&) = nullptr;
  std::vector<std::string> choices = {};
};

const std::vector<ParamSpec>& ParameterTable();

// "group/key": how `vahf params`, docs/parameters.md and an experiment's
// parameter overrides name a parameter.
std::string ParamName(const ParamSpec& spec);
// Every parameter's name, in table order.
std::vector<std::string> ParamNames();
// The spec of "group/key", or nullptr.
const ParamSpec* FindParam(const std::string& name);

// Reads `value` into `p` by the spec's rule: the InputError of a value that
// breaks it names the node (the scene loader's and the experiment files' one
// reader of parameter values).
void ReadParamValue(const ParamSpec& spec, const JsonNode& value, Parameters* p);

// Its rule as `vahf params` states it: "in [lo, hi]", "in (lo, hi]",
// "integer in [lo, hi]" or the names of its choices.
std::string RuleText(const ParamSpec& spec);

// The value of a parameter in `p`, as text.
std::string ParamValueText(const ParamSpec& spec, const Parameters& p);

// A Markdown table of every parameter with its default.
std::string ParameterTableMarkdown();

}  // namespace vahf::scene
