// Reads and writes the CSV dialect of lab datasets (docs/lab-data.md, "CSV"):
// RFC 4180 (comma separator, double-quoted fields with doubled quotes, line
// breaks allowed inside quotes; LF or CRLF line ends), a header line, '#'
// comment lines and blank lines ignored, every row as wide as the header.
// Every error is a vahf::InputError naming the file, "line L, column NAME"
// (L the physical 1-based line), the value and the rule.
//
// Hand-written rather than on a Debian library because neither fits: libcsv
// (libcsv-dev) reports no line or column, knows no comment lines and trims
// spaces, and the Fast C++ CSV Parser (libfccp-dev) fixes the column count at
// compile time and reads a line at a time, so a quoted field cannot hold a
// line break.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vahf::data {

// One data row: its fields in header order, and the physical line where each
// field starts (a quoted field may span lines).
struct CsvRow {
  std::vector<std::string> fields;
  std::vector<int> lines;
  int line = 0;  // where the row starts
};

struct CsvFile {
  std::string file;  // for messages
  int header_line = 0;
  std::vector<std::string> header;
  std::vector<CsvRow> rows;
};

// Parses `text` read from `file`. A UTF-8 byte order mark is skipped.
CsvFile ParseCsv(const std::string& text, const std::string& file);

// One field of a row, as the rules of a column read it.
class CsvCell {
 public:
  CsvCell(const std::string& file, const std::string& column, const std::string& text,
          int line);

  const std::string& text() const { return *text_; }
  bool empty() const { return text_->empty(); }
  int line() const { return line_; }
  // "line L, column NAME".
  std::string Where() const;

  // Throws InputError at this cell with `rule`.
  [[noreturn]] void Fail(const std::string& rule) const;

  // Strict decimal over the whole field ([+-]digits[.digits][e[+-]digits]):
  // no spaces, hex, NaN, infinities or empty field; finite as a double.
  double Number() const;
  // A decimal integer (optional sign, digits only) in [min, max].
  std::int64_t Integer(std::int64_t min, std::int64_t max) const;
  // Non-empty text.
  const std::string& Text() const;
  // One of `choices`.
  const std::string& Choice(const std::vector<std::string>& choices) const;

 private:
  const std::string* file_;
  const std::string* column_;
  const std::string* text_;
  int line_;
};

// A parsed file bound to the columns its format knows: every required column
// is in the header, and every header column is required or optional (columns
// in any order). An InputError names the header line and the column otherwise.
class CsvTable {
 public:
  CsvTable(CsvFile csv, const std::vector<std::string>& required,
           const std::vector<std::string>& optional);

  const CsvFile& csv() const { return csv_; }
  const std::vector<CsvRow>& rows() const { return csv_.rows; }
  bool Has(const std::string& column) const { return Index(column) >= 0; }
  // The cell of a column the header has (asking for another is a bug).
  CsvCell Cell(const CsvRow& row, const std::string& column) const;
  // The cell, or nothing when the header lacks the column.
  std::optional<CsvCell> Optional(const CsvRow& row, const std::string& column) const;

 private:
  int Index(const std::string& column) const;

  CsvFile csv_;
};

// A field as the dialect writes it: quoted (its quotes doubled) when it holds
// a comma, quote, CR or LF, begins with '#' (it would read as a comment) or
// is the only, empty, field of its row (it would read as a blank line).
std::string CsvField(const std::string& text, bool only_field = false);
// A row: the fields joined by commas, ended by "\n".
std::string CsvLine(const std::vector<std::string>& fields);

}  // namespace vahf::data
