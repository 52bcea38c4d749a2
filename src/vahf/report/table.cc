#include "vahf/report/table.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "vahf/core/error.h"

namespace vahf::report {
namespace {

std::string Field(const std::string& text, bool alone_on_line) {
  const bool quote = text.find_first_of(",\"\r\n") != std::string::npos ||
                     (alone_on_line && text.empty());
  if (!quote) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + '"';
}

std::string CellText(const Table::Cell& cell) {
  if (const double* x = std::get_if<double>(&cell)) {
    // fmt writes nan and inf already; the sign of a NaN is not data.
    return std::isnan(*x) ? std::string("nan") : fmt::format("{}", *x);
  }
  if (const std::int64_t* i = std::get_if<std::int64_t>(&cell))
    return fmt::format("{}", *i);
  return std::get<std::string>(cell);
}

}  // namespace

Table::Table(std::vector<std::string> columns) : columns_(std::move(columns)) {
  VAHF_CHECK(!columns_.empty(), "a table needs at least one column");
  std::set<std::string> seen;
  for (const std::string& c : columns_) {
    VAHF_CHECK(!c.empty(), "a column name is empty");
    VAHF_CHECK(seen.insert(c).second, "column '" + c + "' appears twice");
  }
}

const Table::Cell& Table::at(std::size_t row, std::size_t column) const {
  VAHF_CHECK(row < cells_.size() && column < columns_.size(),
             fmt::format("cell ({}, {}) outside a {} x {} table", row, column,
                         cells_.size(), columns_.size()));
  return cells_[row][column];
}

void Table::AddRow(std::vector<Cell> row) {
  VAHF_CHECK(
      row.size() == columns_.size(),
      fmt::format("a row of {} cells for {} columns", row.size(), columns_.size()));
  cells_.push_back(std::move(row));
}

std::string Table::ToCsv() const {
  const bool alone = columns_.size() == 1;
  std::string out;
  const auto line = [&](const std::vector<std::string>& fields) {
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (i > 0) out += ',';
      out += Field(fields[i], alone);
    }
    out += '\n';
  };
  line(columns_);
  std::vector<std::string> fields(columns_.size());
  for (const std::vector<Cell>& row : cells_) {
    std::transform(row.begin(), row.end(), fields.begin(), CellText);
    line(fields);
  }
  return out;
}

}  // namespace vahf::report
