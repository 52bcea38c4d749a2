// A tidy table: named columns, one observation per row, each cell a double, an
// integer or a string; written as CSV with deterministic formatting, so equal
// tables give equal bytes (the results digest of manifest.h relies on it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace vahf::report {

class Table {
 public:
  // A cell: write an int64 as std::int64_t{...}, a count of type size_t as
  // static_cast<std::int64_t>(...).
  using Cell = std::variant<double, std::int64_t, std::string>;

  // Column names must be non-empty and distinct (a broken invariant: a bug).
  explicit Table(std::vector<std::string> columns);

  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t rows() const { return cells_.size(); }
  const Cell& at(std::size_t row, std::size_t column) const;

  // One cell per column, in column order (else a bug).
  void AddRow(std::vector<Cell> row);

  // RFC 4180 CSV with "\n" line ends: a header line, then one line per row.
  // Doubles in the shortest form that reads back to the same bits
  // (fmt::format("{}", x): 0.1, 1e-05, 3), NaN and infinities as nan, inf,
  // -inf; integers in decimal; a field is quoted (its quotes doubled) only
  // when it holds a comma, quote, CR or LF, or when an empty field would
  // otherwise make a blank line.
  std::string ToCsv() const;

 private:
  std::vector<std::string> columns_;
  std::vector<std::vector<Cell>> cells_;
};

}  // namespace vahf::report
