// The progress line: its text, and when it is printed (nothing in the first
// 2 s, at most every 0.5 s, a final line and newline only after a printed one).
#include "vahf/experiment/progress.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace vahf::experiment {
namespace {

std::string Contents(std::FILE* f) {
  std::string out;
  std::rewind(f);
  for (int c; (c = std::fgetc(f)) != EOF;) out += static_cast<char>(c);
  return out;
}

TEST(FormatProgress, Text) {
  // 120 trials at 35.2 trials/s: 3.41 s so far; 380 left take 10.8 s.
  EXPECT_EQ(FormatProgress("table1", 120, 500, 120 / 35.2),
            "table1: 120/500 trials, 35.2 trials/s, about 11 s left");
  EXPECT_EQ(FormatProgress("", 0, 10, 3.0),
            "0/10 trials, 0.0 trials/s, time left unknown");
  EXPECT_EQ(FormatProgress("x", 1, 1001, 3.0),
            "x: 1/1001 trials, 0.3 trials/s, about 50 min left");
  EXPECT_EQ(FormatProgress("x", 1, 10001, 3.0),
            "x: 1/10001 trials, 0.3 trials/s, about 8.3 h left");
  EXPECT_EQ(FormatProgress("paper", 3, 6, 3.0, "cycles"),
            "paper: 3/6 cycles, 1.0 cycles/s, about 3 s left");
}

TEST(ProgressMeter, QuietAtFirstThenTwiceASecondThenANewline) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  ProgressMeter meter("mc", 100, true, f);
  meter.Update(10, 1.0);  // within the first 2 s
  meter.Update(20, 2.0);
  EXPECT_FALSE(meter.printed());
  meter.Update(25, 2.5);  // printed
  meter.Update(26, 2.9);  // too soon after
  meter.Update(50, 3.0);  // printed
  meter.Finish(100, 6.0);
  EXPECT_EQ(Contents(f),
            "\rmc: 25/100 trials, 10.0 trials/s, about 8 s left"
            "\rmc: 50/100 trials, 16.7 trials/s, about 3 s left"
            "\rmc: 100/100 trials, 16.7 trials/s, finished in 6 s"
            "\n");
  std::fclose(f);
}

TEST(ProgressMeter, ALongerLineIsBlankedAndAStopIsSaid) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  ProgressMeter meter("", 100000, true, f);
  meter.Update(1, 5.0);
  meter.Finish(2, 6.0);
  EXPECT_EQ(Contents(f),
            "\r1/100000 trials, 0.2 trials/s, about 138.9 h left"
            "\r2/100000 trials, 0.3 trials/s, stopped after 6 s \n");
  std::fclose(f);
}

TEST(ProgressMeter, CountsItsOwnUnit) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  ProgressMeter meter("paper", 6, true, f, "cycles");
  meter.Update(3, 3.0);
  meter.Finish(6, 6.0);
  EXPECT_EQ(Contents(f),
            "\rpaper: 3/6 cycles, 1.0 cycles/s, about 3 s left"
            "\rpaper: 6/6 cycles, 1.0 cycles/s, finished in 6 s\n");
  std::fclose(f);
}

// Into a file or pipe: a line each, at most every 10 s.
TEST(ProgressMeter, ALogGetsANewLineEveryTenSeconds) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  EXPECT_FALSE(IsTerminal(f));
  ProgressMeter meter("mc", 100, true, f, "trials", ProgressMeter::Style::kLog);
  meter.Update(10, 2.5);   // printed
  meter.Update(20, 5.0);   // too soon for a log
  meter.Update(50, 12.5);  // printed
  meter.Finish(100, 20.0);
  EXPECT_EQ(Contents(f),
            "mc: 10/100 trials, 4.0 trials/s, about 23 s left\n"
            "mc: 50/100 trials, 4.0 trials/s, about 13 s left\n"
            "mc: 100/100 trials, 5.0 trials/s, finished in 20 s\n");
  std::fclose(f);
}

TEST(ProgressMeter, SilentWhenDisabledOrNeverPrinted) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  ProgressMeter disabled("mc", 10, false, f);
  disabled.Update(5, 10.0);
  disabled.Finish(10, 20.0);
  ProgressMeter quick("mc", 10, true, f);
  quick.Update(10, 1.0);
  quick.Finish(10, 1.5);
  EXPECT_EQ(Contents(f), "");
  std::fclose(f);
}

}  // namespace
}  // namespace vahf::experiment
