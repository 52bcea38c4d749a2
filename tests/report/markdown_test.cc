// A Markdown table written as described: headings, the "---" line, one line
// per row, each cell between "| " and " |"; a row that does not fit is a bug.
#include "vahf/report/markdown.h"

#include <gtest/gtest.h>

namespace vahf::report {
namespace {

TEST(MarkdownTable, WritesTheHeadingsTheRuleAndEachRow) {
  MarkdownTable t{{"part", "time (s)"}};
  t.AddRow({"piston", "1.250 [1.100, 1.400]"});
  t.AddRow({"rod", "-"});
  EXPECT_EQ(ToMarkdown(t),
            "| part | time (s) |\n"
            "| --- | --- |\n"
            "| piston | 1.250 [1.100, 1.400] |\n"
            "| rod | - |\n");
}

TEST(MarkdownTable, KeepsEachCellAsWritten) {
  // An empty cell and one with its own spaces keep their bytes: the sections
  // rely on it ("- " where a value is missing before the paper's value).
  MarkdownTable t{{"a", "b", "c"}};
  t.AddRow({"", "- ", "**x**"});
  EXPECT_EQ(ToMarkdown(t), "| a | b | c |\n| --- | --- | --- |\n|  | -  | **x** |\n");
}

TEST(MarkdownTable, WithoutRowsIsItsHeadings) {
  EXPECT_EQ(ToMarkdown(MarkdownTable({"only"})), "| only |\n| --- |\n");
}

TEST(MarkdownTableDeathTest, ARowOfTheWrongWidthIsABug) {
  MarkdownTable t{{"a", "b"}};
  EXPECT_DEATH(t.AddRow({"1"}), "a Markdown row of 1 cells under 2 headings");
  EXPECT_DEATH(t.AddRow({"1", "2", "3"}), "a Markdown row of 3 cells under 2 headings");
  EXPECT_DEATH(MarkdownTable(std::vector<std::string>{}), "needs at least one heading");
}

}  // namespace
}  // namespace vahf::report
