#include "vahf/data/lab_dataset.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "vahf/core/atomic_file.h"
#include "vahf/core/error.h"
#include "vahf/core/whole_file.h"
#include "vahf/data/csv.h"
#include "vahf/scene/experiment_file.h"
#include "vahf/scene/json_reader.h"

namespace vahf::data {
namespace {

namespace fs = std::filesystem;
using scene::JsonNode;

constexpr int kMaxInt = std::numeric_limits<int>::max();
// A lab trial or a segment's mean lasts seconds to minutes; more than a day
// (1e5 s) is a unit mistake.
constexpr double kMaxTime = 1e5;

// Each file's required columns; the writer writes them in this order.
const std::vector<std::string> kTrialColumns = {"operator",   "sex",       "height",
                                                "arm_length", "condition", "part",
                                                "repetition", "time",      "success"};
const std::vector<std::string> kSegmentColumns = {"segment",  "start",     "end",
                                                  "attempts", "successes", "mean_time"};
const std::vector<std::string> kSummaryColumns = {
    "quantity", "part", "condition", "segment",     "instant",
    "value",    "sd",   "n",         "uncertainty", "source"};

// A unit as the manifest names it: SI value = x * mul / div with mul or div
// 1, so one rounding (multiplying by 1e-3, which no double holds exactly,
// would round twice: 1750 mm reads as exactly 1.75 m).
struct Unit {
  std::string name;
  double mul = 1, div = 1;
  double Si(double x) const { return x * mul / div; }
  bool identity() const { return mul == 1 && div == 1; }
};

const std::vector<Unit> kTimeUnits = {{"s", 1, 1}, {"ms", 1, 1000}, {"min", 60, 1}};
const std::vector<Unit> kLengthUnits = {{"m", 1, 1}, {"cm", 1, 100}, {"mm", 1, 1000}};
// Segment bounds are a schedule kept in minutes.
const std::vector<Unit> kScheduleUnits = {{"min", 1, 1}, {"s", 1, 60}};

Unit ReadUnit(const JsonNode& node, const std::vector<Unit>& units) {
  std::vector<std::string> names;
  for (const Unit& u : units) names.push_back(u.name);
  const std::string name = node.Choice(names);
  return *std::find_if(units.begin(), units.end(),
                       [&](const Unit& u) { return u.name == name; });
}

// " (here 25 m, units mm)": the value in the unit a rule is stated in, when
// the file's unit differs, so that a wrong unit shows.
std::string InRuleUnit(double x, const Unit& u, const char* rule_unit) {
  return u.identity() ? "" : fmt::format(" (here {} {}, units {})", x, rule_unit, u.name);
}

// What the manifest says about one CSV file.
struct TableSpec {
  std::string name;      // as the manifest gives it
  std::string resolved;  // joined to the manifest's folder
  std::string pointer;   // of its "file", for a missing file
  std::map<std::string, Unit> units;
};

using TextSource =
    std::function<std::string(const TableSpec&, const JsonNode& file_node)>;

// ---------------------------------------------------------------- manifest

std::string ReadFileName(const JsonNode& node) {
  const std::string name = node.String();
  const fs::path p(name);
  const bool inside =
      !name.empty() && p.is_relative() &&
      std::none_of(p.begin(), p.end(), [](const fs::path& part) { return part == ".."; });
  if (!inside)
    node.Fail(
        "a dataset's file is named relative to the manifest's folder and lies inside "
        "it (not empty, no absolute path, no '..')");
  return name;
}

std::string Resolve(const std::string& folder, const std::string& name) {
  return folder.empty() ? name : (fs::path(folder) / name).string();
}

// `node` is {"file": ..., "units": {...}, extra_keys...} with `unit_keys` in
// units (each a column or column family with a physical unit), all required
// unless `units_optional`, when each defaults to the first of its units (s).
TableSpec ReadTableSpec(
    const JsonNode& node, const std::string& folder,
    const std::vector<std::pair<std::string, const std::vector<Unit>*>>& unit_keys,
    bool units_optional, std::vector<std::string> extra_keys = {}) {
  std::vector<std::string> keys = {"file", "units"};
  keys.insert(keys.end(), extra_keys.begin(), extra_keys.end());
  node.ExpectObject(keys);
  TableSpec spec;
  const JsonNode file = node.Required("file");
  spec.name = ReadFileName(file);
  spec.resolved = Resolve(folder, spec.name);
  spec.pointer = file.path();
  std::optional<JsonNode> units =
      units_optional ? node.Optional("units") : std::optional(node.Required("units"));
  std::vector<std::string> unit_names;
  for (const auto& [key, table] : unit_keys) unit_names.push_back(key);
  if (units) units->ExpectObject(unit_names);
  for (const auto& [key, table] : unit_keys) {
    if (units_optional) {
      const auto u = units ? units->Optional(key) : std::nullopt;
      spec.units[key] = u ? ReadUnit(*u, *table) : table->front();
    } else {
      spec.units[key] = ReadUnit(units->Required(key), *table);
    }
  }
  return spec;
}

std::string ReadDiskFile(const TableSpec& spec, const JsonNode& file_node) {
  std::error_code ec;
  if (!fs::exists(spec.resolved, ec)) file_node.Fail("no such file: " + spec.resolved);
  if (fs::is_directory(spec.resolved, ec))
    file_node.Fail("names a folder, not a file: " + spec.resolved);
  std::optional<std::string> text = ReadWholeFile(spec.resolved);
  if (!text) file_node.Fail("cannot open " + spec.resolved + " for reading");
  return *std::move(text);
}

// Reads and binds one file; a file without data rows declares nothing and
// is refused.
CsvTable ReadTable(const TableSpec& spec, const JsonNode& file_node,
                   const TextSource& source, const std::vector<std::string>& required,
                   const std::vector<std::string>& optional, std::size_t min_rows) {
  CsvTable table(ParseCsv(source(spec, file_node), spec.resolved), required, optional);
  if (table.rows().size() < min_rows)
    throw InputError(spec.resolved, fmt::format("line {}", table.csv().header_line),
                     fmt::format("{} data row{}", table.rows().size(),
                                 table.rows().size() == 1 ? "" : "s"),
                     fmt::format("the file needs at least {} data row{}", min_rows,
                                 min_rows == 1 ? "" : "s"));
  return table;
}

std::string OptionalText(const CsvTable& t, const CsvRow& row,
                         const std::string& column) {
  const auto cell = t.Optional(row, column);
  return cell ? cell->text() : std::string();
}

// ---------------------------------------------------------------- trials.csv

std::vector<LabTrial> ReadTrials(const CsvTable& t, const TableSpec& spec) {
  const Unit& height_unit = spec.units.at("height");
  const Unit& arm_unit = spec.units.at("arm_length");
  const Unit& time_unit = spec.units.at("time");
  std::vector<LabTrial> out;
  // An operator is one person: one sex, stature and arm length.
  std::map<std::string, std::size_t> first_row_of;
  std::map<std::tuple<std::string, std::string, std::string, int>, int> line_of;
  for (const CsvRow& row : t.rows()) {
    LabTrial x;
    x.line = row.line;
    x.operator_id = t.Cell(row, "operator").Text();
    x.sex = t.Cell(row, "sex").Choice({"male", "female"});
    const CsvCell height = t.Cell(row, "height");
    x.height = height_unit.Si(height.Number());
    // GB/T 10000-1988's 1st-99th percentiles are 1.45-1.81 m: outside 1-2.5 m
    // is a unit mistake.
    if (!(x.height >= 1.0 && x.height <= 2.5))
      height.Fail("a stature lies in [1, 2.5] m" +
                  InRuleUnit(x.height, height_unit, "m"));
    const CsvCell arm = t.Cell(row, "arm_length");
    x.arm_length = arm_unit.Si(arm.Number());
    if (!(x.arm_length >= 0.4 && x.arm_length <= 1.2))
      arm.Fail("an arm length lies in [0.4, 1.2] m" +
               InRuleUnit(x.arm_length, arm_unit, "m"));
    x.condition = t.Cell(row, "condition").Text();
    x.part = t.Cell(row, "part").Text();
    const CsvCell repetition = t.Cell(row, "repetition");
    x.repetition = static_cast<int>(repetition.Integer(1, kMaxInt));
    x.success = static_cast<int>(t.Cell(row, "success").Integer(0, 1));
    const CsvCell time = t.Cell(row, "time");
    if (time.empty()) {
      if (x.success == 1)
        time.Fail("may be empty only when success = 0: a successful trial has its time");
    } else {
      x.time = time_unit.Si(time.Number());
      if (!(x.time > 0 && x.time <= kMaxTime))
        time.Fail(fmt::format("an assembly time is > 0 and at most {} s", kMaxTime) +
                  InRuleUnit(x.time, time_unit, "s"));
    }
    x.source = OptionalText(t, row, "source");
    x.note = OptionalText(t, row, "note");

    const auto [it, fresh] = first_row_of.emplace(x.operator_id, out.size());
    if (!fresh) {
      const LabTrial& first = out[it->second];
      const auto differs = [&](const char* column, const std::string& a) {
        t.Cell(row, column)
            .Fail(fmt::format("operator '{}' has {} {} on line {}: an operator's sex, "
                              "height and arm_length "
                              "are the same on each of their rows",
                              x.operator_id, column, a, first.line));
      };
      if (x.sex != first.sex) differs("sex", first.sex);
      if (x.height != first.height) differs("height", fmt::format("{} m", first.height));
      if (x.arm_length != first.arm_length)
        differs("arm_length", fmt::format("{} m", first.arm_length));
    }
    const auto key = std::make_tuple(x.operator_id, x.condition, x.part, x.repetition);
    const auto [seen, unique] = line_of.emplace(key, x.line);
    if (!unique)
      repetition.Fail(fmt::format(
          "line {} has the same operator, condition, part and repetition: each trial "
          "appears once",
          seen->second));
    out.push_back(std::move(x));
  }
  return out;
}

// ---------------------------------------------------------------- segments.csv

std::vector<LabSegment> ReadSegments(const CsvTable& t, const TableSpec& spec) {
  const Unit& start_unit = spec.units.at("start");
  const Unit& end_unit = spec.units.at("end");
  const Unit& time_unit = spec.units.at("mean_time");
  std::vector<LabSegment> out;
  std::map<std::string, std::size_t> last_of;  // per condition (series), in `out`
  for (const CsvRow& row : t.rows()) {
    LabSegment x;
    x.line = row.line;
    if (const auto c = t.Optional(row, "condition")) x.condition = c->Text();
    const auto last = last_of.find(x.condition);
    const LabSegment* previous = last == last_of.end() ? nullptr : &out[last->second];
    const CsvCell segment = t.Cell(row, "segment");
    x.segment = static_cast<int>(segment.Integer(1, kMaxInt));
    const int expected = previous ? previous->segment + 1 : 1;
    if (x.segment != expected)
      segment.Fail(fmt::format(
          "segments{} are numbered 1, 2, ... in file order: {} expected here",
          x.condition.empty() ? "" : " of condition '" + x.condition + "'", expected));
    const CsvCell start = t.Cell(row, "start");
    x.start_min = start_unit.Si(start.Number());
    if (!(x.start_min >= 0)) start.Fail("a segment starts at >= 0 min");
    if (previous && !(x.start_min >= previous->end_min))
      start.Fail(
          fmt::format("segments do not overlap: segment {} ends at {} min (line {})",
                      previous->segment, previous->end_min, previous->line) +
          InRuleUnit(x.start_min, start_unit, "min"));
    const CsvCell end = t.Cell(row, "end");
    x.end_min = end_unit.Si(end.Number());
    if (!(x.end_min > x.start_min))
      end.Fail(fmt::format("a segment ends after it starts, at {} min", x.start_min) +
               InRuleUnit(x.end_min, end_unit, "min"));
    const CsvCell attempts = t.Cell(row, "attempts");
    x.attempts = static_cast<int>(attempts.Integer(1, kMaxInt));
    const CsvCell successes = t.Cell(row, "successes");
    x.successes = static_cast<int>(successes.Integer(0, kMaxInt));
    if (x.successes > x.attempts)
      successes.Fail(fmt::format("successes are at most the attempts, {}", x.attempts));
    const CsvCell mean = t.Cell(row, "mean_time");
    if (!mean.empty()) {
      if (x.successes == 0)
        mean.Fail(
            "a mean time of the successful attempts needs a success: leave it empty "
            "when successes = 0");
      x.mean_time = time_unit.Si(mean.Number());
      if (!(x.mean_time > 0 && x.mean_time <= kMaxTime))
        mean.Fail(fmt::format("a mean assembly time is > 0 and at most {} s", kMaxTime) +
                  InRuleUnit(x.mean_time, time_unit, "s"));
    }
    x.source = OptionalText(t, row, "source");
    x.note = OptionalText(t, row, "note");
    last_of[x.condition] = out.size();
    out.push_back(std::move(x));
  }
  return out;
}

// ---------------------------------------------------------------- summaries.csv

std::vector<LabSummary> ReadSummaries(const CsvTable& t, const TableSpec& spec) {
  const Unit& instant_unit = spec.units.at("instant");
  const Unit& time_unit = spec.units.at("time");
  std::vector<LabSummary> out;
  for (const CsvRow& row : t.rows()) {
    LabSummary x;
    x.line = row.line;
    x.quantity = t.Cell(row, "quantity").Choice(LabQuantities());
    const bool is_time = x.quantity == "assembly_time";
    const Unit& value_unit = is_time ? time_unit : kTimeUnits.front();  // 1: no unit
    x.part = t.Cell(row, "part").text();
    x.condition = t.Cell(row, "condition").text();
    if (const CsvCell s = t.Cell(row, "segment"); !s.empty())
      x.segment = static_cast<int>(s.Integer(1, kMaxInt));
    if (const CsvCell s = t.Cell(row, "instant"); !s.empty()) {
      x.instant = instant_unit.Si(s.Number());
      if (!(x.instant >= 0)) s.Fail("an instant is a time >= 0 s");
    }
    const CsvCell value = t.Cell(row, "value");
    x.value = value_unit.Si(value.Number());
    if (is_time && !(x.value > 0 && x.value <= kMaxTime))
      value.Fail(fmt::format("an assembly time is > 0 and at most {} s", kMaxTime) +
                 InRuleUnit(x.value, value_unit, "s"));
    if (!is_time && !(x.value >= 0 && x.value <= 1))
      value.Fail(fmt::format("{} is a proportion or factor in [0, 1]", x.quantity));
    if (const CsvCell s = t.Cell(row, "sd"); !s.empty()) {
      x.sd = value_unit.Si(s.Number());
      if (!(x.sd >= 0)) s.Fail("a standard deviation is >= 0");
    }
    if (const CsvCell s = t.Cell(row, "n"); !s.empty())
      x.n = static_cast<int>(s.Integer(1, kMaxInt));
    if (const CsvCell s = t.Cell(row, "uncertainty"); !s.empty()) {
      x.uncertainty = value_unit.Si(s.Number());
      if (!(x.uncertainty >= 0)) s.Fail("a reading uncertainty is a half-width, >= 0");
    }
    x.source = t.Cell(row, "source").Text();
    x.note = OptionalText(t, row, "note");
    out.push_back(std::move(x));
  }
  return out;
}

// ---------------------------------------------------------------- tracks/*.csv

const std::vector<std::string>& TrackSensors() {
  static const std::vector<std::string> sensors = {"part", "brow", "lshoulder",
                                                   "rshoulder", "body"};
  return sensors;
}

std::vector<std::string> TrackColumns() {
  std::vector<std::string> columns = {"time"};
  for (const std::string& s : TrackSensors())
    for (const char* axis : {"_x", "_y", "_z"}) columns.push_back(s + axis);
  return columns;
}

std::vector<TrackSample> ReadSamples(const CsvTable& t, const TableSpec& spec) {
  const Unit& time_unit = spec.units.at("time");
  const Unit& length_unit = spec.units.at("position");
  std::vector<TrackSample> out;
  for (const CsvRow& row : t.rows()) {
    TrackSample x;
    x.line = row.line;
    const CsvCell time = t.Cell(row, "time");
    x.time = time_unit.Si(time.Number());
    if (!out.empty() && !(x.time > out.back().time))
      time.Fail(fmt::format("a track's time increases strictly: line {} has {} s",
                            out.back().line, out.back().time) +
                InRuleUnit(x.time, time_unit, "s"));
    Eigen::Vector3d* targets[] = {&x.part, &x.brow, &x.left_shoulder, &x.right_shoulder,
                                  &x.body};
    for (std::size_t s = 0; s < TrackSensors().size(); ++s)
      for (int k = 0; k < 3; ++k) {
        const std::string column = TrackSensors()[s] + "_" + "xyz"[k];
        (*targets[s])[k] = length_unit.Si(t.Cell(row, column).Number());
      }
    if (const auto v = t.Optional(row, "visibility"); v && !v->empty()) {
      x.visibility = v->Number();
      if (!(x.visibility >= 0 && x.visibility <= 1))
        v->Fail("V (Eq. 1) is a fraction of pixels in [0, 1]");
    }
    out.push_back(x);
  }
  return out;
}

// ---------------------------------------------------------------- the dataset

// The manifest's format, name, description and provenance.
void ReadHeader(const JsonNode& root, LabDataset* d) {
  const JsonNode format = root.Required("format");
  if (format.String() != scene::kLabFormat)
    format.Fail(std::string("a lab dataset declares \"format\": \"") + scene::kLabFormat +
                "\"");
  const JsonNode name = root.Required("name");
  d->name = name.String();
  if (d->name.empty() ||
      !std::all_of(d->name.begin(), d->name.end(), [](unsigned char c) {
        return std::isalnum(c) || c == '_' || c == '.' || c == '-';
      }))
    name.Fail("a dataset's name is letters, digits, '_', '.' and '-' (at least one)");
  const JsonNode description = root.Required("description");
  d->description = description.String();
  if (d->description.empty())
    description.Fail("say in a sentence what the dataset holds");
  const JsonNode provenance = root.Required("provenance");
  if (!provenance.json().is_object()) provenance.Fail("must be an object");
  const JsonNode source_node = provenance.Required("source");
  if (source_node.String().empty())
    source_node.Fail(
        "say who recorded the data, where and when (or how it was generated)");
  for (const auto& item : provenance.json().items())
    provenance.Required(item.key()).String();  // every entry is text
  d->provenance = provenance.json();
}

// The files the manifest names, each named once.
class FileClaims {
 public:
  void Claim(const TableSpec& spec, const JsonNode& node) {
    const auto [it, fresh] = pointer_of_.emplace(
        fs::path(spec.name).lexically_normal().string(), spec.pointer);
    if (!fresh)
      node.Required("file").Fail("names the same file as " + it->second +
                                 ": each file of a dataset is named once");
  }

 private:
  std::map<std::string, std::string> pointer_of_;
};

// The manifest's tables: where each is and in which units, before any is read.
struct ManifestTables {
  std::optional<JsonNode> trials_node, segments_node, summaries_node, tracks_node;
  std::optional<TableSpec> trials, segments, summaries;
  std::vector<TableSpec> tracks;
};

// Each track's file and units, and whose it is (d->tracks, samples still empty).
void ReadTrackSpecs(const JsonNode& tracks_node, FileClaims* claims, ManifestTables* m,
                    LabDataset* d) {
  const std::size_t n = tracks_node.ArraySize(1);
  for (std::size_t k = 0; k < n; ++k) {
    const JsonNode node = tracks_node.At(k);
    m->tracks.push_back(ReadTableSpec(
        node, d->folder, {{"time", &kTimeUnits}, {"position", &kLengthUnits}}, false,
        {"operator", "condition", "repetition"}));
    claims->Claim(m->tracks.back(), node);
    SensorTrack track;
    track.file = m->tracks.back().resolved;
    const JsonNode op = node.Required("operator");
    track.operator_id = op.String();
    if (track.operator_id.empty())
      op.Fail("a track names its operator (as in trials.csv)");
    const JsonNode condition = node.Required("condition");
    track.condition = condition.String();
    if (track.condition.empty()) condition.Fail("a track names its condition");
    track.repetition = static_cast<int>(node.Required("repetition").Integer(1, kMaxInt));
    d->tracks.push_back(std::move(track));
  }
}

// The whole manifest, checked before any file is read.
ManifestTables ReadManifest(const JsonNode& root, LabDataset* d) {
  ManifestTables m;
  m.trials_node = root.Optional("trials");
  m.segments_node = root.Optional("segments");
  m.summaries_node = root.Optional("summaries");
  m.tracks_node = root.Optional("tracks");
  if (!m.trials_node && !m.segments_node && !m.summaries_node && !m.tracks_node)
    root.Fail("a dataset holds at least one of trials, segments, summaries and tracks");
  if (m.trials_node)
    m.trials = ReadTableSpec(
        *m.trials_node, d->folder,
        {{"height", &kLengthUnits}, {"arm_length", &kLengthUnits}, {"time", &kTimeUnits}},
        false);
  if (m.segments_node)
    m.segments = ReadTableSpec(*m.segments_node, d->folder,
                               {{"start", &kScheduleUnits},
                                {"end", &kScheduleUnits},
                                {"mean_time", &kTimeUnits}},
                               false);
  if (m.summaries_node)
    m.summaries = ReadTableSpec(*m.summaries_node, d->folder,
                                {{"instant", &kTimeUnits}, {"time", &kTimeUnits}}, true);
  FileClaims claims;
  if (m.trials) claims.Claim(*m.trials, *m.trials_node);
  if (m.segments) claims.Claim(*m.segments, *m.segments_node);
  if (m.summaries) claims.Claim(*m.summaries, *m.summaries_node);
  if (m.tracks_node) ReadTrackSpecs(*m.tracks_node, &claims, &m, d);
  return m;
}

// The files the manifest names, read into d.
void ReadFiles(const ManifestTables& m, const TextSource& source, LabDataset* d) {
  if (m.trials) {
    d->trials_file = m.trials->name;
    const CsvTable t = ReadTable(*m.trials, m.trials_node->Required("file"), source,
                                 kTrialColumns, {"source", "note"}, 1);
    d->trials = ReadTrials(t, *m.trials);
  }
  if (m.segments) {
    d->segments_file = m.segments->name;
    const CsvTable t = ReadTable(*m.segments, m.segments_node->Required("file"), source,
                                 kSegmentColumns, {"condition", "source", "note"}, 1);
    d->segments = ReadSegments(t, *m.segments);
  }
  if (m.summaries) {
    d->summaries_file = m.summaries->name;
    const CsvTable t = ReadTable(*m.summaries, m.summaries_node->Required("file"), source,
                                 kSummaryColumns, {"note"}, 1);
    d->summaries = ReadSummaries(t, *m.summaries);
  }
  // A track holds sensor samples only: notes go in its comment lines.
  for (std::size_t k = 0; k < m.tracks.size(); ++k) {
    const CsvTable t = ReadTable(m.tracks[k], m.tracks_node->At(k).Required("file"),
                                 source, TrackColumns(), {"visibility"}, 2);
    d->tracks[k].samples = ReadSamples(t, m.tracks[k]);
  }
}

LabDataset Parse(const nlohmann::json& document, const std::string& path,
                 const TextSource& source) {
  const JsonNode root(document, path);
  if (!document.is_object()) root.Fail("a lab dataset's manifest is a JSON object");
  root.ExpectObject({"format", "name", "description", "provenance", "trials", "segments",
                     "summaries", "tracks"});
  LabDataset d;
  d.file = path;
  d.folder = fs::path(path).parent_path().string();
  ReadHeader(root, &d);
  const ManifestTables m = ReadManifest(root, &d);
  ReadFiles(m, source, &d);
  return d;
}

// ---------------------------------------------------------------- writing

std::string Num(double x) { return std::isnan(x) ? std::string() : fmt::format("{}", x); }
std::string Int(int x) { return fmt::format("{}", x); }

std::string TrialsCsv(const std::vector<LabTrial>& trials) {
  std::vector<std::string> header = kTrialColumns;
  header.insert(header.end(), {"source", "note"});
  std::string out = CsvLine(header);
  for (const LabTrial& x : trials)
    out += CsvLine({x.operator_id, x.sex, Num(x.height), Num(x.arm_length), x.condition,
                    x.part, Int(x.repetition), Num(x.time), Int(x.success), x.source,
                    x.note});
  return out;
}

std::string SegmentsCsv(const std::vector<LabSegment>& segments) {
  // The condition column, which makes every row name its series, only when
  // there are series.
  const bool series =
      std::any_of(segments.begin(), segments.end(),
                  [](const LabSegment& x) { return !x.condition.empty(); });
  std::vector<std::string> header = kSegmentColumns;
  if (series) header.push_back("condition");
  header.insert(header.end(), {"source", "note"});
  std::string out = CsvLine(header);
  for (const LabSegment& x : segments) {
    std::vector<std::string> row = {Int(x.segment),  Num(x.start_min), Num(x.end_min),
                                    Int(x.attempts), Int(x.successes), Num(x.mean_time)};
    if (series) row.push_back(x.condition);
    row.insert(row.end(), {x.source, x.note});
    out += CsvLine(row);
  }
  return out;
}

std::string SummariesCsv(const std::vector<LabSummary>& summaries) {
  std::vector<std::string> header = kSummaryColumns;
  header.push_back("note");
  std::string out = CsvLine(header);
  for (const LabSummary& x : summaries)
    out += CsvLine({x.quantity, x.part, x.condition, x.segment ? Int(x.segment) : "",
                    Num(x.instant), Num(x.value), Num(x.sd), x.n ? Int(x.n) : "",
                    Num(x.uncertainty), x.source, x.note});
  return out;
}

std::string TrackCsv(const SensorTrack& track) {
  const bool camera =
      std::any_of(track.samples.begin(), track.samples.end(),
                  [](const TrackSample& x) { return !std::isnan(x.visibility); });
  std::vector<std::string> header = TrackColumns();
  if (camera) header.push_back("visibility");
  std::string out = CsvLine(header);
  for (const TrackSample& x : track.samples) {
    std::vector<std::string> row = {Num(x.time)};
    for (const Eigen::Vector3d* p :
         {&x.part, &x.brow, &x.left_shoulder, &x.right_shoulder, &x.body})
      for (int k = 0; k < 3; ++k) row.push_back(Num((*p)[k]));
    if (camera) row.push_back(Num(x.visibility));
    out += CsvLine(row);
  }
  return out;
}

bool Inside(const fs::path& p) {
  return !p.empty() && p.is_relative() && p != "." &&
         std::none_of(p.begin(), p.end(),
                      [](const fs::path& part) { return part == ".."; });
}

// A track's file relative to the dataset's folder, or relative as it is, or
// a fresh name.
std::string TrackName(const SensorTrack& track, const std::string& folder,
                      std::size_t k) {
  const fs::path file(track.file);
  if (!folder.empty() && !track.file.empty()) {
    const fs::path relative = file.lexically_relative(folder);
    if (Inside(relative)) return relative.generic_string();
  }
  if (Inside(file)) return file.lexically_normal().generic_string();
  return fmt::format("tracks/{}.csv", k + 1);
}

}  // namespace

const std::vector<std::string>& LabQuantities() {
  static const std::vector<std::string> quantities = {
      "assembly_time", "success_rate", "eta", "lambda_c", "V", "f", "r", "g"};
  return quantities;
}

LabDataset ParseLabDataset(const nlohmann::json& manifest,
                           const std::string& manifest_path) {
  return Parse(manifest, manifest_path, ReadDiskFile);
}

std::vector<std::string> LabDatasetFiles(const LabDataset& dataset) {
  std::vector<std::string> out = {dataset.file};
  for (const std::string& f :
       {dataset.trials_file, dataset.segments_file, dataset.summaries_file})
    if (!f.empty()) out.push_back(dataset.folder + "/" + f);
  for (const SensorTrack& t : dataset.tracks) out.push_back(t.file);
  return out;
}

LabDataset LoadLabDataset(const std::string& manifest_path) {
  return ParseLabDataset(scene::ReadJsonFile(manifest_path), manifest_path);
}

void WriteLabDataset(const LabDataset& d, const std::string& folder) {
  using ordered = nlohmann::ordered_json;
  std::map<std::string, std::string> files;  // name relative to `folder` -> text
  ordered m;
  m["format"] = scene::kLabFormat;
  m["name"] = d.name;
  m["description"] = d.description;
  m["provenance"] = ordered::parse(d.provenance.dump());
  const auto table = [&](const char* key, const std::string& name, const char* fallback,
                         std::string text, ordered units) {
    const std::string file = name.empty() ? fallback : name;
    m[key] = {{"file", file}, {"units", std::move(units)}};
    files[file] = std::move(text);
  };
  if (!d.trials.empty())
    table("trials", d.trials_file, "trials.csv", TrialsCsv(d.trials),
          {{"height", "m"}, {"arm_length", "m"}, {"time", "s"}});
  if (!d.segments.empty())
    table("segments", d.segments_file, "segments.csv", SegmentsCsv(d.segments),
          {{"start", "min"}, {"end", "min"}, {"mean_time", "s"}});
  if (!d.summaries.empty())
    table("summaries", d.summaries_file, "summaries.csv", SummariesCsv(d.summaries),
          {{"instant", "s"}, {"time", "s"}});
  for (std::size_t k = 0; k < d.tracks.size(); ++k) {
    const SensorTrack& t = d.tracks[k];
    const std::string file = TrackName(t, d.folder, k);
    m["tracks"].push_back({{"file", file},
                           {"operator", t.operator_id},
                           {"condition", t.condition},
                           {"repetition", t.repetition},
                           {"units", {{"time", "s"}, {"position", "m"}}}});
    files[file] = TrackCsv(t);
  }
  const std::string manifest_text = m.dump(2) + "\n";

  // Checked as the loader will read it, before anything is written.
  const std::string manifest_path = (fs::path(folder) / "dataset.json").string();
  Parse(nlohmann::json::parse(manifest_text), manifest_path,
        [&](const TableSpec& spec, const JsonNode&) { return files.at(spec.name); });

  // The CSV files first: a manifest never names a file that is not there yet.
  for (const auto& [name, text] : files) {
    const fs::path path = fs::path(folder) / name;
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    if (ec)
      throw InputError(path.parent_path().string(), "", "",
                       "cannot create the folder: " + ec.message());
    WriteFileAtomically(path.string(), text);
  }
  WriteFileAtomically(manifest_path, manifest_text);
}

namespace {

std::string Count(std::size_t n, const std::string& noun,
                  const std::string& plural = "") {
  return fmt::format("{} {}", n, n == 1 ? noun : plural.empty() ? noun + "s" : plural);
}

template <typename T, typename F>
std::size_t Distinct(const std::vector<T>& rows, F key) {
  std::set<std::string> seen;
  for (const T& x : rows) seen.insert(key(x));
  return seen.size();
}

}  // namespace

std::string DescribeLabDataset(const LabDataset& d) {
  std::string out =
      fmt::format("lab dataset '{}' ({})\n  {}\n", d.name, d.file, d.description);
  if (d.provenance.is_object() && d.provenance.contains("source"))
    out += fmt::format("provenance: {}\n", d.provenance["source"].get<std::string>());
  if (!d.trials.empty()) {
    const auto successes =
        std::count_if(d.trials.begin(), d.trials.end(),
                      [](const LabTrial& x) { return x.success == 1; });
    out += fmt::format(
        "trials ({}): {}, {}, {}, {}; {} successful\n", d.trials_file,
        Count(d.trials.size(), "trial"),
        Count(Distinct(d.trials, [](const LabTrial& x) { return x.operator_id; }),
              "operator"),
        Count(Distinct(d.trials, [](const LabTrial& x) { return x.part; }), "part"),
        Count(Distinct(d.trials, [](const LabTrial& x) { return x.condition; }),
              "condition"),
        successes);
  }
  if (!d.segments.empty()) {
    int attempts = 0, successes = 0;
    for (const LabSegment& x : d.segments)
      attempts += x.attempts, successes += x.successes;
    out += fmt::format(
        "segments ({}): {} in {}; {} of {} attempts successful\n", d.segments_file,
        Count(d.segments.size(), "segment"),
        Count(Distinct(d.segments, [](const LabSegment& x) { return x.condition; }),
              "series", "series"),
        successes, attempts);
  }
  if (!d.summaries.empty()) {
    std::string by_quantity;
    for (const std::string& q : LabQuantities()) {
      const auto n = std::count_if(d.summaries.begin(), d.summaries.end(),
                                   [&](const LabSummary& x) { return x.quantity == q; });
      if (n > 0)
        by_quantity += fmt::format("{}{} {}", by_quantity.empty() ? "" : ", ", q, n);
    }
    out += fmt::format("summaries ({}): {}: {}\n", d.summaries_file,
                       Count(d.summaries.size(), "summary", "summaries"), by_quantity);
  }
  if (!d.tracks.empty()) {
    std::size_t samples = 0;
    for (const SensorTrack& t : d.tracks) samples += t.samples.size();
    out += fmt::format("tracks: {}, {}\n", Count(d.tracks.size(), "track"),
                       Count(samples, "sample"));
    for (const SensorTrack& t : d.tracks)
      if (!t.samples.empty())
        out += fmt::format(
            "  {}: operator '{}', condition '{}', repetition {}, {}, {} to {} s\n",
            t.file, t.operator_id, t.condition, t.repetition,
            Count(t.samples.size(), "sample"), t.samples.front().time,
            t.samples.back().time);
  }
  return out;
}

}  // namespace vahf::data
