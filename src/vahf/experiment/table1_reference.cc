#include "vahf/experiment/table1_reference.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "vahf/human/factors.h"
#include "vahf/human/fatigue.h"
#include "vahf/scene/json_reader.h"

namespace vahf::experiment {
namespace {

double HalfUnit(int decimals) { return 0.5 * std::pow(10.0, -decimals); }

// A printed input in [0, 1] stands for a true value within h of it.
Interval InputBox(double printed, double h) {
  return {std::max(0.0, printed - h), std::min(1.0, printed + h)};
}

// Range of a multilinear function over a box: min and max over its corners.
template <std::size_t N, typename F>
Interval CornerRange(const std::array<Interval, N>& box, F f) {
  Interval out{std::numeric_limits<double>::infinity(),
               -std::numeric_limits<double>::infinity()};
  for (unsigned mask = 0; mask < (1u << N); ++mask) {
    std::array<double, N> x;
    for (std::size_t k = 0; k < N; ++k) x[k] = (mask >> k) & 1u ? box[k].hi : box[k].lo;
    const double y = f(x);
    out.lo = std::min(out.lo, y);
    out.hi = std::max(out.hi, y);
  }
  return out;
}

}  // namespace

Table1 LoadTable1(const std::string& path) {
  const nlohmann::json doc = scene::ReadJsonFile(path);
  const scene::JsonNode root(doc, path);
  root.ExpectObject({"source", "units", "decimals", "rows"});
  Table1 t;
  t.file = path;
  t.source = root.Required("source").String();
  const scene::JsonNode dec = root.Required("decimals");
  dec.ExpectObject({"V", "f", "eta", "r", "g", "lambda_c", "t", "A", "psi_c"});
  t.decimals_inputs = static_cast<int>(dec.Required("V").Integer(0, 6));
  for (const char* k : {"f", "r", "g"})
    if (dec.Required(k).Integer(0, 6) != t.decimals_inputs)
      dec.Required(k).Fail("V, f, r and g must be printed to the same decimals");
  t.decimals_outputs = static_cast<int>(dec.Required("eta").Integer(0, 6));
  if (dec.Required("lambda_c").Integer(0, 6) != t.decimals_outputs)
    dec.Required("lambda_c")
        .Fail("eta and lambda_c must be printed to the same decimals");
  t.decimals_a = static_cast<int>(dec.Required("A").Integer(0, 6));
  t.decimals_psi = static_cast<int>(dec.Required("psi_c").Integer(0, 6));
  const scene::JsonNode rows = root.Required("rows");
  for (std::size_t k = 0, n = rows.ArraySize(1); k < n; ++k) {
    const scene::JsonNode row = rows.At(k);
    row.ExpectObject({"subassembly", "part", "instant", "V", "f", "eta", "r", "g",
                      "lambda_c", "t", "A", "psi_c"});
    Table1Row r;
    r.subassembly = row.Required("subassembly").String();
    r.part = row.Required("part").String();
    r.instant = row.Required("instant").String();
    r.V = row.Required("V").InRange(0, 1);
    r.f = row.Required("f").InRange(0, 1);
    r.eta = row.Required("eta").InRange(0, 1);
    r.r = row.Required("r").InRange(0, 1);
    r.g = row.Required("g").InRange(0, 1);
    r.lambda_c = row.Required("lambda_c").InRange(0, 1);
    r.t = row.Required("t").NonNegative();
    r.A = row.Required("A").NonNegative();
    r.psi_c = row.Required("psi_c").InRange(0, 1);
    t.rows.push_back(r);
  }
  return t;
}

std::vector<Table1Check> CheckTable1(const Table1& table) {
  const double hi = HalfUnit(table.decimals_inputs);
  const double ho = HalfUnit(table.decimals_outputs);
  std::vector<Table1Check> out;
  for (const Table1Row& row : table.rows) {
    Table1Check c;
    c.row = row;
    c.eta.computed = human::VisionCoefficient(row.V, row.f);
    c.eta.allowed = CornerRange<2>({InputBox(row.V, hi), InputBox(row.f, hi)},
                                   [](const std::array<double, 2>& x) {
                                     return human::VisionCoefficient(x[0], x[1]);
                                   });
    c.eta.printed = {row.eta - ho, row.eta + ho};
    c.eta.consistent = c.eta.allowed.Meets(c.eta.printed);
    c.lambda_c.computed = human::ComfortCoefficient(row.r, row.g, row.V);
    c.lambda_c.allowed =
        CornerRange<3>({InputBox(row.r, hi), InputBox(row.g, hi), InputBox(row.V, hi)},
                       [](const std::array<double, 3>& x) {
                         return human::ComfortCoefficient(x[0], x[1], x[2]);
                       });
    c.lambda_c.printed = {row.lambda_c - ho, row.lambda_c + ho};
    c.lambda_c.consistent = c.lambda_c.allowed.Meets(c.lambda_c.printed);
    c.psi_eq6 = human::FatigueCoefficient(row.A * human::kJoulePerKcal,
                                          human::FatigueParams{}.a_max);
    out.push_back(c);
  }
  return out;
}

PsiFeasibility PsiColumnFeasibility(const Table1& table) {
  // Psi = 1 - A / A_max in [p - h, p + h] with A in [a - ha, a + ha] needs
  // A_max in [A / (1 - p + h), A / (1 - p - h)] for some such A.
  const double hp = HalfUnit(table.decimals_psi), ha = HalfUnit(table.decimals_a);
  Interval a_max{0.0, std::numeric_limits<double>::infinity()};
  for (const Table1Row& row : table.rows) {
    const double lo = (row.A - ha) / (1.0 - row.psi_c + hp);
    const double denominator = 1.0 - row.psi_c - hp;
    const double hi = denominator > 0 ? (row.A + ha) / denominator
                                      : std::numeric_limits<double>::infinity();
    a_max.lo = std::max(a_max.lo, lo);
    a_max.hi = std::min(a_max.hi, hi);
  }
  return {a_max, a_max.lo <= a_max.hi};
}

std::string FormatTable1Check(const Table1& table,
                              const std::vector<Table1Check>& checks) {
  std::string out =
      fmt::format("Table 1 of the paper against Eqs. 2, 3 and 6 ({})\n", table.file);
  out += fmt::format(
      "{:<14} {:>2} | {:>5} {:>5} {:>5} {:>5} | {:>5} {:>6} {:>15} {:<4} | {:>5} {:>6} "
      "{:>15} {:<4} | {:>5} {:>6}\n",
      "part", "", "V", "f", "r", "g", "eta", "Eq. 2", "allowed", "ok", "lam_c", "Eq. 3",
      "allowed", "ok", "Psi_c", "Eq. 6");
  int inconsistent = 0;
  for (const Table1Check& c : checks) {
    const Table1Row& r = c.row;
    inconsistent += !c.eta.consistent + !c.lambda_c.consistent;
    out += fmt::format(
        "{:<14} {:>2} | {:5.2f} {:5.2f} {:5.2f} {:5.2f} | {:5.2f} {:6.4f} "
        "[{:.4f},{:.4f}] "
        "{:<4} | {:5.2f} {:6.4f} [{:.4f},{:.4f}] {:<4} | {:5.1f} {:6.4f}\n",
        r.part, r.instant, r.V, r.f, r.r, r.g, r.eta, c.eta.computed, c.eta.allowed.lo,
        c.eta.allowed.hi, c.eta.consistent ? "yes" : "NO", r.lambda_c,
        c.lambda_c.computed, c.lambda_c.allowed.lo, c.lambda_c.allowed.hi,
        c.lambda_c.consistent ? "yes" : "NO", r.psi_c, c.psi_eq6);
  }
  const PsiFeasibility psi = PsiColumnFeasibility(table);
  const auto [psi_min, psi_max] = std::minmax_element(
      checks.begin(), checks.end(),
      [](const Table1Check& a, const Table1Check& b) { return a.psi_eq6 < b.psi_eq6; });
  out += fmt::format(
      "\n{} of {} eta/lambda_c entries lie outside what the rounding of the table allows "
      "(the interval of values its printed inputs admit, against the printed value +- "
      "{}).\n",
      inconsistent, 2 * checks.size(), HalfUnit(table.decimals_outputs));
  out += fmt::format(
      "Psi_c: Eq. 6 with A in kcal and the 1600 kcal limit gives {:.4f}-{:.4f}, not the "
      "printed {:.1f}; a single A_max fitting every row would need {:.1f} <= A_max <= "
      "{:.1f} kcal: {}.\n",
      psi_min->psi_eq6, psi_max->psi_eq6, checks.front().row.psi_c, psi.a_max.lo,
      psi.a_max.hi, psi.feasible ? "possible" : "impossible");
  out += "See reference/paper/NOTES.md.\n";
  return out;
}

}  // namespace vahf::experiment
