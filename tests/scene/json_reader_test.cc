// Tests of the JSON reader every vahf file goes through (scene/json_reader.h):
// a key repeated within one object is refused, naming the file, the JSON
// pointer and the key, wherever it sits (a key repeated in different objects
// is not a repeat); nesting is refused one level past kMaxJsonDepth, and
// 100 000 nested arrays (which once overflowed the stack in an error message)
// give one InputError; a value in a message is at most 100 characters and
// bounded in depth whatever the value, even one built in code nested 100 000
// deep; a pointer stays on one line whatever its keys hold.
#include "vahf/scene/json_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "support/test_files.h"
#include "vahf/core/error.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::scene {
namespace {

using ::nlohmann::json;
using ::testing::EndsWith;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

// The InputError that parsing `text` as "f.json" throws; fails the test if none.
InputError ParseError(const std::string& text) {
  try {
    ParseJsonText(text, "f.json");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for " << text.substr(0, 200);
  return InputError("", "", "", "");
}

// `levels` arrays nested in one another, innermost empty.
std::string NestedArrays(int levels) {
  return std::string(levels, '[') + std::string(levels, ']');
}

TEST(JsonReaderTest, DuplicateKeyAtTheRoot) {
  const InputError e = ParseError(R"({"a": 1, "b": 2, "a": 3})");
  EXPECT_EQ(e.file(), "f.json");
  EXPECT_EQ(e.where(), "/a");
  EXPECT_THAT(e.rule(), HasSubstr("duplicate key \"a\""));
  EXPECT_THAT(e.rule(), HasSubstr("at most once"));
  EXPECT_THAT(std::string(e.what()), Not(HasSubstr("\n")));
}

TEST(JsonReaderTest, DuplicateKeyNamesItsPointer) {
  const InputError e = ParseError(
      R"({"parts": [{"name": "bore", "pose": {"position": [0, 0, 1]}},
                    {"name": "peg", "pose": {"position": [0, 0, 1], "position": [0, 0, 2]}}],
          "sequence": ["peg"]})");
  EXPECT_EQ(e.where(), "/parts/1/pose/position");
  EXPECT_THAT(e.rule(), HasSubstr("duplicate key \"position\""));
}

TEST(JsonReaderTest, DuplicateKeyAfterNestedContainers) {
  // The pointer follows arrays of arrays and objects in arrays.
  const InputError e =
      ParseError(R"({"a": [[1, 2], [3], {"x": [4]}, {"y": 5, "z~/": 6, "z~/": 7}]})");
  EXPECT_EQ(e.where(), "/a/3/z~0~1");
}

TEST(JsonReaderTest, SameKeyInDifferentObjectsIsNoRepeat) {
  const json j = ParseJsonText(
      R"({"a": {"k": 1}, "b": {"k": 2}, "c": [{"k": 3}, {"k": 4}], "k": {"k": {"k": 5}}})",
      "f.json");
  EXPECT_EQ(j["c"][1]["k"], 4);
  EXPECT_EQ(j["k"]["k"]["k"], 5);
}

TEST(JsonReaderTest, DuplicateKeyInAFile) {
  const std::string path =
      testing::WriteFile(testing::TestDir("vahf_json_reader_test") / "scene.json",
                         R"({"format": "vahf-scene/1", "name": "x", "name": "y"})");
  try {
    ReadJsonFile(path);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.where(), "/name");
    EXPECT_THAT(e.rule(), HasSubstr("duplicate key \"name\""));
  }
}

TEST(JsonReaderTest, NestingUpToTheLimitIsRead) {
  const json j = ParseJsonText(NestedArrays(kMaxJsonDepth), "f.json");
  EXPECT_TRUE(j.is_array());
}

TEST(JsonReaderTest, NestingPastTheLimitIsRefused) {
  const InputError e = ParseError(NestedArrays(kMaxJsonDepth + 1));
  std::string where;
  for (int i = 0; i < kMaxJsonDepth; ++i) where += "/0";
  EXPECT_EQ(e.where(), where);
  EXPECT_THAT(e.rule(), HasSubstr("nested deeper than 64 levels"));
}

TEST(JsonReaderTest, DeeplyNestedFieldIsOneError) {
  // 100 000 nested arrays as a scene's name: once a stack overflow while the
  // error message printed the value.
  const std::string path = testing::WriteFile(
      testing::TestDir("vahf_json_reader_test") / "deep.json",
      R"({"format": "vahf-scene/1", "name": )" + NestedArrays(100'000) + "}");
  try {
    LoadScene(path);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_THAT(e.where(), StartsWith("/name/0/0/0/"));
    EXPECT_THAT(e.rule(), HasSubstr("nested deeper than 64 levels"));
    EXPECT_LE(std::string(e.what()).size(), 1000u);  // not the 200 000 characters
  }
}

TEST(JsonReaderTest, DeepValueBuiltInCodeIsShownBounded) {
  // Nothing stops a document built in code from nesting 100 000 deep
  // (nlohmann builds and destroys it without recursion): its message must
  // not recurse through it either.
  json deep = json::array();
  for (int i = 0; i < 100'000; ++i) {
    json outer = json::array();
    outer.push_back(std::move(deep));
    deep = std::move(outer);
  }
  const std::string file = "code";
  const JsonNode node(deep, file, "/x");
  try {
    node.Number();
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.value(), "[[[[[...]]]]]");
    EXPECT_THAT(e.rule(), HasSubstr("must be a number, not a array"));
  }
}

TEST(JsonReaderTest, LongContainerKeepsItsStart) {
  json many = json::array();
  for (int i = 0; i < 100'000; ++i) many.push_back(i);
  const std::string file = "code";
  const std::string shown = JsonNode(many, file).ValueText();
  EXPECT_EQ(shown.size(), 100u);
  EXPECT_THAT(shown, StartsWith("[0,1,2,3,"));
  EXPECT_THAT(shown, EndsWith("..."));
}

TEST(JsonReaderTest, ShortValuesAreWhole) {
  const std::string file = "code";
  EXPECT_EQ(JsonNode(json::parse(R"({"a":[1,{"b":[2]}],"c":"d"})"), file).ValueText(),
            R"({"a":[1,{"b":[2]}],"c":"d"})");
  EXPECT_EQ(JsonNode(json(std::nan("")), file).ValueText(), "nan");
  EXPECT_EQ(JsonNode(json(-std::numeric_limits<double>::infinity()), file).ValueText(),
            "-inf");
}

TEST(JsonReaderTest, PointerStaysOnOneLine) {
  EXPECT_EQ(PointerToken("a/b~c"), "a~1b~0c");
  EXPECT_EQ(PointerToken("line\nbreak"), "line\\u000abreak");
  const InputError e = ParseError("{\"a\\nb\": 1, \"a\\nb\": 2}");
  EXPECT_EQ(e.where(), "/a\\u000ab");
  EXPECT_THAT(std::string(e.what()), Not(HasSubstr("\n")));
}

}  // namespace
}  // namespace vahf::scene
