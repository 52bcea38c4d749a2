// The table1 kind (docs/experiments.md, "table1"): the paper's Table 1 at its
// instants, beside the paper's values.
#include "vahf/experiment/design.h"
#include "vahf/experiment/table1_input.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/run_support.h"
#include "vahf/report/section.h"

namespace vahf::kinds {

Kind Table1Kind() {
  Kind k;
  k.name = "table1";
  k.summary = "Table 1: V, f, r, g, eta, lambda_c and Psi_c at the paper's instants";
  k.doc = "experiments.md#table1-paper-sec-4-table-1";
  k.keys = {"paper_table"};
  k.parse = experiment::ReadTable1;
  k.check = CheckOneScene;
  k.design = experiment::Table1Run;
  k.conditions = experiment::Table1Conditions;
  k.analyse = report::Table1Section;
  return k;
}

}  // namespace vahf::kinds
