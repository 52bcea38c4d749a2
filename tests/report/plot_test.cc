// gnuplot renders a script with inline data to a PNG (checked by its 8-byte
// signature, PNG spec Sec. 5.2); a script's own terminal is kept; a failing
// script or a missing gnuplot is a PlotError naming the script's first line
// and gnuplot's complaint.
#include "vahf/report/plot.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace vahf::report {
namespace {

const char kPngSignature[] = "\x89PNG\r\n\x1a\n";

std::string Head(const std::string& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(n, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(n));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

std::string TempPng(const std::string& name) {
  return (std::filesystem::path(::testing::TempDir()) / name).string();
}

TEST(RenderPlot, InlineDataToPng) {
  const std::string png = TempPng("plot_test_inline.png");
  std::ofstream(png) << "stale";  // replaced, not appended to
  RenderPlot(
      "set title 'completion time'\n"
      "$d << EOD\n1 2.5\n2 2.7\n3 3.1\nEOD\n"
      "plot $d using 1:2 with linespoints title 'mean'\n",
      png);
  EXPECT_EQ(Head(png, 8), std::string(kPngSignature, 8));
  EXPECT_GT(std::filesystem::file_size(png), 1000u);
  std::filesystem::remove(png);
}

TEST(RenderPlot, KeepsTheScriptsTerminal) {
  const std::string png = TempPng("it's a plot.png");  // a quote in the path
  RenderPlot("set terminal png size 200,120\nplot x*x\n", png);
  EXPECT_EQ(Head(png, 8), std::string(kPngSignature, 8));
  std::filesystem::remove(png);
}

TEST(RenderPlot, AFailingScriptNamesItsFirstLineAndGnuplotsMessage) {
  const std::string png = TempPng("plot_test_bad.png");
  try {
    RenderPlot("# fatigue: mean time per segment\nplot $missing using 1:2\n", png);
    ADD_FAILURE();
  } catch (const PlotError& e) {
    EXPECT_THAT(e.what(),
                ::testing::StartsWith(
                    "gnuplot failed (exit status 1) on the plot script beginning "
                    "'# fatigue: mean time per segment':\n"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("no datablock named $missing"));
  }
  EXPECT_FALSE(std::filesystem::exists(png));
}

TEST(RenderPlot, NoGnuplotOnPath) {
  const std::string saved = std::getenv("PATH") ? std::getenv("PATH") : "";
  setenv("PATH", "/nonexistent", 1);
  try {
    RenderPlot("plot x\n", TempPng("plot_test_none.png"));
    ADD_FAILURE();
  } catch (const PlotError& e) {
    EXPECT_THAT(e.what(),
                ::testing::StartsWith(
                    "cannot run gnuplot (No such file or directory; it comes with "
                    "the Debian package gnuplot-nox, see tools/setup) on the plot "
                    "script beginning 'plot x'"));
  }
  setenv("PATH", saved.c_str(), 1);
}

}  // namespace
}  // namespace vahf::report
