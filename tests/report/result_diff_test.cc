// FirstDifference: equal bytes give none; a CSV table is compared field by
// field (row, physical line and column named, a quoted field spanning lines
// included), then by its header and its length; a file that is not CSV, or
// a CSV an edit broke, line by line.
#include "vahf/report/result_diff.h"

#include <gtest/gtest.h>

namespace vahf::report {
namespace {

const std::string kTable = "cycle,part,eta\n0,rod,0.25\n1,rod,0.5\n2,\"a\nb\",0.75\n";

TEST(FirstDifference, NoneForEqualBytes) {
  EXPECT_FALSE(FirstDifference("t.csv", kTable, kTable));
  EXPECT_FALSE(FirstDifference("summary.json", "{}\n", "{}\n"));
}

TEST(FirstDifference, NamesTheRowLineAndColumnOfAField) {
  std::string edited = kTable;
  edited.replace(edited.find("0.5"), 3, "0.6");
  const auto d = FirstDifference("t.csv", edited, kTable);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->row, 2);
  EXPECT_EQ(d->line, 3);
  EXPECT_EQ(d->column, "eta");
  EXPECT_EQ(d->recorded, "0.6");
  EXPECT_EQ(d->rerun, "0.5");
  EXPECT_EQ(d->Text(),
            "t.csv: row 2 (line 3), column eta: 0.6 in the run, 0.5 in the re-run");
}

TEST(FirstDifference, CountsPhysicalLinesPastAQuotedLineBreak) {
  std::string edited = kTable;
  edited.replace(edited.find("0.75"), 4, "0.70");
  const auto d = FirstDifference("t.csv", kTable, edited);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->row, 3);
  EXPECT_EQ(d->line, 5);  // the row starts on line 4; its last field is on line 5
  EXPECT_EQ(d->column, "eta");
}

TEST(FirstDifference, ARowOnlyOneSideHas) {
  const std::string shorter = "cycle,part,eta\n0,rod,0.25\n1,rod,0.5\n";
  const auto d = FirstDifference("t.csv", shorter, kTable);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->row, 3);
  EXPECT_EQ(d->recorded, "(end of file)");
  EXPECT_EQ(d->rerun, "2,\"a\nb\",0.75");
}

TEST(FirstDifference, AHeader) {
  std::string renamed = kTable;
  renamed.replace(0, 5, "trial");
  const auto d = FirstDifference("t.csv", renamed, kTable);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->row, 0);
  EXPECT_EQ(d->line, 1);
  EXPECT_EQ(d->recorded, "trial,part,eta");
  EXPECT_EQ(d->Text(),
            "t.csv: line 1: trial,part,eta in the run, cycle,part,eta in the re-run");
}

TEST(FirstDifference, ByLineForJsonAndForACsvAnEditBroke) {
  const auto j = FirstDifference("summary.json", "{\n \"a\": 1,\n \"b\": 2\n}\n",
                                 "{\n \"a\": 1,\n \"b\": 3\n}\n");
  ASSERT_TRUE(j);
  EXPECT_EQ(j->row, 0);
  EXPECT_EQ(j->line, 3);
  EXPECT_EQ(j->recorded, " \"b\": 2");
  std::string broken = kTable;
  broken.replace(broken.find("0,rod,0.25"), 10, "0,rod");  // a row too short
  const auto c = FirstDifference("t.csv", broken, kTable);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->row, 0);
  EXPECT_EQ(c->line, 2);
  EXPECT_EQ(c->recorded, "0,rod");
}

TEST(FirstDifference, OnlyAFinalLineBreak) {
  const auto d = FirstDifference("summary.json", "{}\n", "{}");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->line, 2);
  EXPECT_EQ(d->recorded, "\\n");
  EXPECT_EQ(d->rerun, "(end of file)");
}

TEST(FirstDifference, ShortensLongValuesInItsText) {
  const std::string a(200, 'a'), b(200, 'b');
  const auto d = FirstDifference("x.txt", a, b);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->recorded, a);          // the fields hold the whole value
  EXPECT_LT(d->Text().size(), 170u);  // two 60-character values and the words
  EXPECT_NE(d->Text().find("..."), std::string::npos);
}

}  // namespace
}  // namespace vahf::report
