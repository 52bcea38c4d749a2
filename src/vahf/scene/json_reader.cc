#include "vahf/scene/json_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "vahf/core/error.h"

namespace vahf::scene {
namespace {

std::size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string TypeName(const nlohmann::json& j) {
  if (j.is_number()) return "number";
  return j.type_name();
}

// Compact JSON for a message, shortened in the middle so that both ends stay
// readable (the end of a long path is its file name, the part a user needs);
// non-finite numbers (which JSON text cannot hold but a document built in
// code can) are shown as nan or inf rather than nlohmann's "null".
std::string Shown(const nlohmann::json& j) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) {
    const double v = j.get<double>();
    return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
  }
  constexpr std::size_t kMax = 100, kHead = 30, kTail = kMax - kHead - 3;
  const std::string text = j.dump();
  if (text.size() <= kMax) return text;
  return text.substr(0, kHead) + "..." + text.substr(text.size() - kTail);
}

std::string Joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

}  // namespace

nlohmann::json ReadJsonFile(const std::string& path) {
  if (std::filesystem::is_directory(path))
    throw InputError(path, "", "", "is a directory, not a JSON file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "", "cannot open the file for reading");
  std::stringstream buffer;
  buffer << in.rdbuf();
  try {
    return nlohmann::json::parse(buffer.str());
  } catch (const nlohmann::json::parse_error& e) {
    // e.what() carries "line L, column C". NaN and Infinity land here as an
    // invalid literal: say why, since other tools write them.
    const std::string what = e.what();
    const bool literal = what.find("invalid literal") != std::string::npos;
    throw InputError(path, "", "",
                     fmt::format("not valid JSON: {}{}", what,
                                 literal ? " (NaN and Infinity are not JSON numbers)" : ""));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path, "", "", fmt::format("not valid JSON: {}", e.what()));
  }
}

std::string PointerToken(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

JsonNode::JsonNode(const nlohmann::json& json, const std::string& file, std::string path)
    : json_(&json), file_(&file), path_(std::move(path)) {}

std::string JsonNode::ValueText() const { return Shown(*json_); }

void JsonNode::Fail(const std::string& rule) const {
  throw InputError(*file_, path_.empty() ? "/" : path_, ValueText(), rule);
}

void JsonNode::ExpectObject(std::initializer_list<const char*> allowed) const {
  ExpectObject(std::vector<std::string>(allowed.begin(), allowed.end()));
}

void JsonNode::ExpectObject(const std::vector<std::string>& allowed) const {
  if (!json_->is_object()) Fail("must be an object, not a " + TypeName(*json_));
  for (const auto& item : json_->items()) {
    if (std::find(allowed.begin(), allowed.end(), item.key()) != allowed.end()) continue;
    std::string nearest;
    std::size_t best = 3;  // suggest only close matches
    for (const auto& k : allowed) {
      const std::size_t d = EditDistance(item.key(), k);
      if (d < best) best = d, nearest = k;
    }
    const std::string hint =
        nearest.empty() ? "known keys: " + Joined(allowed) : "did you mean '" + nearest + "'?";
    throw InputError(*file_, path_ + "/" + PointerToken(item.key()), Shown(item.value()),
                     "unknown key '" + item.key() + "' (" + hint + ")");
  }
}

JsonNode JsonNode::Required(const std::string& key) const {
  if (!json_->is_object()) Fail("must be an object, not a " + TypeName(*json_));
  const auto it = json_->find(key);
  if (it == json_->end())
    throw InputError(*file_, path_ + "/" + PointerToken(key), "(missing)",
                     "required field '" + key + "' is missing");
  return JsonNode(*it, *file_, path_ + "/" + PointerToken(key));
}

std::optional<JsonNode> JsonNode::Optional(const std::string& key) const {
  if (!json_->is_object()) Fail("must be an object, not a " + TypeName(*json_));
  const auto it = json_->find(key);
  if (it == json_->end()) return std::nullopt;
  return JsonNode(*it, *file_, path_ + "/" + PointerToken(key));
}

std::size_t JsonNode::ArraySize(std::size_t min_size) const {
  if (!json_->is_array()) Fail("must be an array, not a " + TypeName(*json_));
  if (json_->size() < min_size)
    Fail(fmt::format("must have at least {} element{}", min_size, min_size == 1 ? "" : "s"));
  return json_->size();
}

JsonNode JsonNode::At(std::size_t index) const {
  return JsonNode((*json_)[index], *file_, path_ + "/" + std::to_string(index));
}

double JsonNode::Number() const {
  if (!json_->is_number()) Fail("must be a number, not a " + TypeName(*json_));
  const double v = json_->get<double>();
  if (!std::isfinite(v)) Fail("must be a finite number");
  return v;
}

double JsonNode::Positive() const {
  const double v = Number();
  if (!(v > 0)) Fail("must be > 0");
  return v;
}

double JsonNode::NonNegative() const {
  const double v = Number();
  if (!(v >= 0)) Fail("must be >= 0");
  return v;
}

double JsonNode::InRange(double lo, double hi) const {
  const double v = Number();
  if (!(v >= lo && v <= hi)) Fail(fmt::format("must lie in [{}, {}]", lo, hi));
  return v;
}

std::int64_t JsonNode::Integer(std::int64_t min, std::int64_t max) const {
  if (!json_->is_number_integer()) Fail("must be an integer, not a " + TypeName(*json_));
  if (json_->is_number_unsigned() &&
      json_->get<std::uint64_t>() > static_cast<std::uint64_t>(max))
    Fail(fmt::format("must lie in [{}, {}]", min, max));
  const std::int64_t v = json_->get<std::int64_t>();
  if (v < min || v > max) Fail(fmt::format("must lie in [{}, {}]", min, max));
  return v;
}

std::uint64_t JsonNode::Unsigned() const {
  if (!json_->is_number_integer() || (!json_->is_number_unsigned() &&
                                      json_->get<std::int64_t>() < 0))
    Fail("must be a non-negative integer");
  return json_->get<std::uint64_t>();
}

std::string JsonNode::String() const {
  if (!json_->is_string()) Fail("must be a string, not a " + TypeName(*json_));
  return json_->get<std::string>();
}

std::string JsonNode::Choice(const std::vector<std::string>& choices) const {
  const std::string s = String();
  if (std::find(choices.begin(), choices.end(), s) == choices.end())
    Fail("must be one of: " + Joined(choices));
  return s;
}

bool JsonNode::Boolean() const {
  if (!json_->is_boolean()) Fail("must be true or false, not a " + TypeName(*json_));
  return json_->get<bool>();
}

Eigen::Vector3d JsonNode::Vector3() const {
  if (!json_->is_array() || json_->size() != 3) Fail("must be an array of 3 numbers");
  return {At(0).Number(), At(1).Number(), At(2).Number()};
}

Eigen::Vector2d JsonNode::Vector2() const {
  if (!json_->is_array() || json_->size() != 2) Fail("must be an array of 2 numbers");
  return {At(0).Number(), At(1).Number()};
}

}  // namespace vahf::scene
