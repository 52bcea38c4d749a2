// A figure described as data is written as the gnuplot script it describes:
// the terminal, the data blocks, the settings and plot commands in order,
// each series as "DATA using COLUMNS STYLE title 'T'"; and gnuplot renders it.
#include "vahf/report/figure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "vahf/report/plot.h"

namespace vahf::report {
namespace {

TEST(DataRow, FormatsEachFieldAsAsked) {
  EXPECT_EQ(DataRow().Number(0.1).Number(3).Number(1e-5).Text(), "0.1 3 1e-05");
  EXPECT_EQ(DataRow().Integer(-1).Short(0.123456789).Label("piston a").Text(),
            "-1 0.123457 \"piston a\"");
  EXPECT_EQ(DataRow().Number(std::nan("")).Text(), "nan");
}

TEST(DataRow, MeanAndIntervalOfASummary) {
  stats::Summary s;
  EXPECT_EQ(DataRow().MeanAndInterval(s).Text(), "nan nan nan");  // no mean: not drawn
  s.mean = 2.5;
  EXPECT_EQ(DataRow().MeanAndInterval(s).Text(), "2.5 2.5 2.5");  // no interval
  s.ci = stats::Interval{2, 3.25};
  EXPECT_EQ(DataRow().MeanAndInterval(s).Text(), "2.5 2 3.25");
}

TEST(Figure, WritesTheScriptItDescribes) {
  Figure f;
  f.Data("d", {DataRow().Integer(0).Label("P1").Number(1.5),
               DataRow().Integer(1).Label("P2").Number(2)})
      .Title("time per operator")
      .XLabel("operator")
      .YLabel("time (s)")
      .CategoryRange(2)
      .Set("grid y")
      .Draw({"$d", "1:3:xtic(2)", "with boxes", std::nullopt})
      .Draw({"''", "1:3", "with points pt 7", "mean"});
  EXPECT_EQ(GnuplotScript(f),
            "$d << EOD\n0 \"P1\" 1.5\n1 \"P2\" 2\nEOD\n"
            "set title 'time per operator'\n"
            "set xlabel 'operator'\n"
            "set ylabel 'time (s)'\n"
            "set xrange [-0.5:2-0.5]\n"
            "set grid y\n"
            "plot $d using 1:3:xtic(2) with boxes notitle, "
            "'' using 1:3 with points pt 7 title 'mean'\n");
}

TEST(Figure, ATerminalFirstThenEveryBlockThenEachPanel) {
  // A multiplot: the data of both panels before any setting; a setting after
  // a series starts the next panel's plot command.
  Figure f;
  f.Terminal("pngcairo size 1100,500 noenhanced")
      .Data("a", {DataRow().Number(1).Number(2)})
      .Set("multiplot layout 1,2 title 'two'")
      .Title("left")
      .Draw({"$a", "1:2", "", "a"})
      .Draw({"0.5", "", "with lines dt 2", "limit"})
      .Data("b", {})
      .Title("right")
      .Set("label 1 'nothing' at graph 0.5, 0.5 center")
      .Draw({"[1:10] [1:10] 2", "", "lc rgb 'white'", std::nullopt})
      .Unset("label 1")
      .Unset("multiplot");
  EXPECT_EQ(GnuplotScript(f),
            "set terminal pngcairo size 1100,500 noenhanced\n"
            "$a << EOD\n1 2\nEOD\n$b << EOD\nEOD\n"
            "set multiplot layout 1,2 title 'two'\n"
            "set title 'left'\n"
            "plot $a using 1:2 title 'a', 0.5 with lines dt 2 title 'limit'\n"
            "set title 'right'\n"
            "set label 1 'nothing' at graph 0.5, 0.5 center\n"
            "plot [1:10] [1:10] 2 lc rgb 'white' notitle\n"
            "unset label 1\n"
            "unset multiplot\n");
}

TEST(Figure, QuotesTextAsGnuplotReadsIt) {
  EXPECT_EQ(GnuplotString("mean, 95 %"), "'mean, 95 %'");
  EXPECT_EQ(GnuplotString("the operator's time"), "'the operator''s time'");
  Figure f;
  f.Title("Fig. 1: it's \"eta\"").Draw({"x", "", "", "x's"});
  EXPECT_EQ(GnuplotScript(f), "set title 'Fig. 1: it''s \"eta\"'\nplot x title 'x''s'\n");
}

TEST(FigureDeathTest, AFigureThatPlotsNothingIsABug) {
  Figure f;
  f.Title("empty");
  EXPECT_DEATH(GnuplotScript(f), "a figure plots nothing");
}

TEST(Figure, GnuplotRendersTheScript) {
  // The writer's script is gnuplot's syntax: quotes in titles, a data block,
  // labels in the data, an error-bar series on the block before.
  Figure f;
  f.Data("d", {DataRow().Integer(0).Label("the rod's").Number(1).Number(0.8).Number(1.2),
               DataRow().Integer(1).Label("piston").Number(2).Number(1.5).Number(2.5)})
      .Title("the operator's time")
      .YLabel("time (s)")
      .CategoryRange(2)
      .Draw({"$d", "1:3:xtic(2)", "with boxes", std::nullopt})
      .Draw({"''", "1:3:4:5", "with yerrorbars pt 7", "mean, 95 %"});
  const std::string png =
      (std::filesystem::path(::testing::TempDir()) / "figure_test.png").string();
  RenderPlot(GnuplotScript(f), png);
  EXPECT_GT(std::filesystem::file_size(png), 1000u);
  std::filesystem::remove(png);
}

}  // namespace
}  // namespace vahf::report
