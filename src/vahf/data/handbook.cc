#include "vahf/data/handbook.h"

#include <fmt/format.h>

#include <map>
#include <optional>

#include "vahf/core/error.h"
#include "vahf/core/whole_file.h"
#include "vahf/data/csv.h"

namespace vahf::data {
namespace {

// A handbook time is positive; one insertion element lasting more than an
// hour is a unit mistake.
constexpr double kMaxTmu = 100000;  // 1 h
constexpr double kMaxSeconds = 3600;

double ReadTime(const CsvCell& cell, double max, const char* unit) {
  const double t = cell.Number();
  if (!(t > 0 && t <= max))
    cell.Fail(fmt::format("a handbook time is positive and at most {} {}", max, unit));
  return t;
}

// Refuses a second row of one code, naming the first.
void CheckUnique(std::map<std::string, int>& first_line, const CsvCell& code) {
  const auto [it, inserted] = first_line.emplace(code.text(), code.line());
  if (!inserted)
    code.Fail(fmt::format("duplicate code: line {} gives it already", it->second));
}

std::string ReadText(const std::string& path) {
  std::optional<std::string> text = ReadWholeFile(path);
  if (!text) throw InputError(path, "file", "", "cannot open the file for reading");
  return *std::move(text);
}

}  // namespace

std::string MtmPositionCode(int fit_class, const std::string& symmetry,
                            const std::string& handling) {
  return fmt::format("P{}{}{}", fit_class, symmetry, handling == "easy" ? "E" : "D");
}

const MtmPositionTime* MtmPositionTable::Find(const std::string& code) const {
  for (const MtmPositionTime& r : rows)
    if (r.code == code) return &r;
  return nullptr;
}

const BdInsertionTime* BdInsertionTable::Find(const std::string& code) const {
  for (const BdInsertionTime& r : rows)
    if (r.code == code) return &r;
  return nullptr;
}

bool IsBdInsertionCode(const std::string& code) {
  if (code.size() != 2 || code[0] < '0' || code[0] > '5' || code[1] < '0' ||
      code[1] > '9')
    return false;
  const int column = code[1] - '0';
  return code[0] >= '3' || column <= 3 || column >= 6;
}

MtmPositionTable ParseMtmPosition(const std::string& text, const std::string& file) {
  const CsvTable t(ParseCsv(text, file),
                   {"code", "fit_class", "symmetry", "handling", "tmu", "source"},
                   {"description"});
  MtmPositionTable out;
  out.file = file;
  std::map<std::string, int> first_line;
  for (const CsvRow& row : t.rows()) {
    MtmPositionTime x;
    x.line = row.line;
    x.fit_class = static_cast<int>(t.Cell(row, "fit_class").Integer(1, 3));
    x.symmetry = t.Cell(row, "symmetry").Choice({"S", "SS", "NS"});
    x.handling = t.Cell(row, "handling").Choice({"easy", "difficult"});
    const CsvCell code = t.Cell(row, "code");
    x.code = code.Text();
    const std::string expected = MtmPositionCode(x.fit_class, x.symmetry, x.handling);
    if (x.code != expected)
      code.Fail(fmt::format(
          "unknown code for this row: a Position code is P<fit class><S|SS|NS><E|D>, "
          "here {}",
          expected));
    CheckUnique(first_line, code);
    x.tmu = ReadTime(t.Cell(row, "tmu"), kMaxTmu, "TMU");
    x.source = t.Cell(row, "source").Text();
    out.rows.push_back(std::move(x));
  }
  return out;
}

BdInsertionTable ParseBdInsertion(const std::string& text, const std::string& file) {
  const CsvTable t(
      ParseCsv(text, file), {"code", "seconds", "source"},
      {"section", "access_vision", "holding_down", "align", "resistance", "description"});
  BdInsertionTable out;
  out.file = file;
  std::map<std::string, int> first_line;
  for (const CsvRow& row : t.rows()) {
    BdInsertionTime x;
    x.line = row.line;
    const CsvCell code = t.Cell(row, "code");
    x.code = code.Text();
    if (!IsBdInsertionCode(x.code))
      code.Fail(
          "unknown code: a manual insertion code is two digits, rows 0-2 with columns "
          "0-3 or 6-9, rows 3-5 with columns 0-9");
    CheckUnique(first_line, code);
    x.row = x.code[0] - '0';
    x.column = x.code[1] - '0';
    x.seconds = ReadTime(t.Cell(row, "seconds"), kMaxSeconds, "s");
    x.source = t.Cell(row, "source").Text();
    out.rows.push_back(std::move(x));
  }
  return out;
}

MtmPositionTable ReadMtmPosition(const std::string& path) {
  return ParseMtmPosition(ReadText(path), path);
}

BdInsertionTable ReadBdInsertion(const std::string& path) {
  return ParseBdInsertion(ReadText(path), path);
}

}  // namespace vahf::data
