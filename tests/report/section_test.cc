// Tests of the shared pieces of the report sections (report/section.h).
#include "vahf/report/section.h"

#include <gtest/gtest.h>

namespace vahf::report {
namespace {

TEST(MeanCi, MeanWithItsIntervalTheMeanAloneOrADash) {
  // 1, 2, 3: mean 2, sd 1, t(0.975, 2) = 4.303: 2 -+ 2.484.
  EXPECT_EQ(MeanCi(stats::Summarize({1.0, 2.0, 3.0})), "2.000 [-0.484, 4.484]");
  EXPECT_EQ(MeanCi(stats::Summarize({1.25})), "1.250");  // one sample: no interval
  EXPECT_EQ(MeanCi(stats::Summarize({})), "-");
}

TEST(Claim, HoldsEveryField) {
  const nlohmann::json c = Claim("eta rises", true, "t test", "0.2 [0.1, 0.3]");
  EXPECT_EQ(c["claim"], "eta rises");
  EXPECT_EQ(c["reproduced"], true);
  EXPECT_EQ(c["test"], "t test");
  EXPECT_EQ(c["evidence"], "0.2 [0.1, 0.3]");
}

}  // namespace
}  // namespace vahf::report
