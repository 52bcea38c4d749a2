// Loads and validates a scene file (docs/scene-format.md). Any violation is one
// vahf::InputError naming the file, the JSON path, the value and the rule.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "vahf/scene/scene.h"

namespace vahf::scene {

inline constexpr const char* kSceneFormat = "vahf-scene/1";

Scene LoadScene(const std::string& path);

// Validates an already parsed document; `file` names it in messages.
Scene ParseScene(const nlohmann::json& document, const std::string& file);

// A human-readable account of what a scene holds (`vahf check`).
std::string DescribeScene(const Scene& scene);

// The rules that tie a scene's parameters together (the sight and glance
// plateaus' order, D1 < D2 < D3 for its operator): the first one `scene`
// breaks, or empty. The loader applies them to a file's values; whatever
// changes parameters after loading (an experiment's settings, a calibration's
// trial values) applies them again.
std::string ParameterViolation(const Scene& scene);

// The size rules of that list: the moving parts' contact shells and, under the
// resolving contact model, every part's rims stay countable
// (contact::kMaxShellPoints, kMaxRimPoints), checked before anything is made.
std::string SizeViolation(const Scene& scene);
// Throws its violation as an InputError at the scene file's
// /parameters/contact: the loader's and the trial model builder's check.
void RequireCountableSizes(const Scene& scene);

}  // namespace vahf::scene
