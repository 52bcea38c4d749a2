// The parameter table: every entry has exactly one accessor, names are unique,
// defaults obey their own rules, every number has finite bounds that the
// reader enforces at both edges, and docs/parameters.md is the table's
// current output (regenerate with `vahf params > docs/parameters.md` after a
// change); the integrator accuracy lies inside (0, 1) (Simbody asserts it; 1
// once aborted a trial that `check` had passed).
#include "vahf/scene/parameter_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "vahf/contact/contact_registry.h"
#include "vahf/core/error.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/stepper_catalogue.h"

namespace vahf::scene {
namespace {

TEST(ParameterTable, WellFormed) {
  std::set<std::string> names;
  Parameters defaults;
  for (const ParamSpec& s : ParameterTable()) {
    const std::string name = std::string(s.group) + "/" + s.key;
    EXPECT_TRUE(names.insert(name).second) << "duplicate " << name;
    EXPECT_EQ((s.real != nullptr) + (s.count != nullptr) + (s.text != nullptr), 1)
        << name;
    if (s.real) {
      const double v = s.real(defaults);
      switch (s.rule) {
        case ParamRule::kClosed:
          EXPECT_TRUE(v >= s.lo && v <= s.hi) << name;
          break;
        case ParamRule::kOpenBelow:
          EXPECT_TRUE(v > s.lo && v <= s.hi) << name;
          break;
        case ParamRule::kCount:  // a declared count, stored as an exact double
          EXPECT_TRUE(v >= s.lo && v <= s.hi && v == std::floor(v)) << name;
          break;
        default:
          ADD_FAILURE() << name << " has a rule for another kind of value";
      }
    }
    if (s.count) {
      EXPECT_EQ(s.rule, ParamRule::kCount) << name;
      EXPECT_TRUE(s.count(defaults) >= s.lo && s.count(defaults) <= s.hi) << name;
    }
    if (s.rule != ParamRule::kChoice) {
      EXPECT_TRUE(std::isfinite(s.lo) && std::isfinite(s.hi) && s.lo < s.hi) << name;
    }
    if (s.text) {
      EXPECT_EQ(s.rule, ParamRule::kChoice) << name;
      const std::string v = s.text(defaults);
      EXPECT_NE(std::find(s.choices.begin(), s.choices.end(), v), s.choices.end())
          << name;
    }
  }
  EXPECT_GE(names.size(), 30u);
}

// Every declared key is a row of its group with its declaration's unit,
// rule, bounds and meaning, whose default is the declaration's and which
// reads into the ParamValues `values` returns.
void ExpectRowsOfTheirDeclarations(const std::vector<const core::ParamDecl*>& decls,
                                   const std::string& group,
                                   core::ParamValues& (*values)(Parameters&)) {
  ASSERT_FALSE(decls.empty()) << group;
  for (const core::ParamDecl* d : decls) {
    const ParamSpec* s = FindParam(group + "/" + d->key);
    ASSERT_NE(s, nullptr) << d->key;
    EXPECT_STREQ(s->unit, d->unit) << d->key;
    EXPECT_EQ(s->rule, d->rule) << d->key;
    EXPECT_EQ(s->lo, d->lo) << d->key;
    EXPECT_EQ(s->hi, d->hi) << d->key;
    EXPECT_STREQ(s->meaning, d->meaning) << d->key;
    Parameters p;
    EXPECT_EQ(s->real(p), d->default_value) << d->key;
    const nlohmann::json hi = d->rule == ParamRule::kCount
                                  ? nlohmann::json(static_cast<std::int64_t>(d->hi))
                                  : nlohmann::json(d->hi);
    ReadParamValue(*s, JsonNode(hi, "f.json", ""), &p);
    EXPECT_EQ(values(p).Get(*d), d->hi) << d->key;
    Parameters defaults;
    EXPECT_EQ(values(defaults).Get(*d), d->default_value) << d->key;
  }
}

TEST(ParameterTable, ContactModelKeysAreRowsOfTheirDeclarations) {
  ExpectRowsOfTheirDeclarations(
      contact::ContactModelParams(), "contact",
      [](Parameters& p) -> core::ParamValues& { return p.contact.values; });
}

// A stepper's settings (steppers.def) likewise, into
// SimulationParams::stepper_values; a count reads back as the integer set.
TEST(ParameterTable, StepperSettingsAreRowsOfTheirDeclarations) {
  ExpectRowsOfTheirDeclarations(
      StepperSettings(), "simulation",
      [](Parameters& p) -> core::ParamValues& { return p.simulation.stepper_values; });
  Parameters p;
  ReadParamValue(*FindParam("simulation/max_order"),
                 JsonNode(nlohmann::json(2), "f.json", ""), &p);
  EXPECT_EQ(p.simulation.stepper_values.Count(stepper_settings::max_order), 2);
  EXPECT_EQ(ParamValueText(*FindParam("simulation/jacobian_interval"), p), "51");
}

TEST(ParameterTable, AccessorsReachDistinctFields) {
  // Writing through one accessor changes that parameter only.
  for (const ParamSpec& s : ParameterTable()) {
    if (!s.real) continue;
    Parameters p;
    s.real(p) = 12345.0;
    for (const ParamSpec& other : ParameterTable()) {
      if (!other.real || &other == &s) continue;
      EXPECT_NE(other.real(p), 12345.0)
          << s.group << "/" << s.key << " aliases " << other.group << "/" << other.key;
    }
  }
}

// Every bound is enforced: the edge values are read (or refused, for an open
// lower edge), and a value just outside either edge is refused with the rule.
TEST(ParameterTable, BoundsAreEnforcedAtBothEdges) {
  const std::string file = "scene.json";
  const auto reads = [&](const ParamSpec& s, double x) {
    const nlohmann::json value = s.rule == ParamRule::kCount
                                     ? nlohmann::json(static_cast<std::int64_t>(x))
                                     : nlohmann::json(x);
    Parameters p;
    try {
      ReadParamValue(s, JsonNode(value, file, "/parameters/x"), &p);
      return true;
    } catch (const InputError& e) {
      EXPECT_NE(e.rule().find("must lie in"), std::string::npos) << e.what();
      return false;
    }
  };
  for (const ParamSpec& s : ParameterTable()) {
    const std::string name = ParamName(s);
    if (s.rule == ParamRule::kChoice) continue;
    const bool integer = s.rule == ParamRule::kCount;
    const double below = integer ? s.lo - 1 : std::nextafter(s.lo, -HUGE_VAL);
    const double above = integer ? s.hi + 1 : std::nextafter(s.hi, HUGE_VAL);
    EXPECT_FALSE(reads(s, below)) << name;
    EXPECT_EQ(reads(s, s.lo), s.rule != ParamRule::kOpenBelow) << name;
    EXPECT_TRUE(reads(s, s.hi)) << name;
    EXPECT_FALSE(reads(s, above)) << name;
    if (!integer) {
      EXPECT_FALSE(reads(s, 1e308)) << name;
    }
  }
}

TEST(ParameterTable, AccuracyLiesStrictlyBetweenZeroAndOne) {
  const ParamSpec* accuracy = FindParam("simulation/accuracy");
  ASSERT_NE(accuracy, nullptr);
  const std::string file = "scene.json";
  for (const double bad : {0.0, 1.0, 2.0, -1e-4, 1e-16}) {
    const nlohmann::json value = bad;
    Parameters p;
    try {
      ReadParamValue(*accuracy, JsonNode(value, file, "/parameters/simulation/accuracy"),
                     &p);
      ADD_FAILURE() << "accuracy " << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.rule(), "must lie in [1e-12, 0.5]") << bad;
    }
  }
  const nlohmann::json good = 0.5;
  Parameters p;
  ReadParamValue(*accuracy, JsonNode(good, file), &p);
  EXPECT_EQ(p.simulation.accuracy, 0.5);
  EXPECT_NE(
      ParameterTableMarkdown().find("| `simulation/accuracy` | 1 | in [1e-12, 0.5] |"),
      std::string::npos);
}

TEST(ParameterTable, DocsAreCurrent) {
  std::ifstream in(std::string(VAHF_SOURCE_DIR) + "/docs/parameters.md");
  ASSERT_TRUE(in) << "docs/parameters.md is missing";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find(ParameterTableMarkdown()), std::string::npos)
      << "docs/parameters.md is out of date: regenerate its table with `vahf params`";
}

}  // namespace
}  // namespace vahf::scene
