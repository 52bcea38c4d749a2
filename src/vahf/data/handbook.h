// The assembly-time handbooks as data (data/handbooks/README.md): the MTM-1
// Position element times and the Boothroyd-Dewhurst manual insertion times,
// each row with its source. Read with the lab datasets' CSV dialect
// (data/csv.h); every fault is one vahf::InputError naming the file, "line L,
// column NAME", the value and the rule: a missing or unknown column, an
// unknown code, a time that is not a positive finite number, a duplicate code.
#pragma once

#include <string>
#include <vector>

namespace vahf::data {

// 1 TMU = 0.00001 h = 0.036 s: MTM-1 data card (MTM Association e.V.,
// Hamburg, 2019 edition, "Time Units" box).
inline constexpr double kSecondsPerTmu = 0.036;

// One MTM-1 Position time: code P<fit class><symmetry><handling>, e.g.
// "P2SE" (class 2, symmetric, easy to handle).
struct MtmPositionTime {
  std::string code;
  int fit_class = 0;     // 1 loose, 2 close, 3 exact
  std::string symmetry;  // "S", "SS" or "NS"
  std::string handling;  // "easy" or "difficult"
  double tmu = 0;        // > 0
  std::string source;
  int line = 0;  // in its file
  double seconds() const { return tmu * kSecondsPerTmu; }
};

// The MTM-1 code of a class: "P" + fit class + symmetry + "E" (easy) or "D".
std::string MtmPositionCode(int fit_class, const std::string& symmetry,
                            const std::string& handling);

struct MtmPositionTable {
  std::string file;
  std::vector<MtmPositionTime> rows;  // in file order; may be empty
  // The row of `code`, or nullptr.
  const MtmPositionTime* Find(const std::string& code) const;
};

// One Boothroyd-Dewhurst manual insertion time: a two-digit code, first digit
// the row (0-2 added but not secured, 3-5 secured immediately; within each,
// access and vision: easy, obstructed or restricted, obstructed and
// restricted), second the column (holding down, alignment, resistance; for
// rows 3-5 the way the part is secured).
struct BdInsertionTime {
  std::string code;
  int row = 0, column = 0;  // the code's digits
  double seconds = 0;       // > 0
  std::string source;
  int line = 0;
};

struct BdInsertionTable {
  std::string file;
  std::vector<BdInsertionTime> rows;
  const BdInsertionTime* Find(const std::string& code) const;
};

// Whether `code` names a cell of the manual insertion chart this loader
// knows: rows 0-2 with columns 0-3 and 6-9, rows 3-5 with columns 0-9.
bool IsBdInsertionCode(const std::string& code);

// Parse `text` read from `file`. Columns (any order): code, fit_class,
// symmetry, handling, tmu, source, optional description.
MtmPositionTable ParseMtmPosition(const std::string& text, const std::string& file);
// Columns: code, seconds, source; optional section, access_vision,
// holding_down, align, resistance, description (text, as the README names
// them).
BdInsertionTable ParseBdInsertion(const std::string& text, const std::string& file);

// Read and parse a file; an unreadable file is an InputError at "file".
MtmPositionTable ReadMtmPosition(const std::string& path);
BdInsertionTable ReadBdInsertion(const std::string& path);

}  // namespace vahf::data
