// A 4 cm aluminium block falling freely from 1 m, with no operator and no
// visibility (tests only): its scene document with the test's simulation
// parameters.
#pragma once

#include <nlohmann/json.hpp>

namespace vahf::testing {

inline nlohmann::json FreeFallScene(const nlohmann::json& simulation) {
  return {{"format", "vahf-scene/1"},
          {"name", "fall"},
          {"operator",
           {{"height", 1.75},
            {"arm_length", 0.74},
            {"position", {0.0, -0.35}},
            {"facing_deg", 90}}},
          {"parts",
           {{{"name", "block"},
             {"role", "assembling"},
             {"geometry", {{"type", "box"}, {"size", {0.04, 0.04, 0.04}}}},
             {"density", 2700},
             {"friction", 0.2},
             {"pose", {{"position", {0.0, 0.0, 1.0}}}},
             {"target", {{"position", {0.0, 0.0, -5.0}}}}}}},
          {"sequence", {"block"}},
          {"parameters",
           {{"guidance", {{"mode", "none"}}},
            {"visibility", {{"mode", "off"}}},
            {"simulation", simulation}}}};
}

}  // namespace vahf::testing
