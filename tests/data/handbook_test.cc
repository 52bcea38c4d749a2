// Tests of the handbook tables (data/handbook.h) and the classification of a
// fit (data/handbook_classification.h). Oracles: the shipped CSV files as
// data/handbooks/README.md lists their values (each against its source
// there); for the loader's rules, hand-written files with one fault each; for
// the classes, the shipped scenes' profile points, read by hand from
// experiments/scenes/*.json, and the rules of docs/handbooks.md applied by
// hand. The MTM-1 rows of the fixtures are made-up times (the shipped MTM-1
// file has none yet: README, "Not verified").
#include "vahf/data/handbook.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "vahf/core/error.h"
#include "vahf/data/handbook_classification.h"

namespace vahf::data {
namespace {

using ::testing::HasSubstr;

std::string SourceDir() { return VAHF_SOURCE_DIR; }

const char kMtmHeader[] = "code,fit_class,symmetry,handling,tmu,source\n";
const char kBdHeader[] = "code,seconds,source\n";

TEST(HandbookTest, ShippedBoothroydDewhurstTableLoadsWithItsValues) {
  const BdInsertionTable t =
      ReadBdInsertion(SourceDir() + "/data/handbooks/boothroyd_dewhurst_insertion.csv");
  ASSERT_EQ(t.rows.size(), 30u);  // 24 added-not-secured codes, 6 push or snap fits
  const BdInsertionTime* easy = t.Find("00");
  ASSERT_NE(easy, nullptr);
  EXPECT_EQ(easy->seconds, 1.5);
  EXPECT_EQ(easy->row, 0);
  EXPECT_EQ(easy->column, 0);
  EXPECT_EQ(easy->source, "S2");
  EXPECT_EQ(t.Find("03")->seconds, 3.5);
  EXPECT_EQ(t.Find("29")->seconds, 11.5);
  EXPECT_EQ(t.Find("31")->seconds, 5.0);
  EXPECT_EQ(t.Find("04"), nullptr);  // no such cell in rows 0-2
}

TEST(HandbookTest, ShippedMtmTableLoadsAndHoldsNoUnverifiedTime) {
  const MtmPositionTable t =
      ReadMtmPosition(SourceDir() + "/data/handbooks/mtm1_position.csv");
  EXPECT_TRUE(t.rows.empty());
}

TEST(HandbookTest, MtmRowGivesSecondsAtPointZeroThreeSixPerTmu) {
  const MtmPositionTable t = ParseMtmPosition(
      std::string(kMtmHeader) + "P2SE,2,S,easy,10.0,fixture\nP1NSD,1,NS,difficult,20,f\n",
      "t.csv");
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0].line, 2);
  EXPECT_DOUBLE_EQ(t.Find("P2SE")->seconds(), 0.36);
  EXPECT_DOUBLE_EQ(t.Find("P1NSD")->seconds(), 0.72);
  EXPECT_EQ(MtmPositionCode(3, "SS", "difficult"), "P3SSD");
}

template <typename Parse>
InputError ErrorOf(Parse parse, const std::string& text) {
  try {
    parse(text, "t.csv");
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return InputError("", "", "", "");
}

InputError MtmError(const std::string& rows) {
  return ErrorOf(ParseMtmPosition, kMtmHeader + rows);
}
InputError BdError(const std::string& rows) {
  return ErrorOf(ParseBdInsertion, kBdHeader + rows);
}

TEST(HandbookTest, EachBadMtmRowNamesLineColumnValueAndRule) {
  InputError e = MtmError("P2SE,2,S,easy,10,f\nP2SD,2,S,easy,10,f\n");
  EXPECT_EQ(e.file(), "t.csv");
  EXPECT_EQ(e.where(), "line 3, column code");
  EXPECT_EQ(e.value(), "P2SD");
  EXPECT_THAT(e.rule(), HasSubstr("unknown code"));

  e = MtmError("P2SE,2,S,easy,-1,f\n");
  EXPECT_EQ(e.where(), "line 2, column tmu");
  EXPECT_THAT(e.rule(), HasSubstr("positive"));

  e = MtmError("P2SE,2,S,easy,NaN,f\n");
  EXPECT_EQ(e.where(), "line 2, column tmu");
  EXPECT_THAT(e.rule(), HasSubstr("NaN"));

  e = MtmError("P2SE,2,S,easy,10,f\n# a comment\nP2SE,2,S,easy,11,f\n");
  EXPECT_EQ(e.where(), "line 4, column code");
  EXPECT_THAT(e.rule(), HasSubstr("duplicate code: line 2"));

  e = MtmError("P4SE,4,S,easy,10,f\n");
  EXPECT_EQ(e.where(), "line 2, column fit_class");

  e = MtmError("P2XE,2,X,easy,10,f\n");
  EXPECT_EQ(e.where(), "line 2, column symmetry");

  e = MtmError("P2SE,2,S,easy,10,\n");
  EXPECT_EQ(e.where(), "line 2, column source");

  e = ErrorOf(ParseMtmPosition, "code,fit_class,symmetry,handling,source\n");
  EXPECT_EQ(e.where(), "line 1, column tmu");
  EXPECT_EQ(e.value(), "(missing)");
}

TEST(HandbookTest, EachBadBoothroydDewhurstRowNamesLineColumnValueAndRule) {
  InputError e = BdError("04,3.0,f\n");
  EXPECT_EQ(e.where(), "line 2, column code");
  EXPECT_EQ(e.value(), "04");
  EXPECT_THAT(e.rule(), HasSubstr("unknown code"));

  EXPECT_EQ(BdError("7,3.0,f\n").where(), "line 2, column code");
  EXPECT_EQ(BdError("60,3.0,f\n").where(), "line 2, column code");

  e = BdError("00,0,f\n");
  EXPECT_EQ(e.where(), "line 2, column seconds");
  EXPECT_THAT(e.rule(), HasSubstr("positive"));

  e = BdError("00,-1.5,f\n");
  EXPECT_EQ(e.where(), "line 2, column seconds");

  e = BdError("00,nan,f\n");
  EXPECT_EQ(e.where(), "line 2, column seconds");

  e = BdError("00,1.5,f\n01,2.5,f\n00,1.5,f\n");
  EXPECT_EQ(e.where(), "line 4, column code");
  EXPECT_THAT(e.rule(), HasSubstr("duplicate code: line 2"));

  e = ErrorOf(ParseBdInsertion, "code,seconds\n00,1.5\n");
  EXPECT_EQ(e.where(), "line 1, column source");

  e = ErrorOf(ParseBdInsertion, "code,seconds,source,colour\n00,1.5,f,red\n");
  EXPECT_EQ(e.where(), "line 1, column colour");
  EXPECT_THAT(e.rule(), HasSubstr("unknown column"));
}

class HandbookClassTest : public ::testing::Test {
 protected:
  void SetUp() override {
    bd_ =
        ReadBdInsertion(SourceDir() + "/data/handbooks/boothroyd_dewhurst_insertion.csv");
    mtm_ = ParseMtmPosition(std::string(kMtmHeader) + "P2SE,2,S,easy,10,fixture\n", "t");
  }
  BdInsertionTable bd_;
  MtmPositionTable mtm_;
};

TEST_F(HandbookClassTest, PistonRodIsAnOiledChamferedCloseFit) {
  // hydraulic_cylinder.json: barrel bore radius 0.0315115 m, rod head radius
  // 0.0314775 m (34 um radial, 63 mm), 1 mm chamfers, VG 46 oil.
  InsertionFit fit;
  fit.radial_clearance = 0.0315115 - 0.0314775;
  fit.diameter = 2 * 0.0315115;
  fit.chamfered = true;
  fit.lubricated = true;
  const HandbookClasses c = ClassifyInsertion(fit, mtm_, bd_);
  EXPECT_EQ(c.mtm.fit_class, 2);  // 2 * 34 um / 63 mm = 1.08/1000 < 2/1000
  EXPECT_EQ(c.mtm.symmetry, "S");
  EXPECT_EQ(c.mtm.code, "P2SE");
  ASSERT_TRUE(c.mtm.seconds.has_value());
  EXPECT_DOUBLE_EQ(*c.mtm.seconds, 0.36);  // the fixture's 10 TMU
  EXPECT_THAT(c.mtm.why, HasSubstr("class 2 (close)"));
  EXPECT_EQ(c.bd.code, "00");  // easy reach, stays put, chamfered, oiled
  ASSERT_TRUE(c.bd.seconds.has_value());
  EXPECT_EQ(*c.bd.seconds, 1.5);
  EXPECT_THAT(c.bd.why, HasSubstr("no resistance"));
}

TEST_F(HandbookClassTest, PegIsALooseChamferedFit) {
  // peg_in_hole.json: bore radius 0.01005 m, peg radius 0.01 m (50 um
  // radial), chamfers on both, dry.
  InsertionFit fit;
  fit.radial_clearance = 0.01005 - 0.01;
  fit.diameter = 0.02;
  fit.chamfered = true;
  const HandbookClasses c = ClassifyInsertion(fit, mtm_, bd_);
  EXPECT_EQ(c.mtm.code, "P1SE");            // 100 um / 20 mm = 5/1000
  EXPECT_FALSE(c.mtm.seconds.has_value());  // no P1SE row
  EXPECT_EQ(c.bd.code, "00");
  EXPECT_EQ(*c.bd.seconds, 1.5);
}

TEST_F(HandbookClassTest, DryCloseUnchamferedAndPressFitsClassAsTheRulesSay) {
  InsertionFit fit;
  fit.radial_clearance = 34e-6;
  fit.diameter = 0.063;
  EXPECT_EQ(ClassifyInsertion(fit, mtm_, bd_).bd.code, "03");  // no chamfer, dry drag
  fit.chamfered = true;
  EXPECT_EQ(ClassifyInsertion(fit, mtm_, bd_).bd.code, "01");
  fit.holding_down_required = true;
  fit.restricted_vision = true;
  EXPECT_EQ(ClassifyInsertion(fit, mtm_, bd_).bd.code, "17");
  fit.holding_down_required = false;
  fit.restricted_vision = false;
  fit.radial_clearance = -10e-6;
  fit.pressure_required = true;
  const HandbookClasses c = ClassifyInsertion(fit, mtm_, bd_);
  EXPECT_EQ(c.mtm.code, "P3SE");
  EXPECT_EQ(c.bd.code, "31");
  EXPECT_EQ(*c.bd.seconds, 5.0);
  fit.rotationally_symmetric = false;
  fit.easy_to_handle = false;
  EXPECT_EQ(ClassifyInsertion(fit, mtm_, bd_).mtm.code, "P3NSD");
}

TEST_F(HandbookClassTest, ABadDiameterIsAnInputError) {
  InsertionFit fit;
  fit.diameter = 0;
  try {
    ClassifyInsertion(fit, mtm_, bd_);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "diameter");
  }
}

}  // namespace
}  // namespace vahf::data
