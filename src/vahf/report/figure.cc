#include "vahf/report/figure.h"

#include <fmt/format.h>

#include <cmath>

#include "vahf/core/error.h"

namespace vahf::report {
namespace {

std::string SeriesText(const Series& s) {
  std::string out = s.data;
  if (!s.columns.empty()) out += " using " + s.columns;
  if (!s.style.empty()) out += " " + s.style;
  return out + (s.title ? " title " + GnuplotString(*s.title) : " notitle");
}

}  // namespace

DataRow& DataRow::Number(double x) {
  text_ += fmt::format("{}{}", text_.empty() ? "" : " ", x);
  return *this;
}

DataRow& DataRow::Integer(std::int64_t i) {
  text_ += fmt::format("{}{}", text_.empty() ? "" : " ", i);
  return *this;
}

DataRow& DataRow::Short(double x) {
  text_ += fmt::format("{}{:g}", text_.empty() ? "" : " ", x);
  return *this;
}

DataRow& DataRow::Label(const std::string& text) {
  text_ += fmt::format("{}\"{}\"", text_.empty() ? "" : " ", text);
  return *this;
}

DataRow& DataRow::MeanAndInterval(const stats::Summary& s) {
  const double mean = s.mean.value_or(NAN);
  return Number(mean).Number(s.ci ? s.ci->lower : mean).Number(s.ci ? s.ci->upper : mean);
}

std::string DataRow::Text() const { return text_; }

Figure& Figure::Terminal(const std::string& what) {
  terminal_ = "set terminal " + what + "\n";
  return *this;
}

Figure& Figure::Data(const std::string& name, const std::vector<DataRow>& rows) {
  data_ += "$" + name + " << EOD\n";
  for (const DataRow& r : rows) data_ += r.Text() + "\n";
  data_ += "EOD\n";
  return *this;
}

Figure& Figure::Title(const std::string& text) {
  return Set("title " + GnuplotString(text));
}

Figure& Figure::XLabel(const std::string& text) {
  return Set("xlabel " + GnuplotString(text));
}

Figure& Figure::YLabel(const std::string& text) {
  return Set("ylabel " + GnuplotString(text));
}

Figure& Figure::Set(const std::string& what) {
  steps_.push_back({"set " + what, {}});
  return *this;
}

Figure& Figure::Unset(const std::string& what) {
  steps_.push_back({"unset " + what, {}});
  return *this;
}

Figure& Figure::CategoryRange(std::size_t n) {
  return Set(fmt::format("xrange [-0.5:{}-0.5]", n));
}

Figure& Figure::Draw(Series series) {
  if (steps_.empty() || !steps_.back().line.empty()) steps_.push_back({});
  steps_.back().plot.push_back(std::move(series));
  return *this;
}

std::string GnuplotScript(const Figure& figure) {
  std::string out = figure.terminal_ + figure.data_;
  bool plots = false;
  for (const Figure::Step& step : figure.steps_) {
    if (!step.line.empty()) {
      out += step.line + "\n";
      continue;
    }
    plots = true;
    out += "plot ";
    for (std::size_t i = 0; i < step.plot.size(); ++i)
      out += (i ? ", " : "") + SeriesText(step.plot[i]);
    out += "\n";
  }
  VAHF_CHECK(plots, "a figure plots nothing");
  return out;
}

std::string GnuplotString(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

}  // namespace vahf::report
