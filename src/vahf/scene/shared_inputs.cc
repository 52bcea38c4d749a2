#include "vahf/scene/shared_inputs.h"

#include <fmt/format.h>

#include "vahf/core/error.h"

namespace vahf::scene {

std::vector<OperatorEntry> ReadOperators(const JsonNode& node, const Scene& scene) {
  std::vector<OperatorEntry> out;
  const std::size_t n = node.ArraySize(1);
  for (std::size_t k = 0; k < n; ++k) {
    const JsonNode o = node.At(k);
    o.ExpectObject({"name", "sex", "height", "arm_length", "source"});
    OperatorEntry e;
    e.name = o.Required("name").String();
    e.sex = o.Required("sex").Choice({"male", "female"});
    // The bounds of the scene file's operator (scene_loader.cc).
    e.height = o.Required("height").InRange(1.0, 2.5);
    e.arm_length = o.Required("arm_length").InRange(0.3, 1.2);
    if (auto source = o.Optional("source")) e.source = source->String();
    const std::string reach = scene.params.reach.Violation(e.arm_length, e.height);
    if (!reach.empty()) o.Fail(reach);
    for (const OperatorEntry& other : out)
      if (other.name == e.name) o.Required("name").Fail("operator names must be unique");
    out.push_back(e);
  }
  return out;
}

FatigueDesign ReadFatigueObject(const JsonNode& f, const std::vector<std::string>& also) {
  std::vector<std::string> keys = {"duration_min", "segments", "pilot_cycles"};
  keys.insert(keys.end(), also.begin(), also.end());
  f.ExpectObject(keys);
  FatigueDesign out;
  if (auto d = f.Optional("duration_min")) out.duration_min = d->Positive();
  if (auto s = f.Optional("segments"))
    out.segments = static_cast<int>(s->Integer(1, 1000));
  if (auto p = f.Optional("pilot_cycles"))
    out.pilot_cycles = static_cast<int>(p->Integer(0, 10'000'000));
  return out;
}

FatigueDesign ReadFatigue(const JsonNode& root) {
  const auto f = root.Optional("fatigue");
  return f ? ReadFatigueObject(*f, {}) : FatigueDesign{};
}

const std::vector<std::string>& FitQuantities() {
  static const std::vector<std::string> kQuantities = {"assembly_time", "success_rate",
                                                       "eta", "lambda_c"};
  return kQuantities;
}

bool AtInstant(const std::string& quantity) {
  return quantity == "eta" || quantity == "lambda_c";
}

namespace {

// A target's instant: required of eta and lambda_c (the factors change over a
// trial; a value without its instant compares nothing), refused elsewhere.
void ReadInstant(const JsonNode& node, FitTarget* t) {
  if (!AtInstant(t->quantity)) {
    if (auto instant = node.Optional("instant"))
      instant->Fail("only eta and lambda_c are read at an instant");
    return;
  }
  t->instant = node.Required("instant").NonNegative();  // finite, s from the start
  if (t->segment > 0)
    node.Required("segment").Fail(
        "eta and lambda_c at an instant are read from the lab operators' trials, "
        "not from a segment of the hour of work");
}

}  // namespace

std::vector<FitTarget> ReadTargets(const JsonNode& list, const Scene& scene,
                                   bool margin) {
  std::vector<FitTarget> out;
  const std::size_t m = list.ArraySize(1);
  for (std::size_t k = 0; k < m; ++k) {
    const JsonNode node = list.At(k);
    if (margin) {
      node.ExpectObject(
          {"quantity", "part", "by", "segment", "condition", "instant", "margin"});
    } else {
      node.ExpectObject(
          {"quantity", "part", "by", "segment", "condition", "instant", "variance"});
    }
    FitTarget t;
    t.pointer = node.path();
    t.quantity = node.Required("quantity").Choice(FitQuantities());
    std::vector<std::string> parts = {"all"};
    for (int index : scene.sequence) parts.push_back(scene.parts[index].name);
    t.part = node.Required("part").Choice(parts);
    if (auto by = node.Optional("by")) {
      const std::string b = by->Choice({"operator", "repetition", "all"});
      t.by_operator = b == "operator";
      t.by_repetition = b == "repetition";
    }
    if (auto segment = node.Optional("segment"))
      t.segment = static_cast<int>(segment->Integer(1, 1000));
    if (auto condition = node.Optional("condition")) {
      t.condition = condition->String();
      if (t.condition.empty())
        condition->Fail("names the lab's condition; leave the key out to read any");
    }
    if (t.segment > 0 && t.by_operator)
      node.Required("by").Fail("a segment's value is the lab's over all operators");
    if (t.segment > 0 && t.by_repetition)
      node.Required("by").Fail(
          "a segment's value is the lab's over the hour of work, which has no "
          "repetitions");
    ReadInstant(node, &t);
    if (auto variance = node.Optional("variance")) {
      t.pooled_variance = variance->Choice({"own", "pooled"}) == "pooled";
      if (t.pooled_variance && !t.by_operator)
        variance->Fail(
            "pools the variances of one target per operator: needs \"by\": "
            "\"operator\"");
      if (t.pooled_variance && t.quantity == "success_rate")
        variance->Fail(
            "a rate's variance is binomial, p (1 - p) / n, from its own "
            "counts: only a mean (assembly_time, eta, lambda_c) pools");
    }
    // A margin is in the quantity's unit: at most an hour for a time, 1 for a
    // rate, eta or lambda_c.
    if (margin)
      t.margin =
          node.Required("margin").InRange(0, t.quantity == "assembly_time" ? 3600 : 1);
    if (margin && !(t.margin > 0)) node.Required("margin").Fail("must be > 0");
    out.push_back(t);
  }
  return out;
}

void CheckSegments(const std::vector<FitTarget>& targets, const FatigueDesign& fatigue,
                   const std::string& path) {
  for (const FitTarget& t : targets)
    if (t.segment > fatigue.segments)
      throw InputError(
          path, t.pointer + "/segment", std::to_string(t.segment),
          fmt::format("the fatigue design has {} segments", fatigue.segments));
}

}  // namespace vahf::scene
