// A Markdown table described as data: a heading per column and rows of cell
// text, written by one writer, so that every table of report.md has the same
// form ("| a | b |", then "| --- | --- |", then one line per row).
#pragma once

#include <string>
#include <vector>

namespace vahf::report {

class MarkdownTable {
 public:
  // At least one heading (else a bug).
  explicit MarkdownTable(std::vector<std::string> headings);

  // One cell per heading (else a bug).
  void AddRow(std::vector<std::string> cells);

 private:
  friend std::string ToMarkdown(const MarkdownTable& table);
  std::vector<std::string> headings_;
  std::vector<std::vector<std::string>> rows_;
};

// "| h1 | h2 |\n| --- | --- |\n| c1 | c2 |\n": each cell between "| " and " |".
std::string ToMarkdown(const MarkdownTable& table);

}  // namespace vahf::report
