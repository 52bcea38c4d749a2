// Where two versions of a result file first differ, for `vahf verify`
// (docs/reproducibility.md): a CSV table by data row and column, any other
// file (summary.json) by line, so that a reviewer is pointed at the value
// that moved, not only told that a digest did.
#pragma once

#include <optional>
#include <string>

namespace vahf::report {

struct ResultDifference {
  std::string file;      // the result file's name, as the manifest lists it
  int line = 0;          // 1-based physical line of the first difference
  int row = 0;           // a CSV's 1-based data row (the header is row 0); 0 otherwise
  std::string column;    // a CSV's column name; empty otherwise
  std::string recorded;  // the field or line as the run wrote it
  std::string rerun;     // and as the re-run did
  // "table1_instants.csv: row 3 (line 4), column eta: 0.512 in the run, 0.513
  // in the re-run"; a value past 60 characters is cut in the middle.
  std::string Text() const;
};

// The first difference between `recorded` and `rerun`, the bytes of result
// file `name`; nothing when they are equal. A file whose name ends in .csv
// and which both sides parse as CSV (data/csv.h) is compared field by field;
// otherwise line by line. A side that ends first differs at the next line,
// its value "(end of file)".
std::optional<ResultDifference> FirstDifference(const std::string& name,
                                                const std::string& recorded,
                                                const std::string& rerun);

}  // namespace vahf::report
