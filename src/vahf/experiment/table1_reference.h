// The paper's Table 1 as a reference: loads reference/paper/table1.json and
// checks each row's eta (Eq. 2) and lambda_c (Eq. 3) against V, f, r, g within
// what the table's rounding allows, and its Psi_c column against Eq. 6.
//
// The bound. A value printed to d decimals stands for any true value within
// h = 0.5 * 10^-d of it. eta = 1 - V f and lambda_c = 1 - (r + g) V / 2 are
// multilinear in their inputs, so over the box of true inputs (each printed
// input +- h, clipped to [0, 1]) they take their extremes at the box's
// corners: that gives the interval of values the printed inputs allow. A row
// is consistent when this interval meets the printed output +- h.
#pragma once

#include <string>
#include <vector>

namespace vahf::experiment {

struct Table1Row {
  std::string subassembly, part, instant;
  double V, f, eta, r, g, lambda_c, t, A, psi_c;
};

struct Table1 {
  std::string file, source;
  int decimals_inputs = 2;   // of V, f, r, g (the inputs share one precision)
  int decimals_outputs = 2;  // of eta and lambda_c
  int decimals_a = 2, decimals_psi = 1;
  std::vector<Table1Row> rows;
};

// Errors in the file are vahf::InputError naming it.
Table1 LoadTable1(const std::string& path);

struct Interval {
  double lo, hi;
  bool Meets(const Interval& other) const { return lo <= other.hi && other.lo <= hi; }
};

struct CoefficientCheck {
  double computed;   // from the printed inputs
  Interval allowed;  // over the rounding box of the inputs
  Interval printed;  // the printed output +- its half unit
  bool consistent;
};

struct Table1Check {
  Table1Row row;
  CoefficientCheck eta, lambda_c;
  double psi_eq6;  // Eq. 6 with A read as kcal and the 1600 kcal limit
};

std::vector<Table1Check> CheckTable1(const Table1& table);

// Whether any single A_max makes Eq. 6, Psi = (A_max - A) / A_max, print as the
// table's Psi_c in every row: the interval of A_max each row allows, intersected.
struct PsiFeasibility {
  Interval a_max;  // empty (lo > hi) when no A_max fits every row
  bool feasible;
};
PsiFeasibility PsiColumnFeasibility(const Table1& table);

// The side-by-side table `tools/run` prints.
std::string FormatTable1Check(const Table1& table,
                              const std::vector<Table1Check>& checks);

}  // namespace vahf::experiment
