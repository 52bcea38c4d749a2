// Reads a JSON document field by field, keeping the JSON pointer of each node
// so that any error names the file, the path, the value and the rule
// (vahf::InputError). Used by the scene and experiment loaders.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace vahf::scene {

// Parses a file as JSON; a syntax error or an unreadable file is an InputError
// naming the line and column.
nlohmann::json ReadJsonFile(const std::string& path);

class JsonNode {
 public:
  JsonNode(const nlohmann::json& json, const std::string& file, std::string path = "");

  const std::string& path() const { return path_; }
  const std::string& file() const { return *file_; }
  const nlohmann::json& json() const { return *json_; }

  // Throws InputError at this node with `rule`.
  [[noreturn]] void Fail(const std::string& rule) const;

  // Objects. Every key must be one of `allowed` (an unknown key is usually a
  // typo: the error suggests the nearest allowed key).
  void ExpectObject(std::initializer_list<const char*> allowed) const;
  void ExpectObject(const std::vector<std::string>& allowed) const;
  JsonNode Required(const std::string& key) const;
  std::optional<JsonNode> Optional(const std::string& key) const;

  // Arrays.
  std::size_t ArraySize(std::size_t min_size = 0) const;
  JsonNode At(std::size_t index) const;

  // Scalars. Numbers must be finite.
  double Number() const;
  double Positive() const;     // > 0
  double NonNegative() const;  // >= 0
  double InRange(double lo, double hi) const;  // lo <= x <= hi
  std::int64_t Integer(std::int64_t min, std::int64_t max) const;
  std::uint64_t Unsigned() const;
  std::string String() const;
  std::string Choice(const std::vector<std::string>& choices) const;
  bool Boolean() const;
  Eigen::Vector3d Vector3() const;
  Eigen::Vector2d Vector2() const;

  // The value as the message shows it (compact JSON, shortened).
  std::string ValueText() const;

 private:
  const nlohmann::json* json_;
  const std::string* file_;
  std::string path_;
};

// Escapes a key for a JSON pointer (RFC 6901).
std::string PointerToken(const std::string& key);

}  // namespace vahf::scene
