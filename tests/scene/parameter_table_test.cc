// The parameter table: every entry has exactly one accessor, names are unique,
// defaults obey their own rules, and docs/parameters.md is the table's current
// output (regenerate with `vahf params > docs/parameters.md` after a change);
// the integrator accuracy lies in (0, 1), both ends excluded (Simbody asserts
// it; 1 once aborted a trial that `check` had passed).
#include "vahf/scene/parameter_table.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "vahf/core/error.h"
#include "vahf/scene/json_reader.h"

namespace vahf::scene {
namespace {

TEST(ParameterTable, WellFormed) {
  std::set<std::string> names;
  Parameters defaults;
  for (const ParamSpec& s : ParameterTable()) {
    const std::string name = std::string(s.group) + "/" + s.key;
    EXPECT_TRUE(names.insert(name).second) << "duplicate " << name;
    EXPECT_EQ((s.real != nullptr) + (s.count != nullptr) + (s.text != nullptr), 1) << name;
    if (s.real) {
      const double v = s.real(defaults);
      switch (s.rule) {
        case ParamRule::kPositive: EXPECT_GT(v, 0) << name; break;
        case ParamRule::kNonNegative: EXPECT_GE(v, 0) << name; break;
        case ParamRule::kUnit: EXPECT_TRUE(v >= 0 && v <= 1) << name; break;
        case ParamRule::kOpenUnit: EXPECT_TRUE(v > 0 && v < 1) << name; break;
        case ParamRule::kAngle: EXPECT_TRUE(v >= 0 && v <= 180) << name; break;
        default: ADD_FAILURE() << name << " has a rule for another kind of value";
      }
    }
    if (s.text) {
      EXPECT_EQ(s.rule, ParamRule::kChoice) << name;
      const std::string v = s.text(defaults);
      EXPECT_NE(std::find(s.choices.begin(), s.choices.end(), v), s.choices.end()) << name;
    }
  }
  EXPECT_GE(names.size(), 30u);
}

TEST(ParameterTable, AccessorsReachDistinctFields) {
  // Writing through one accessor changes that parameter only.
  for (const ParamSpec& s : ParameterTable()) {
    if (!s.real) continue;
    Parameters p;
    s.real(p) = 12345.0;
    for (const ParamSpec& other : ParameterTable()) {
      if (!other.real || &other == &s) continue;
      EXPECT_NE(other.real(p), 12345.0) << s.group << "/" << s.key << " aliases "
                                        << other.group << "/" << other.key;
    }
  }
}

TEST(ParameterTable, AccuracyLiesStrictlyBetweenZeroAndOne) {
  const ParamSpec* accuracy = FindParam("simulation/accuracy");
  ASSERT_NE(accuracy, nullptr);
  const std::string file = "scene.json";
  for (const double bad : {0.0, 1.0, 2.0, -1e-4}) {
    const nlohmann::json value = bad;
    Parameters p;
    try {
      ReadParamValue(*accuracy, JsonNode(value, file, "/parameters/simulation/accuracy"), &p);
      ADD_FAILURE() << "accuracy " << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.rule(), "must lie in (0, 1)") << bad;
    }
  }
  const nlohmann::json good = 0.999;
  Parameters p;
  ReadParamValue(*accuracy, JsonNode(good, file), &p);
  EXPECT_EQ(p.simulation.accuracy, 0.999);
  EXPECT_NE(ParameterTableMarkdown().find("| `simulation/accuracy` | 1 | in (0, 1) |"),
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
