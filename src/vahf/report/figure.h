// A gnuplot figure described as data: inline data blocks of rows, the
// settings in the order gnuplot reads them, and the series to draw; one
// writer, GnuplotScript, turns it into the script that RenderPlot (plot.h)
// renders. A script is self-contained: its data travels inline.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vahf/stats/summary.h"

namespace vahf::report {

// One line of inline data: fields separated by one space.
class DataRow {
 public:
  DataRow& Number(double x);                // shortest form that reads back: 0.1, 1e-05
  DataRow& Integer(std::int64_t i);         // decimal
  DataRow& Short(double x);                 // printf's %g: six significant digits
  DataRow& Label(const std::string& text);  // "text" as written, for xtic()
  // A summary's mean and 95 % interval as three fields: NaN (not drawn) without
  // a mean, the mean thrice without an interval.
  DataRow& MeanAndInterval(const stats::Summary& s);
  std::string Text() const;

 private:
  std::string text_;
};

// "DATA using COLUMNS STYLE title 'TITLE'": DATA a block ("$d"), "''" for the
// one before, or a function ("0.5"); no `using` without columns; STYLE as
// written ("with yerrorbars pt 7", "lc rgb 'white'"), or none.
struct Series {
  std::string data = "$d";
  std::string columns;
  std::string style;
  std::optional<std::string> title;  // quoted as GnuplotString; none: notitle
};

class Figure {
 public:
  // "set terminal WHAT", before the data (by default RenderPlot chooses).
  Figure& Terminal(const std::string& what);
  // An inline block `$name << EOD`; blocks come first in the script.
  Figure& Data(const std::string& name, const std::vector<DataRow>& rows);
  // "set title 'TEXT'" and the axis labels, quoted by GnuplotString.
  Figure& Title(const std::string& text);
  Figure& XLabel(const std::string& text);
  Figure& YLabel(const std::string& text);
  // "set WHAT" as written: "grid", "yrange [0:1]", "key left top".
  Figure& Set(const std::string& what);
  Figure& Unset(const std::string& what);
  // "set xrange [-0.5:N-0.5]": N categories at 0, 1, ..., N-1.
  Figure& CategoryRange(std::size_t n);
  // A series of the plot command after the last setting (a new command when
  // a setting came since the last series: a multiplot's next panel).
  Figure& Draw(Series series);

 private:
  friend std::string GnuplotScript(const Figure& figure);
  // A setting line, or (line empty) a plot command of these series.
  struct Step {
    std::string line;
    std::vector<Series> plot;
  };
  std::string terminal_;
  std::string data_;
  std::vector<Step> steps_;
};

// The terminal, the data blocks, then the settings and plot commands in the
// order given, each on a line of its own, a plot command joining its series
// with ", "; a figure that plots nothing is a bug.
std::string GnuplotScript(const Figure& figure);

// A gnuplot string literal taken as written: 'text', a single quote inside
// doubled.
std::string GnuplotString(const std::string& text);

}  // namespace vahf::report
