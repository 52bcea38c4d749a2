#include "vahf/report/result_diff.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "vahf/core/error.h"
#include "vahf/data/csv.h"

namespace vahf::report {
namespace {

constexpr const char* kEnd = "(end of file)";

std::string Shortened(const std::string& text) {
  constexpr std::size_t kMax = 60, kHead = 40, kTail = kMax - kHead - 3;
  if (text.size() <= kMax) return text;
  return text.substr(0, kHead) + "..." + text.substr(text.size() - kTail);
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) {
      out.push_back(text.substr(start));
      break;
    }
    out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

ResultDifference ByLine(const std::string& name, const std::string& recorded,
                        const std::string& rerun) {
  const std::vector<std::string> a = Lines(recorded), b = Lines(rerun);
  std::size_t i = 0;
  while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
  ResultDifference d;
  d.file = name;
  d.line = static_cast<int>(i) + 1;
  d.recorded = i < a.size() ? a[i] : kEnd;
  d.rerun = i < b.size() ? b[i] : kEnd;
  // Equal lines but unequal bytes: only a final line break differs.
  if (d.recorded == d.rerun) d.recorded = recorded.size() > rerun.size() ? "\\n" : kEnd;
  if (d.recorded == d.rerun) d.rerun = "\\n";
  return d;
}

// Field by field; nothing when the parsed tables are equal (the bytes may
// still differ, in quoting or line ends: the caller then compares lines).
std::optional<ResultDifference> ByField(const std::string& name, const data::CsvFile& a,
                                        const data::CsvFile& b) {
  ResultDifference d;
  d.file = name;
  if (a.header != b.header) {
    d.line = a.header_line;
    d.recorded = data::CsvLine(a.header);
    d.rerun = data::CsvLine(b.header);
    d.recorded.pop_back();  // CsvLine's "\n"
    d.rerun.pop_back();
    return d;
  }
  const std::size_t rows = std::max(a.rows.size(), b.rows.size());
  for (std::size_t r = 0; r < rows; ++r) {
    d.row = static_cast<int>(r) + 1;
    if (r >= a.rows.size() || r >= b.rows.size()) {
      const data::CsvRow& present = r < a.rows.size() ? a.rows[r] : b.rows[r];
      d.line = present.line;
      d.recorded = r < a.rows.size() ? data::CsvLine(present.fields) : kEnd;
      d.rerun = r < b.rows.size() ? data::CsvLine(present.fields) : kEnd;
      for (std::string* s : {&d.recorded, &d.rerun})
        if (!s->empty() && s->back() == '\n') s->pop_back();
      return d;
    }
    const data::CsvRow &ra = a.rows[r], &rb = b.rows[r];
    for (std::size_t c = 0; c < ra.fields.size(); ++c) {
      if (ra.fields[c] == rb.fields[c]) continue;
      d.line = ra.lines[c];
      d.column = a.header[c];
      d.recorded = ra.fields[c];
      d.rerun = rb.fields[c];
      return d;
    }
  }
  return std::nullopt;
}

bool EndsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() &&
         s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

std::string ResultDifference::Text() const {
  std::string where;
  if (row > 0) {
    where = fmt::format("row {} (line {})", row, line);
    if (!column.empty()) where += ", column " + column;
  } else {
    where = fmt::format("line {}", line);
  }
  return fmt::format("{}: {}: {} in the run, {} in the re-run", file, where,
                     Shortened(recorded), Shortened(rerun));
}

std::optional<ResultDifference> FirstDifference(const std::string& name,
                                                const std::string& recorded,
                                                const std::string& rerun) {
  if (recorded == rerun) return std::nullopt;
  if (EndsWith(name, ".csv")) {
    try {
      const data::CsvFile a = data::ParseCsv(recorded, name);
      const data::CsvFile b = data::ParseCsv(rerun, name);
      if (auto d = ByField(name, a, b)) return d;
    } catch (const InputError&) {
      // Not a table both sides can read (an edit broke a row): by line.
    }
  }
  return ByLine(name, recorded, rerun);
}

}  // namespace vahf::report
