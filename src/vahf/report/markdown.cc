#include "vahf/report/markdown.h"

#include <fmt/format.h>

#include <utility>

#include "vahf/core/error.h"

namespace vahf::report {
namespace {

std::string Line(const std::vector<std::string>& cells) {
  std::string out = "|";
  for (const std::string& c : cells) out += " " + c + " |";
  return out + "\n";
}

}  // namespace

MarkdownTable::MarkdownTable(std::vector<std::string> headings)
    : headings_(std::move(headings)) {
  VAHF_CHECK(!headings_.empty(), "a Markdown table needs at least one heading");
}

void MarkdownTable::AddRow(std::vector<std::string> cells) {
  VAHF_CHECK(cells.size() == headings_.size(),
             fmt::format("a Markdown row of {} cells under {} headings", cells.size(),
                         headings_.size()));
  rows_.push_back(std::move(cells));
}

std::string ToMarkdown(const MarkdownTable& table) {
  std::string out = Line(table.headings_);
  out += Line(std::vector<std::string>(table.headings_.size(), "---"));
  for (const std::vector<std::string>& row : table.rows_) out += Line(row);
  return out;
}

}  // namespace vahf::report
