// CSV of a tidy table: shortest round-trip doubles (every double read back
// gives its bits), integers, RFC 4180 quoting only where needed, nan/inf.
#include "vahf/report/table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>

#include "vahf/rng/stream.h"

namespace vahf::report {
namespace {

TEST(Table, CsvOfMixedCells) {
  Table t({"trial", "status", "time_s"});
  t.AddRow({std::int64_t{0}, std::string("completed"), 0.1});
  t.AddRow({std::int64_t{-7}, std::string("timeout"), 30.0});
  t.AddRow({std::numeric_limits<std::int64_t>::max(), std::string(""), 1e-5});
  EXPECT_EQ(t.rows(), 3u);
  EXPECT_EQ(std::get<double>(t.at(1, 2)), 30.0);
  EXPECT_EQ(t.ToCsv(),
            "trial,status,time_s\n"
            "0,completed,0.1\n"
            "-7,timeout,30\n"
            "9223372036854775807,,1e-05\n");
}

TEST(Table, NonFiniteValues) {
  Table t({"x"});
  const double inf = std::numeric_limits<double>::infinity();
  for (double x : {std::numeric_limits<double>::quiet_NaN(),
                   -std::numeric_limits<double>::quiet_NaN(), inf, -inf, -0.0}) {
    t.AddRow({x});
  }
  EXPECT_EQ(t.ToCsv(), "x\nnan\nnan\ninf\n-inf\n-0\n");
}

TEST(Table, QuotingFollowsRfc4180) {
  Table t({"name", "note, with comma"});
  t.AddRow({std::string("plain"), std::string("say \"hi\"")});
  t.AddRow({std::string("two\nlines"), std::string("cr\rhere")});
  t.AddRow({std::string(" spaces kept "), std::string("")});
  EXPECT_EQ(t.ToCsv(),
            "name,\"note, with comma\"\n"
            "plain,\"say \"\"hi\"\"\"\n"
            "\"two\nlines\",\"cr\rhere\"\n"
            " spaces kept ,\n");
}

TEST(Table, AnEmptyFieldAloneOnItsLineIsQuoted) {
  Table t({"label"});
  t.AddRow({std::string("")});
  EXPECT_EQ(t.ToCsv(), "label\n\"\"\n");
}

TEST(Table, DoublesReadBackToTheSameBits) {
  // Random bit patterns of finite doubles (Philox, fixed seed) and awkward
  // decimals: strtod of the written text must return the identical double.
  Table t({"x"});
  rng::Stream s({7, 0}, 0, rng::Purpose::kTest);
  std::vector<double> xs = {0.1, 1.0 / 3.0, 5e-324, 1.7976931348623157e308,
                            123456789.125};
  while (xs.size() < 2000) {
    const std::uint64_t bits = s.Bits();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (std::isfinite(x)) xs.push_back(x);
  }
  for (double x : xs) t.AddRow({x});
  std::istringstream csv(t.ToCsv());
  std::string line;
  std::getline(csv, line);
  for (double x : xs) {
    ASSERT_TRUE(std::getline(csv, line));
    const double back = std::strtod(line.c_str(), nullptr);
    ASSERT_EQ(std::memcmp(&back, &x, sizeof x), 0) << line;
  }
}

TEST(TableDeathTest, MisshapenRowsAndColumnsAreBugs) {
  EXPECT_DEATH(Table({"a", "a"}), "column 'a' appears twice");
  EXPECT_DEATH(Table({"a", ""}), "a column name is empty");
  EXPECT_DEATH(
      {
        Table t({"a", "b"});
        t.AddRow({1.0});
      },
      "a row of 1 cells for 2 columns");
}

}  // namespace
}  // namespace vahf::report
