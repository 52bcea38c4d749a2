// The paper's Table 1 against Eqs. 2, 3 and 6 within what its two-decimal
// rounding allows (the bound is derived in table1_reference.h). The paper is
// inconsistent in named places, recorded in reference/paper/NOTES.md; this test
// names them so that any other row failing, or a named one passing, is caught.
#include "vahf/experiment/table1_reference.h"

#include <gtest/gtest.h>

#include <set>

namespace vahf::experiment {
namespace {

Table1 Load() {
  return LoadTable1(std::string(VAHF_SOURCE_DIR) + "/reference/paper/table1.json");
}

TEST(Table1, HasTwelveRowsOfThreeSubassemblies) {
  const Table1 t = Load();
  ASSERT_EQ(t.rows.size(), 12u);
  EXPECT_EQ(t.decimals_inputs, 2);
  EXPECT_EQ(t.decimals_outputs, 2);
  EXPECT_EQ(t.rows[0].part, "piston rod");
  EXPECT_EQ(t.rows[11].part, "seal ring");
}

TEST(Table1, EtaAndLambdaWithinRoundingExceptKnownInconsistencies) {
  // Known exception: guide sleeve, instant c, lambda_c. Eq. 3 gives
  // 1 - (0.95 + 0.96) / 2 * 0.95 = 0.0928; over the rounding box of r, g, V it
  // can reach at most 0.1023, but the table prints 0.13 (>= 0.125).
  const std::set<std::string> known = {"II c lambda_c"};
  std::set<std::string> inconsistent;
  for (const Table1Check& c : CheckTable1(Load())) {
    const std::string row = c.row.subassembly + " " + c.row.instant;
    if (!c.eta.consistent) inconsistent.insert(row + " eta");
    if (!c.lambda_c.consistent) inconsistent.insert(row + " lambda_c");
    // The allowed interval contains the value computed from the printed inputs.
    EXPECT_LE(c.eta.allowed.lo, c.eta.computed);
    EXPECT_GE(c.eta.allowed.hi, c.eta.computed);
    EXPECT_LE(c.lambda_c.allowed.lo, c.lambda_c.computed);
    EXPECT_GE(c.lambda_c.allowed.hi, c.lambda_c.computed);
  }
  EXPECT_EQ(inconsistent, known);
}

TEST(Table1, TheBoundIsTight) {
  // Piston rod d: eta = 1 - V f with V in [0.075, 0.085], f in [0.795, 0.805]
  // spans [1 - 0.085 * 0.805, 1 - 0.075 * 0.795] = [0.931575, 0.940375].
  const auto checks = CheckTable1(Load());
  const Table1Check& d = checks[3];
  ASSERT_EQ(d.row.instant, "d");
  EXPECT_NEAR(d.eta.allowed.lo, 1 - 0.085 * 0.805, 1e-12);
  EXPECT_NEAR(d.eta.allowed.hi, 1 - 0.075 * 0.795, 1e-12);
  EXPECT_NEAR(d.eta.printed.lo, 0.925, 1e-12);
  EXPECT_NEAR(d.eta.printed.hi, 0.935, 1e-12);
  EXPECT_TRUE(d.eta.consistent);  // 0.9316 <= 0.935: consistent, just
}

TEST(Table1, PsiColumnDoesNotFollowEq6) {
  // Known non-reproduction: with A in kcal and the 1600 kcal limit Eq. 6 gives
  // Psi_c = 0.995-0.999 in every row, printed as 1.0, not 0.9; and no single
  // A_max makes every row print 0.9 (rows need A_max <= 1.805 / 0.05 = 36.1 and
  // A_max >= 7.895 / 0.15 = 52.6).
  const Table1 t = Load();
  for (const Table1Check& c : CheckTable1(t)) {
    EXPECT_GT(c.psi_eq6, 0.95) << c.row.part << " " << c.row.instant;
    EXPECT_NEAR(c.row.psi_c, 0.9, 1e-12);
  }
  const PsiFeasibility f = PsiColumnFeasibility(t);
  EXPECT_FALSE(f.feasible);
  EXPECT_NEAR(f.a_max.lo, 7.895 / 0.15, 1e-9);
  EXPECT_NEAR(f.a_max.hi, 1.805 / 0.05, 1e-9);
}

}  // namespace
}  // namespace vahf::experiment
