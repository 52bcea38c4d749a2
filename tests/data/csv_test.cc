// Tests of the lab datasets' CSV dialect (data/csv.h): RFC 4180 quoting with
// line breaks inside quotes, CRLF, a byte order mark, comment and blank lines
// (a '#' inside a quoted field is data), physical line numbers per field;
// strict numbers; and the writer's quoting, which the reader reads back.
#include "vahf/data/csv.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "vahf/core/error.h"

namespace vahf::data {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(CsvTest, ReadsQuotesCommentsBlankLinesAndLineNumbers) {
  const std::string text =
      "\xEF\xBB\xBF# a comment before the header\r\n"
      "a,b,c\r\n"
      "\r\n"
      "1,\"x, \"\"y\"\"\",\r\n"
      "# a comment between rows\n"
      "2,\"two\n# not a comment\nlines\",z\n"
      "3,,\"\"";
  const CsvFile csv = ParseCsv(text, "t.csv");
  EXPECT_EQ(csv.header_line, 2);
  EXPECT_THAT(csv.header, ElementsAre("a", "b", "c"));
  ASSERT_EQ(csv.rows.size(), 3u);
  EXPECT_THAT(csv.rows[0].fields, ElementsAre("1", "x, \"y\"", ""));
  EXPECT_EQ(csv.rows[0].line, 4);
  EXPECT_THAT(csv.rows[1].fields, ElementsAre("2", "two\n# not a comment\nlines", "z"));
  EXPECT_THAT(csv.rows[1].lines, ElementsAre(6, 6, 8));
  EXPECT_THAT(csv.rows[2].fields, ElementsAre("3", "", ""));
  EXPECT_EQ(csv.rows[2].line, 9);
}

TEST(CsvTest, WriterQuotesWhatTheReaderWouldMisread) {
  EXPECT_EQ(CsvField("plain text"), "plain text");
  EXPECT_EQ(CsvField("a,b"), "\"a,b\"");
  EXPECT_EQ(CsvField("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(CsvField("#1"), "\"#1\"");
  EXPECT_EQ(CsvField("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(CsvLine({""}), "\"\"\n");
  const std::vector<std::string> fields = {"#1", "a,b", "say \"hi\"", "two\r\nlines", ""};
  const CsvFile csv =
      ParseCsv(CsvLine({"a", "b", "c", "d", "e"}) + CsvLine(fields), "t.csv");
  ASSERT_EQ(csv.rows.size(), 1u);
  EXPECT_EQ(csv.rows[0].fields, fields);
}

InputError ParseError(const std::string& text) {
  try {
    ParseCsv(text, "t.csv");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return InputError("", "", "", "");
}

TEST(CsvTest, MalformedRowsNameLineColumnAndValue) {
  InputError e = ParseError("a,b\n1,\"open\nstill open");
  EXPECT_EQ(e.where(), "line 2, column b");
  EXPECT_EQ(e.value(), "\"open");
  EXPECT_THAT(e.rule(), HasSubstr("not closed"));

  e = ParseError("a,b\n1,\"x\"y\n");
  EXPECT_EQ(e.where(), "line 2, column b");
  EXPECT_THAT(e.rule(), HasSubstr("closing quote"));

  e = ParseError("a,b\n1,x\"y\n");
  EXPECT_EQ(e.where(), "line 2, column b");
  EXPECT_EQ(e.value(), "x\"");

  e = ParseError("a,b\n1\n");
  EXPECT_EQ(e.where(), "line 2, column b");
  EXPECT_EQ(e.value(), "(missing)");
  EXPECT_THAT(e.rule(), HasSubstr("the row has 1 field, the header (line 1) 2"));

  e = ParseError("a,b\n1,2,3\n");
  EXPECT_EQ(e.where(), "line 2, column 3");
  EXPECT_EQ(e.value(), "3");

  e = ParseError("a,a\n");
  EXPECT_EQ(e.where(), "line 1, column a");
  EXPECT_THAT(e.rule(), HasSubstr("twice"));

  e = ParseError("# only a comment\n\n");
  EXPECT_THAT(e.rule(), HasSubstr("no header"));
  EXPECT_EQ(e.file(), "t.csv");
}

TEST(CsvTest, NumbersAreStrictDecimals) {
  const std::string file = "t.csv", column = "x";
  const auto number = [&](const std::string& text) {
    return CsvCell(file, column, text, 3).Number();
  };
  EXPECT_EQ(number("1.5"), 1.5);
  EXPECT_EQ(number("-2e-3"), -2e-3);
  EXPECT_EQ(number("+.5"), 0.5);
  EXPECT_EQ(number("7."), 7.0);
  EXPECT_EQ(number("1E+2"), 100.0);
  for (const std::string bad : {"", "1.5x", " 1.5", "1.5 ", "nan", "NaN", "inf",
                                "-Infinity", "0x10", "1e", ".", "1,5", "1e999"}) {
    try {
      number(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), "line 3, column x") << bad;
    }
  }
  const auto integer = [&](const std::string& text) {
    return CsvCell(file, column, text, 3).Integer(1, 10);
  };
  EXPECT_EQ(integer("7"), 7);
  for (const std::string bad : {"0", "11", "1.0", "1e1", "", " 1", "x"}) {
    try {
      integer(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InputError& e) {
      EXPECT_THAT(e.rule(), HasSubstr("an integer from 1 to 10")) << bad;
    }
  }
}

}  // namespace
}  // namespace vahf::data
