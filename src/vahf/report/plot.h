// Plots for the report: a gnuplot script rendered to PNG by gnuplot (found on
// PATH; Debian package gnuplot-nox, installed by tools/setup) run as a
// subprocess with the script on its standard input.
#pragma once

#include <string>

#include "vahf/core/error.h"

namespace vahf::report {

// gnuplot missing, failing, or not writing the PNG: a computation failure
// (reason kRefused) that a report survives, with the figure marked missing. The
// message names the script by its first line and carries gnuplot's standard
// error.
class PlotError : public ComputationError {
 public:
  explicit PlotError(const std::string& message)
      : ComputationError(Reason::kRefused, message) {}
};

// Renders `gnuplot_script` into `png_path`. Unless the script chooses a
// terminal itself (a line starting "set term..."), "set terminal pngcairo size
// 800,500 noenhanced" (labels printed as written: an underscore is not a
// subscript) is put before it; "set output" naming png_path always is, after
// that terminal line. Then checks that gnuplot exited with status 0 and that
// png_path exists and is not empty. A file already at png_path is removed
// first, and a failed plot leaves none. Inline data (`$data << EOD ... EOD`) keeps a plot
// self-contained.
void RenderPlot(const std::string& gnuplot_script, const std::string& png_path);

}  // namespace vahf::report
