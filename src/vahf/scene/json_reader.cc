#include "vahf/scene/json_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <set>

#include "vahf/core/error.h"
#include "vahf/core/whole_file.h"

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

// A scalar as compact JSON; non-finite numbers (which JSON text cannot hold
// but a document built in code can) as nan or inf rather than nlohmann's
// "null", and invalid UTF-8 (likewise only from code) replaced, not thrown.
std::string ScalarText(const nlohmann::json& j) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) {
    const double v = j.get<double>();
    return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
  }
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

constexpr std::size_t kShownMax = 100;  // characters of a value in a message
constexpr int kShownDepth = 4;          // container levels written out

// Appends j as compact JSON to `out`, writing no further element once `out`
// is longer than `limit`; containers below `depth` levels are written as
// [...] or {...}. Recursion is bounded by `depth`, not by j's nesting (a
// document built in code may nest without limit: nlohmann's dump would
// recurse through all of it and overflow the stack).
void AppendBounded(const nlohmann::json& j, int depth, std::size_t limit,
                   std::string& out) {
  if (!j.is_structured()) {
    out += ScalarText(j);
    return;
  }
  const bool array = j.is_array();
  if (depth == 0 && !j.empty()) {
    out += array ? "[...]" : "{...}";
    return;
  }
  out += array ? '[' : '{';
  for (auto it = j.begin(); it != j.end() && out.size() <= limit; ++it) {
    if (it != j.begin()) out += ',';
    if (!array) out += ScalarText(it.key()) + ':';
    AppendBounded(*it, depth - 1, limit, out);
  }
  out += array ? ']' : '}';
}

// The value for a message, at most kShownMax characters. A long scalar is
// shortened in the middle so that both ends stay readable (the end of a long
// path is its file name, the part a user needs); a long container keeps its
// start.
std::string Shown(const nlohmann::json& j) {
  std::string text;
  AppendBounded(j, kShownDepth, kShownMax, text);
  if (text.size() <= kShownMax) return text;
  if (j.is_structured()) return text.substr(0, kShownMax - 3) + "...";
  constexpr std::size_t kHead = 30, kTail = kShownMax - kHead - 3;
  return text.substr(0, kHead) + "..." + text.substr(text.size() - kTail);
}

// Checks the structure of a document as nlohmann's parser builds it, through
// the parser's callback (called at every key, value and container start and
// end, with the nesting depth): a key repeated within one object, and a
// container nested deeper than kMaxJsonDepth, throw an InputError naming the
// JSON pointer. The callback is the simplest robust hook: it sees the events
// in document order before the tree is complete, so a deep document is
// refused before anything recursive could touch it (nlohmann's parser itself
// is iterative, and so is its destructor since 3.10), and the tree is still
// built by nlohmann (a SAX handler of our own would have to build it again).
class StructureCheck {
 public:
  explicit StructureCheck(const std::string& file) : file_(file) {}

  bool operator()(int depth, nlohmann::json::parse_event_t event,
                  nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        // `depth` counts the enclosing containers.
        if (depth + 1 > kMaxJsonDepth)
          throw InputError(
              file_, Pointer(), "",
              fmt::format("nested deeper than {} levels of arrays and objects "
                          "(the most a vahf file may hold)",
                          kMaxJsonDepth));
        levels_.push_back({event == Event::object_start});
        break;
      case Event::key: {
        Level& object = levels_.back();
        object.key = parsed.get<std::string>();
        if (!object.keys.insert(object.key).second)
          throw InputError(
              file_, Pointer(), "",
              fmt::format("duplicate key {} (a key appears at most once in an "
                          "object)",
                          ScalarText(parsed)));
        break;
      }
      case Event::object_end:
      case Event::array_end:
        levels_.pop_back();
        NextElement();
        break;
      case Event::value:
        NextElement();
        break;
    }
    return true;  // keep everything
  }

 private:
  struct Level {
    bool object;
    std::set<std::string> keys = {};  // an object's keys so far
    std::string key = {};             // an object's current key
    std::size_t index = 0;            // an array's current element
  };

  // After a value or a container ends: the enclosing array's next element.
  void NextElement() {
    if (!levels_.empty() && !levels_.back().object) ++levels_.back().index;
  }

  // The JSON pointer of the current position: the current key or element of
  // every enclosing container.
  std::string Pointer() const {
    std::string out;
    for (const Level& l : levels_)
      out += "/" + (l.object ? PointerToken(l.key) : std::to_string(l.index));
    return out.empty() ? "/" : out;
  }

  const std::string& file_;
  std::vector<Level> levels_;
};

std::string Joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

}  // namespace

nlohmann::json ReadJsonFile(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw InputError(path, "", "", "is a directory, not a JSON file");
  const std::optional<std::string> text = ReadWholeFile(path);
  if (!text) throw InputError(path, "", "", "cannot open the file for reading");
  return ParseJsonText(*text, path);
}

nlohmann::json ParseJsonText(const std::string& text, const std::string& file) {
  StructureCheck check(file);
  try {
    return nlohmann::json::parse(text, std::ref(check));
  } catch (const nlohmann::json::parse_error& e) {
    // e.what() carries "line L, column C". NaN and Infinity land here as an
    // invalid literal: say why, since other tools write them.
    const std::string what = e.what();
    const bool literal = what.find("invalid literal") != std::string::npos;
    throw InputError(
        file, "", "",
        fmt::format("not valid JSON: {}{}", what,
                    literal ? " (NaN and Infinity are not JSON numbers)" : ""));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file, "", "", fmt::format("not valid JSON: {}", e.what()));
  }
}

std::string PointerToken(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else if (static_cast<unsigned char>(c) < 0x20)
      out += fmt::format("\\u{:04x}", int{c});
    else
      out += c;
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
    const std::string hint = nearest.empty() ? "known keys: " + Joined(allowed)
                                             : "did you mean '" + nearest + "'?";
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
    Fail(fmt::format("must have at least {} element{}", min_size,
                     min_size == 1 ? "" : "s"));
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
  if (!(v >= lo && v <= hi))
    Fail(fmt::format("must lie in [{}, {}]", NumberText(lo), NumberText(hi)));
  return v;
}

std::string NumberText(double x) {
  const double a = std::fabs(x);
  if (a == 0 || (a >= 1e-2 && a < 1e5)) return fmt::format("{}", x);
  for (int digits = 0;; ++digits) {
    const std::string s = fmt::format("{:.{}e}", x, digits);
    // strtod, not stod: stod throws on a subnormal (1e-310) it reads back.
    if (std::strtod(s.c_str(), nullptr) != x && digits < 17) continue;
    const std::size_t e = s.find('e');
    std::string exponent = s.substr(e + 1);  // "-04", "+05"
    const bool negative = exponent[0] == '-';
    exponent = exponent.substr(1);
    while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
    return s.substr(0, e) + "e" + (negative ? "-" : "") + exponent;
  }
}

double JsonNode::InOpenClosed(double lo, double hi) const {
  const double v = Number();
  if (!(v > lo && v <= hi))
    Fail(fmt::format("must lie in ({}, {}]", NumberText(lo), NumberText(hi)));
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
  if (!json_->is_number_integer() ||
      (!json_->is_number_unsigned() && json_->get<std::int64_t>() < 0))
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

Eigen::Vector3d JsonNode::Vector3(double lo, double hi) const {
  if (!json_->is_array() || json_->size() != 3) Fail("must be an array of 3 numbers");
  return {At(0).InRange(lo, hi), At(1).InRange(lo, hi), At(2).InRange(lo, hi)};
}

Eigen::Vector2d JsonNode::Vector2(double lo, double hi) const {
  if (!json_->is_array() || json_->size() != 2) Fail("must be an array of 2 numbers");
  return {At(0).InRange(lo, hi), At(1).InRange(lo, hi)};
}

}  // namespace vahf::scene
