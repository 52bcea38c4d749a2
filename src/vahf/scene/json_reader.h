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

// How deeply arrays and objects may nest in a vahf file (the root object is
// level 1; the deepest shipped files reach 6: a profile point of a scene,
// /parts/0/geometry/profile/0).
// A bound lets every recursive walk of a document (nlohmann's dump, copy and
// comparison recurse) run in bounded stack.
inline constexpr int kMaxJsonDepth = 64;

// Parses a file as JSON; a syntax error or an unreadable file is an InputError
// naming the line and column. So is a key that appears twice in one object
// (JSON leaves its meaning open, RFC 8259 Sec. 4; nlohmann keeps the last),
// and nesting deeper than kMaxJsonDepth: both are refused while parsing,
// naming the JSON pointer, before the rest of the document is read.
nlohmann::json ReadJsonFile(const std::string& path);

// The same, for text already read (`file` names it in errors).
nlohmann::json ParseJsonText(const std::string& text, const std::string& file);

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
  double Positive() const;                          // > 0
  double NonNegative() const;                       // >= 0
  double InRange(double lo, double hi) const;       // lo <= x <= hi
  double InOpenClosed(double lo, double hi) const;  // lo < x <= hi
  std::int64_t Integer(std::int64_t min, std::int64_t max) const;
  std::uint64_t Unsigned() const;
  std::string String() const;
  std::string Choice(const std::vector<std::string>& choices) const;
  bool Boolean() const;
  Eigen::Vector3d Vector3() const;
  Eigen::Vector2d Vector2() const;
  // Each component in [lo, hi]; an error names the component's pointer.
  Eigen::Vector3d Vector3(double lo, double hi) const;
  Eigen::Vector2d Vector2(double lo, double hi) const;

  // The value as the message shows it: compact JSON, at most 100 characters
  // (a long scalar keeps both ends, a container its start), containers
  // nested more than 4 deep shown as [...] or {...}: bounded whatever the
  // value's size and depth.
  std::string ValueText() const;

 private:
  const nlohmann::json* json_;
  const std::string* file_;
  std::string path_;
};

// A number as people write it, in rules, messages and labels: the shortest
// form that reads back exactly, scientific when small or large (0.5, 1000,
// 1e6, 1e-12, 2.5e-3).
std::string NumberText(double x);

// Escapes a key for a JSON pointer (RFC 6901), and a control character as
// \uXXXX so that a message naming the pointer stays on one line.
std::string PointerToken(const std::string& key);

}  // namespace vahf::scene
