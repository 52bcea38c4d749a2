#include "vahf/data/csv.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string_view>
#include <system_error>

#include "vahf/core/error.h"

namespace vahf::data {
namespace {

// The value as a message shows it: as written, unless blanks at its ends or
// control characters would hide what is wrong (then as a JSON string), and
// shortened in the middle when long.
std::string Shown(const std::string& text) {
  if (text.empty()) return "(empty)";
  const auto blank = [](unsigned char c) { return c <= ' ' || c == 0x7f; };
  const bool plain = !blank(static_cast<unsigned char>(text.front())) &&
                     !blank(static_cast<unsigned char>(text.back())) &&
                     std::none_of(text.begin(), text.end(),
                                  [](unsigned char c) { return c < ' ' || c == 0x7f; });
  const std::string shown =
      plain ? text
            : nlohmann::json(text).dump(-1, ' ', false,
                                        nlohmann::json::error_handler_t::replace);
  constexpr std::size_t kMax = 100, kHead = 60, kTail = kMax - kHead - 3;
  if (shown.size() <= kMax) return shown;
  return shown.substr(0, kHead) + "..." + shown.substr(shown.size() - kTail);
}

std::string Joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// [+-]?(D+(.D*)?|.D+)([eE][+-]?D+)? over the whole of `s`.
bool IsDecimal(std::string_view s) {
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t start = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    return i - start;
  };
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t mantissa = digits();
  if (i < s.size() && s[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == s.size();
}

// Parses one file; `line` is the physical line at `pos`.
class Parser {
 public:
  Parser(const std::string& text, const std::string& file) : text_(text), file_(file) {
    if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0) pos_ = 3;
  }

  CsvFile Parse() {
    CsvFile out;
    out.file = file_;
    bool have_header = false;
    while (pos_ < text_.size()) {
      if (AtLineEnd()) {  // a blank line
        SkipLineEnd();
        continue;
      }
      if (text_[pos_] == '#') {  // a comment, only where a row would begin
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
        if (pos_ < text_.size()) SkipLineEnd();
        continue;
      }
      CsvRow row = Record(have_header ? &out.header : nullptr);
      if (!have_header) {
        CheckHeader(row);
        out.header = std::move(row.fields);
        out.header_line = row.line;
        have_header = true;
        continue;
      }
      CheckWidth(row, out);
      out.rows.push_back(std::move(row));
    }
    if (!have_header)
      throw InputError(file_, "", "", "no header line: the file holds no rows");
    return out;
  }

 private:
  bool AtLineEnd() const {
    return text_[pos_] == '\n' ||
           (text_[pos_] == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n');
  }
  void SkipLineEnd() {
    pos_ += text_[pos_] == '\r' ? 2 : 1;
    ++line_;
  }

  static std::string ColumnName(const std::vector<std::string>* header, std::size_t k) {
    if (header && k < header->size()) return (*header)[k];
    return std::to_string(k + 1);
  }

  [[noreturn]] void Fail(int line, const std::vector<std::string>* header, std::size_t k,
                         const std::string& value, const std::string& rule) const {
    throw InputError(file_,
                     fmt::format("line {}, column {}", line, ColumnName(header, k)),
                     Shown(value), rule);
  }

  // One row from `pos_` to the end of its last line.
  CsvRow Record(const std::vector<std::string>* header) {
    CsvRow row;
    row.line = line_;
    while (true) {
      const std::size_t k = row.fields.size();
      const int field_line = line_;
      std::string field;
      bool row_ends = false;
      if (pos_ < text_.size() && text_[pos_] == '"') {
        ++pos_;
        while (true) {
          if (pos_ >= text_.size())  // shown up to the end of its first line
            Fail(field_line, header, k, "\"" + field.substr(0, field.find('\n')),
                 "a quoted field is not closed: the file ends inside its quotes");
          const char c = text_[pos_];
          if (c == '"') {
            if (pos_ + 1 < text_.size() && text_[pos_ + 1] == '"') {
              field += '"';
              pos_ += 2;
              continue;
            }
            ++pos_;
            break;
          }
          if (c == '\n') ++line_;
          field += c;
          ++pos_;
        }
        if (pos_ >= text_.size()) {
          row_ends = true;
        } else if (text_[pos_] == ',') {
          ++pos_;
        } else if (AtLineEnd()) {
          SkipLineEnd();
          row_ends = true;
        } else {
          Fail(field_line, header, k, "\"" + field + "\"" + text_[pos_],
               "a closing quote must be followed by a comma or the end of the line "
               "(a quote inside a quoted field is written twice: \"\")");
        }
      } else {
        while (pos_ < text_.size() && text_[pos_] != ',' && !AtLineEnd()) {
          const char c = text_[pos_];
          if (c == '"')
            Fail(field_line, header, k, field + text_.substr(pos_, 1),
                 "a quote may only open a field: quote the whole field and write the "
                 "quote twice (\"\")");
          if (c == '\r')
            Fail(field_line, header, k, field + "\r",
                 "a carriage return outside quotes must be followed by a line feed");
          field += c;
          ++pos_;
        }
        if (pos_ >= text_.size()) {
          row_ends = true;
        } else if (text_[pos_] == ',') {
          ++pos_;
        } else {
          SkipLineEnd();
          row_ends = true;
        }
      }
      row.fields.push_back(std::move(field));
      row.lines.push_back(field_line);
      if (row_ends) return row;
    }
  }

  void CheckHeader(const CsvRow& row) const {
    for (std::size_t k = 0; k < row.fields.size(); ++k) {
      if (row.fields[k].empty())
        Fail(row.lines[k], nullptr, k, "", "a header names every column");
      for (std::size_t j = 0; j < k; ++j)
        if (row.fields[j] == row.fields[k])
          Fail(row.lines[k], &row.fields, k, row.fields[k],
               fmt::format("column '{}' appears twice in the header (also column {})",
                           row.fields[k], j + 1));
    }
  }

  void CheckWidth(const CsvRow& row, const CsvFile& out) const {
    const std::size_t n = out.header.size(), m = row.fields.size();
    if (m == n) return;
    const std::string rule = fmt::format(
        "the row has {} field{}, the header (line {}) {}: every row has one field per "
        "column",
        m, m == 1 ? "" : "s", out.header_line, n);
    if (m < n)
      throw InputError(file_,
                       fmt::format("line {}, column {}", row.lines.back(), out.header[m]),
                       "(missing)", rule);
    Fail(row.lines[n], &out.header, n, row.fields[n], rule);
  }

  const std::string& text_;
  const std::string& file_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

}  // namespace

CsvFile ParseCsv(const std::string& text, const std::string& file) {
  return Parser(text, file).Parse();
}

CsvCell::CsvCell(const std::string& file, const std::string& column,
                 const std::string& text, int line)
    : file_(&file), column_(&column), text_(&text), line_(line) {}

std::string CsvCell::Where() const {
  return fmt::format("line {}, column {}", line_, *column_);
}

void CsvCell::Fail(const std::string& rule) const {
  throw InputError(*file_, Where(), Shown(*text_), rule);
}

double CsvCell::Number() const {
  const std::string& s = *text_;
  if (s.empty()) Fail("must be a number, not empty");
  if (!IsDecimal(s)) {
    std::string lower = s;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (lower.find("nan") != std::string::npos || lower.find("inf") != std::string::npos)
      Fail("must be a finite decimal number (NaN and infinities are not measurements)");
    Fail(
        "must be a decimal number (digits, an optional sign, point and exponent; "
        "nothing else in the field)");
  }
  // from_chars takes no '+' and ignores the locale.
  const char* first = s.data() + (s[0] == '+' ? 1 : 0);
  double value = 0;
  const auto [end, ec] = std::from_chars(first, s.data() + s.size(), value);
  if (ec == std::errc::result_out_of_range || !std::isfinite(value))
    Fail("lies outside the range of a double");
  if (ec != std::errc() || end != s.data() + s.size()) Fail("must be a decimal number");
  return value;
}

std::int64_t CsvCell::Integer(std::int64_t min, std::int64_t max) const {
  const std::string& s = *text_;
  const std::string range = max == std::numeric_limits<std::int64_t>::max() ||
                                    max == std::numeric_limits<int>::max()
                                ? fmt::format("an integer >= {}", min)
                                : fmt::format("an integer from {} to {}", min, max);
  if (s.empty()) Fail("must be " + range + ", not empty");
  const std::size_t sign = (s[0] == '+' || s[0] == '-') ? 1 : 0;
  if (s.size() == sign ||
      !std::all_of(s.begin() + static_cast<std::ptrdiff_t>(sign), s.end(),
                   [](char c) { return c >= '0' && c <= '9'; }))
    Fail("must be " + range + " (digits only)");
  std::int64_t value = 0;
  const char* first = s.data() + (s[0] == '+' ? 1 : 0);
  const auto [end, ec] = std::from_chars(first, s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size() || value < min || value > max)
    Fail("must be " + range);
  return value;
}

const std::string& CsvCell::Text() const {
  if (text_->empty()) Fail("must not be empty");
  return *text_;
}

const std::string& CsvCell::Choice(const std::vector<std::string>& choices) const {
  if (std::find(choices.begin(), choices.end(), *text_) == choices.end())
    Fail("must be one of: " + Joined(choices));
  return *text_;
}

CsvTable::CsvTable(CsvFile csv, const std::vector<std::string>& required,
                   const std::vector<std::string>& optional)
    : csv_(std::move(csv)) {
  const std::string where_header = fmt::format("line {}", csv_.header_line);
  for (const std::string& name : csv_.header) {
    if (std::find(required.begin(), required.end(), name) != required.end() ||
        std::find(optional.begin(), optional.end(), name) != optional.end())
      continue;
    std::vector<std::string> known = required;
    known.insert(known.end(), optional.begin(), optional.end());
    throw InputError(csv_.file, where_header + ", column " + name, Shown(name),
                     "unknown column (columns are lower case; this file takes: " +
                         Joined(known) + ")");
  }
  for (const std::string& name : required)
    if (!Has(name))
      throw InputError(csv_.file, where_header + ", column " + name, "(missing)",
                       "the header lacks the required column '" + name + "'");
}

int CsvTable::Index(const std::string& column) const {
  const auto it = std::find(csv_.header.begin(), csv_.header.end(), column);
  return it == csv_.header.end() ? -1 : static_cast<int>(it - csv_.header.begin());
}

CsvCell CsvTable::Cell(const CsvRow& row, const std::string& column) const {
  const auto cell = Optional(row, column);
  VAHF_CHECK(cell.has_value(), "no column '" + column + "' in " + csv_.file);
  return *cell;
}

std::optional<CsvCell> CsvTable::Optional(const CsvRow& row,
                                          const std::string& column) const {
  const int k = Index(column);
  if (k < 0) return std::nullopt;
  return CsvCell(csv_.file, csv_.header[static_cast<std::size_t>(k)],
                 row.fields[static_cast<std::size_t>(k)],
                 row.lines[static_cast<std::size_t>(k)]);
}

std::string CsvField(const std::string& text, bool only_field) {
  const bool quote = text.find_first_of(",\"\r\n") != std::string::npos ||
                     (!text.empty() && text[0] == '#') || (only_field && text.empty());
  if (!quote) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string CsvLine(const std::vector<std::string>& fields) {
  std::string out;
  for (std::size_t k = 0; k < fields.size(); ++k)
    out += (k ? "," : "") + CsvField(fields[k], fields.size() == 1);
  return out + "\n";
}

}  // namespace vahf::data
