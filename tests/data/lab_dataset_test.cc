// Tests of the lab dataset loader and writer (data/lab_dataset.h,
// docs/lab-data.md): a good dataset loads with every value in SI units and
// round-trips through WriteLabDataset and LoadLabDataset; units in mm, cm,
// ms, min and s convert exactly; and each rule of the format, broken alone in
// an otherwise good dataset, throws one InputError naming the file, the line
// and column (or the manifest's JSON pointer), the value and the rule — so
// each test fails if its rule is removed.
#include "vahf/data/lab_dataset.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "support/test_files.h"
#include "vahf/core/error.h"

namespace vahf::data {
namespace {

namespace fs = std::filesystem;
using scene::testing::WriteFile;
using ::testing::HasSubstr;

// A dataset as file name -> text.
using Files = std::map<std::string, std::string>;

std::string TrackRow(const std::string& time, const std::string& part_z,
                     const std::string& visibility) {
  return time + ",0.1,0.2," + part_z +
         ",0,-0.4,1.6,-0.2,-0.45,1.4,0.2,-0.45,1.4,0,-0.45,1.1," + visibility + "\r\n";
}

// Line numbers are part of the tests: trials.csv has its header on line 2,
// rows on lines 3, 4, 6 (to 7) and 8; segments.csv rows on 2-5; summaries.csv
// rows on 3-5; the track (CRLF line ends) rows on 2-4.
Files GoodFiles() {
  Files f;
  f["dataset.json"] = R"({
  "format": "vahf-lab/1",
  "name": "test_lab",
  "description": "Two operators, two fatigue series, three statistics and one track.",
  "provenance": {"source": "synthetic: written by lab_dataset_test", "recorded": "2026-11-01"},
  "trials": {"file": "trials.csv", "units": {"height": "m", "arm_length": "m", "time": "s"}},
  "segments": {"file": "segments.csv",
               "units": {"start": "min", "end": "min", "mean_time": "s"}},
  "summaries": {"file": "summaries.csv"},
  "tracks": [{"file": "tracks/op1_rep1.csv", "operator": "male 1", "condition": "good",
              "repetition": 1, "units": {"time": "s", "position": "m"}}]
}
)";
  f["trials.csv"] =
      "# Recorded by the test; statures from the operators' records.\n"
      "operator,sex,height,arm_length,condition,part,repetition,time,success,note\n"
      "male 1,male,1.75,0.74,good,piston_rod,1,15.2,1,\n"
      "male 1,male,1.75,0.74,good,piston_rod,2,,0,\"dropped, \"\"twice\"\"\"\n"
      "\n"
      "female 1,female,1.62,0.68,good,all,1,16.75,1,\"a note\n"
      "on two lines\"\n"
      "female 1,female,1.62,0.68,good,all,2,1e1,1,\n";
  f["segments.csv"] =
      "segment,start,end,attempts,successes,mean_time,condition,source\n"
      "1,0,15,25,24,16.1,real,Sec. 5.4\n"
      "2,15,30,25,20,16.9,real,\n"
      "1,0,15,25,25,,virtual,\n"
      "2,15,30,25,19,17.5,virtual,\"Fig. 16, read off\"\n";
  f["summaries.csv"] =
      "# What the test's imaginary paper states.\n"
      "quantity,part,condition,segment,instant,value,sd,n,uncertainty,source\n"
      "assembly_time,all,,,,16,1.2,60,,Sec. 5.2: about 16 s\n"
      "success_rate,,real,1,,0.92,,25,0.01,\"Fig. 16, read off\"\n"
      "eta,piston_rod,,,3,0.05,,,,Table 1\n";
  f["tracks/op1_rep1.csv"] =
      "time,part_x,part_y,part_z,brow_x,brow_y,brow_z,lshoulder_x,lshoulder_y,lshoulder_"
      "z,"
      "rshoulder_x,rshoulder_y,rshoulder_z,body_x,body_y,body_z,visibility\r\n" +
      TrackRow("0", "0.9", "1") + TrackRow("0.1", "0.89", "") +
      TrackRow("0.2", "0.88", "0.5");
  return f;
}

// A fresh folder `sub` of the running test's own.
fs::path Folder(const std::string& sub) {
  const ::testing::TestInfo* info =
      ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(::testing::TempDir()) / "lab_dataset" /
                       (std::string(info->test_suite_name()) + "." + info->name()) / sub;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Writes `files` into a fresh folder `sub`; the manifest's path.
std::string WriteDataset(const Files& files, const std::string& sub = "in") {
  const fs::path dir = Folder(sub);
  for (const auto& [name, text] : files) {
    fs::create_directories((dir / name).parent_path());
    WriteFile(dir / name, text);
  }
  return (dir / "dataset.json").string();
}

// Replaces the one occurrence of `from` in `text`.
void Replace(std::string* text, const std::string& from, const std::string& to) {
  const std::size_t at = text->find(from);
  ASSERT_NE(at, std::string::npos) << "no '" << from << "' in\n" << *text;
  ASSERT_EQ(text->find(from, at + 1), std::string::npos) << "'" << from << "' twice";
  text->replace(at, from.size(), to);
}

// Loads `files` expecting an InputError in `file` (a name of `files`) at
// `where`, with `value`, whose rule contains `rule`; what() holds them all.
void ExpectError(const Files& files, const std::string& file, const std::string& where,
                 const std::string& value, const std::string& rule) {
  const std::string manifest = WriteDataset(files);
  const std::string path = (fs::path(manifest).parent_path() / file).string();
  try {
    LoadLabDataset(manifest);
    ADD_FAILURE() << "no error; expected " << path << ": " << where << " = " << value
                  << ": " << rule;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.where(), where);
    EXPECT_EQ(e.value(), value);
    EXPECT_THAT(e.rule(), HasSubstr(rule));
    EXPECT_THAT(std::string(e.what()),
                HasSubstr(path + ": " + where + " = " + value + ": "));
  }
}

bool Same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

// Every field but paths and, unless `lines`, line numbers.
void ExpectSameData(const LabDataset& a, const LabDataset& b, bool lines) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.provenance, b.provenance);
  EXPECT_EQ(a.trials_file, b.trials_file);
  EXPECT_EQ(a.segments_file, b.segments_file);
  EXPECT_EQ(a.summaries_file, b.summaries_file);
  ASSERT_EQ(a.trials.size(), b.trials.size());
  for (std::size_t k = 0; k < a.trials.size(); ++k) {
    const LabTrial &x = a.trials[k], &y = b.trials[k];
    EXPECT_TRUE(
        x.operator_id == y.operator_id && x.sex == y.sex && x.height == y.height &&
        x.arm_length == y.arm_length && x.condition == y.condition && x.part == y.part &&
        x.repetition == y.repetition && Same(x.time, y.time) && x.success == y.success &&
        x.source == y.source && x.note == y.note && (!lines || x.line == y.line))
        << "trial " << k;
  }
  ASSERT_EQ(a.segments.size(), b.segments.size());
  for (std::size_t k = 0; k < a.segments.size(); ++k) {
    const LabSegment &x = a.segments[k], &y = b.segments[k];
    EXPECT_TRUE(x.segment == y.segment && x.start_min == y.start_min &&
                x.end_min == y.end_min && x.attempts == y.attempts &&
                x.successes == y.successes && Same(x.mean_time, y.mean_time) &&
                x.condition == y.condition && x.source == y.source && x.note == y.note &&
                (!lines || x.line == y.line))
        << "segment " << k;
  }
  ASSERT_EQ(a.summaries.size(), b.summaries.size());
  for (std::size_t k = 0; k < a.summaries.size(); ++k) {
    const LabSummary &x = a.summaries[k], &y = b.summaries[k];
    EXPECT_TRUE(x.quantity == y.quantity && x.part == y.part &&
                x.condition == y.condition && x.segment == y.segment &&
                Same(x.instant, y.instant) && x.value == y.value && Same(x.sd, y.sd) &&
                x.n == y.n && Same(x.uncertainty, y.uncertainty) &&
                x.source == y.source && x.note == y.note && (!lines || x.line == y.line))
        << "summary " << k;
  }
  ASSERT_EQ(a.tracks.size(), b.tracks.size());
  for (std::size_t k = 0; k < a.tracks.size(); ++k) {
    const SensorTrack &s = a.tracks[k], &t = b.tracks[k];
    EXPECT_EQ(fs::path(s.file).lexically_relative(a.folder),
              fs::path(t.file).lexically_relative(b.folder));
    EXPECT_EQ(s.operator_id, t.operator_id);
    EXPECT_EQ(s.condition, t.condition);
    EXPECT_EQ(s.repetition, t.repetition);
    ASSERT_EQ(s.samples.size(), t.samples.size());
    for (std::size_t i = 0; i < s.samples.size(); ++i) {
      const TrackSample &x = s.samples[i], &y = t.samples[i];
      EXPECT_TRUE(x.time == y.time && x.part == y.part && x.brow == y.brow &&
                  x.left_shoulder == y.left_shoulder &&
                  x.right_shoulder == y.right_shoulder && x.body == y.body &&
                  Same(x.visibility, y.visibility) && (!lines || x.line == y.line))
          << "track " << k << " sample " << i;
    }
  }
}

std::string ReadText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(LabDatasetTest, LoadsAGoodDatasetInSiUnits) {
  const std::string manifest = WriteDataset(GoodFiles());
  const LabDataset d = LoadLabDataset(manifest);
  EXPECT_EQ(d.file, manifest);
  EXPECT_EQ(d.folder, fs::path(manifest).parent_path().string());
  EXPECT_EQ(d.name, "test_lab");
  EXPECT_EQ(d.provenance["recorded"], "2026-11-01");
  EXPECT_EQ(d.trials_file, "trials.csv");

  ASSERT_EQ(d.trials.size(), 4u);
  const LabTrial& t0 = d.trials[0];
  EXPECT_EQ(t0.operator_id, "male 1");
  EXPECT_EQ(t0.sex, "male");
  EXPECT_EQ(t0.height, 1.75);
  EXPECT_EQ(t0.arm_length, 0.74);
  EXPECT_EQ(t0.condition, "good");
  EXPECT_EQ(t0.part, "piston_rod");
  EXPECT_EQ(t0.repetition, 1);
  EXPECT_EQ(t0.time, 15.2);
  EXPECT_EQ(t0.success, 1);
  EXPECT_EQ(t0.line, 3);
  EXPECT_TRUE(std::isnan(d.trials[1].time));
  EXPECT_EQ(d.trials[1].success, 0);
  EXPECT_EQ(d.trials[1].note, "dropped, \"twice\"");
  EXPECT_EQ(d.trials[2].note, "a note\non two lines");
  EXPECT_EQ(d.trials[2].line, 6);
  EXPECT_EQ(d.trials[3].time, 10.0);
  EXPECT_EQ(d.trials[3].line, 8);

  ASSERT_EQ(d.segments.size(), 4u);
  EXPECT_EQ(d.segments[1].segment, 2);
  EXPECT_EQ(d.segments[1].start_min, 15.0);
  EXPECT_EQ(d.segments[1].end_min, 30.0);
  EXPECT_EQ(d.segments[1].successes, 20);
  EXPECT_EQ(d.segments[1].condition, "real");
  EXPECT_TRUE(std::isnan(d.segments[2].mean_time));
  EXPECT_EQ(d.segments[3].source, "Fig. 16, read off");

  ASSERT_EQ(d.summaries.size(), 3u);
  EXPECT_EQ(d.summaries[0].quantity, "assembly_time");
  EXPECT_EQ(d.summaries[0].segment, 0);
  EXPECT_TRUE(std::isnan(d.summaries[0].instant));
  EXPECT_EQ(d.summaries[0].sd, 1.2);
  EXPECT_EQ(d.summaries[0].n, 60);
  EXPECT_TRUE(std::isnan(d.summaries[0].uncertainty));
  EXPECT_EQ(d.summaries[1].uncertainty, 0.01);
  EXPECT_EQ(d.summaries[1].segment, 1);
  EXPECT_EQ(d.summaries[2].instant, 3.0);
  EXPECT_EQ(d.summaries[2].line, 5);

  ASSERT_EQ(d.tracks.size(), 1u);
  const SensorTrack& track = d.tracks[0];
  EXPECT_EQ(track.file, (fs::path(d.folder) / "tracks/op1_rep1.csv").string());
  EXPECT_EQ(track.operator_id, "male 1");
  EXPECT_EQ(track.repetition, 1);
  ASSERT_EQ(track.samples.size(), 3u);
  EXPECT_EQ(track.samples[1].time, 0.1);
  EXPECT_EQ(track.samples[1].part, Eigen::Vector3d(0.1, 0.2, 0.89));
  EXPECT_EQ(track.samples[1].left_shoulder, Eigen::Vector3d(-0.2, -0.45, 1.4));
  EXPECT_EQ(track.samples[1].body, Eigen::Vector3d(0, -0.45, 1.1));
  EXPECT_TRUE(std::isnan(track.samples[1].visibility));
  EXPECT_EQ(track.samples[2].visibility, 0.5);
  EXPECT_EQ(track.samples[2].line, 4);

  const std::string text = DescribeLabDataset(d);
  for (const char* s :
       {"lab dataset 'test_lab'", "provenance: synthetic: written by lab_dataset_test",
        "trials (trials.csv): 4 trials, 2 operators, 2 parts, 1 condition; 3 successful",
        "segments (segments.csv): 4 segments in 2 series; 88 of 100 attempts successful",
        "summaries (summaries.csv): 3 summaries: assembly_time 1, success_rate 1, eta 1",
        "tracks: 1 track, 3 samples"})
    EXPECT_THAT(text, HasSubstr(s));
}

TEST(LabDatasetTest, RoundTripsThroughWriteAndLoad) {
  const LabDataset original = LoadLabDataset(WriteDataset(GoodFiles()));
  const fs::path out = Folder("written");
  WriteLabDataset(original, out.string());
  const LabDataset again = LoadLabDataset((out / "dataset.json").string());
  ExpectSameData(original, again, false);
  EXPECT_EQ(again.tracks[0].file, (out / "tracks/op1_rep1.csv").string());
  EXPECT_FALSE(fs::exists(out / "dataset.json.partial"));

  // Written again, the same bytes; loaded, the same rows on the same lines.
  const fs::path out2 = Folder("written_again");
  WriteLabDataset(again, out2.string());
  for (const char* name : {"dataset.json", "trials.csv", "segments.csv", "summaries.csv",
                           "tracks/op1_rep1.csv"})
    EXPECT_EQ(ReadText(out / name), ReadText(out2 / name)) << name;
  ExpectSameData(again, LoadLabDataset((out2 / "dataset.json").string()), true);
}

TEST(LabDatasetTest, WriteRefusesWhatLoadWouldRefuseAndWritesNothing) {
  LabDataset d = LoadLabDataset(WriteDataset(GoodFiles()));
  d.trials[1].height = 25;  // m
  const fs::path out = Folder("refused");
  try {
    WriteLabDataset(d, out.string());
    ADD_FAILURE() << "a stature of 25 m was written";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (out / "trials.csv").string());
    EXPECT_EQ(e.where(), "line 3, column height");
    EXPECT_EQ(e.value(), "25");
  }
  EXPECT_FALSE(fs::exists(out / "dataset.json"));
  EXPECT_FALSE(fs::exists(out / "trials.csv"));
}

TEST(LabDatasetTest, ConvertsUnitsToSi) {
  Files f = GoodFiles();
  std::string& m = f["dataset.json"];
  Replace(&m, R"({"height": "m", "arm_length": "m", "time": "s"})",
          R"({"height": "mm", "arm_length": "cm", "time": "ms"})");
  Replace(&m, R"({"start": "min", "end": "min", "mean_time": "s"})",
          R"({"start": "s", "end": "s", "mean_time": "min"})");
  Replace(
      &m, R"("summaries": {"file": "summaries.csv"})",
      R"("summaries": {"file": "summaries.csv", "units": {"instant": "ms", "time": "min"}})");
  Replace(&m, R"({"time": "s", "position": "m"})", R"({"time": "ms", "position": "mm"})");
  f["trials.csv"] =
      "operator,sex,height,arm_length,condition,part,repetition,time,success\n"
      "male 1,male,1750,74,good,piston_rod,1,15200,1\n";
  f["segments.csv"] =
      "segment,start,end,attempts,successes,mean_time\n"
      "1,0,900,25,24,0.25\n"
      "2,900,1800,25,20,0.3\n";
  f["summaries.csv"] =
      "quantity,part,condition,segment,instant,value,sd,n,uncertainty,source\n"
      "assembly_time,all,,,,0.25,0.5,60,0.01,Sec. 5.2\n"
      "eta,piston_rod,,,3000,0.05,0.01,,0.01,Table 1\n";
  f["tracks/op1_rep1.csv"] =
      "time,part_x,part_y,part_z,brow_x,brow_y,brow_z,lshoulder_x,lshoulder_y,lshoulder_"
      "z,"
      "rshoulder_x,rshoulder_y,rshoulder_z,body_x,body_y,body_z\n"
      "0,100,200,900,0,-400,1600,-200,-450,1400,200,-450,1400,0,-450,1100\n"
      "100,100,200,890,0,-400,1600,-200,-450,1400,200,-450,1400,0,-450,1100\n";
  const LabDataset d = LoadLabDataset(WriteDataset(f));
  EXPECT_EQ(d.trials[0].height, 1.75);
  EXPECT_EQ(d.trials[0].arm_length, 0.74);
  EXPECT_EQ(d.trials[0].time, 15.2);
  EXPECT_EQ(d.segments[0].end_min, 15.0);  // s to the schedule's minutes
  EXPECT_EQ(d.segments[1].start_min, 15.0);
  EXPECT_EQ(d.segments[1].end_min, 30.0);
  EXPECT_EQ(d.segments[0].mean_time, 15.0);  // min to s
  EXPECT_EQ(d.segments[1].mean_time, 0.3 * 60);
  EXPECT_EQ(d.summaries[0].value, 15.0);
  EXPECT_EQ(d.summaries[0].sd, 30.0);
  EXPECT_EQ(d.summaries[0].uncertainty, 0.6);
  // Proportions and factors have no unit: units.time leaves them alone.
  EXPECT_EQ(d.summaries[1].value, 0.05);
  EXPECT_EQ(d.summaries[1].sd, 0.01);
  EXPECT_EQ(d.summaries[1].uncertainty, 0.01);
  EXPECT_EQ(d.summaries[1].instant, 3.0);
  EXPECT_EQ(d.tracks[0].samples[1].time, 0.1);
  EXPECT_EQ(d.tracks[0].samples[1].part, Eigen::Vector3d(0.1, 0.2, 0.89));
  EXPECT_EQ(d.tracks[0].samples[0].brow, Eigen::Vector3d(0, -0.4, 1.6));
  EXPECT_TRUE(std::isnan(d.tracks[0].samples[0].visibility));

  // A stature in mm read as m: the message shows the value in m.
  Replace(&f["trials.csv"], "1750,74", "25000,74");
  ExpectError(f, "trials.csv", "line 2, column height", "25000",
              "a stature lies in [1, 2.5] m (here 25 m, units mm)");
}

// ------------------------------------------------------------ malformed CSV

TEST(LabDatasetTest, UnterminatedQuote) {
  Files f = GoodFiles();
  Replace(&f["trials.csv"], "all,2,1e1,1,\n", "all,2,1e1,1,\"unclosed\n");
  ExpectError(f, "trials.csv", "line 8, column note", "\"unclosed", "not closed");
}

TEST(LabDatasetTest, WrongFieldCount) {
  Files f = GoodFiles();
  Replace(&f["segments.csv"], "2,15,30,25,20,16.9,real,\n", "2,15,30,25,20,16.9,real\n");
  ExpectError(f, "segments.csv", "line 3, column source", "(missing)",
              "the row has 7 fields, the header (line 1) 8");
  f = GoodFiles();
  Replace(&f["segments.csv"], "2,15,30,25,20,16.9,real,\n",
          "2,15,30,25,20,16.9,real,,x\n");
  ExpectError(f, "segments.csv", "line 3, column 9", "x",
              "the row has 9 fields, the header (line 1) 8");
}

TEST(LabDatasetTest, QuoteInsideAnUnquotedField) {
  Files f = GoodFiles();
  Replace(&f["trials.csv"], "good,piston_rod,1,", "good,piston\"rod,1,");
  ExpectError(f, "trials.csv", "line 3, column part", "piston\"",
              "a quote may only open");
}

// ------------------------------------------------------------ columns

TEST(LabDatasetTest, MissingRequiredColumn) {
  Files f = GoodFiles();
  f["trials.csv"] =
      "operator,height,arm_length,condition,part,repetition,time,success\n"
      "male 1,1.75,0.74,good,piston_rod,1,15.2,1\n";
  ExpectError(f, "trials.csv", "line 1, column sex", "(missing)",
              "lacks the required column 'sex'");
  // summaries.csv needs its source column.
  f = GoodFiles();
  f["summaries.csv"] =
      "quantity,part,condition,segment,instant,value,sd,n,uncertainty\n"
      "eta,piston_rod,,,3,0.05,,,\n";
  ExpectError(f, "summaries.csv", "line 1, column source", "(missing)", "'source'");
}

TEST(LabDatasetTest, UnknownColumn) {
  Files f = GoodFiles();
  Replace(&f["trials.csv"], "time,success,note", "time,succes,note");
  ExpectError(f, "trials.csv", "line 2, column succes", "succes", "unknown column");
  // Tracks take no free text: notes go in comment lines.
  f = GoodFiles();
  Replace(&f["tracks/op1_rep1.csv"], "body_z,visibility", "body_z,note");
  ExpectError(f, "tracks/op1_rep1.csv", "line 1, column note", "note", "unknown column");
}

// ------------------------------------------------------------ numbers

TEST(LabDatasetTest, BadNumbers) {
  Files f = GoodFiles();
  Replace(&f["trials.csv"], "good,piston_rod,1,15.2,", "good,piston_rod,1,1.5x,");
  ExpectError(f, "trials.csv", "line 3, column time", "1.5x", "must be a decimal number");
  f = GoodFiles();
  Replace(&f["trials.csv"], "good,piston_rod,1,15.2,", "good,piston_rod,1,nan,");
  ExpectError(f, "trials.csv", "line 3, column time", "nan", "finite");
  f = GoodFiles();
  Replace(&f["trials.csv"], "female 1,female,1.62,0.68,good,all,2,",
          "female 1,female,,0.68,good,all,2,");
  ExpectError(f, "trials.csv", "line 8, column height", "(empty)", "not empty");
  f = GoodFiles();
  Replace(&f["segments.csv"], "2,15,30,25,20,16.9,real,", "2,15,30,25,20, 16.9,real,");
  ExpectError(f, "segments.csv", "line 3, column mean_time", "\" 16.9\"",
              "must be a decimal number");
  f = GoodFiles();
  Replace(&f["trials.csv"], "piston_rod,2,,0,", "piston_rod,2.0,,0,");
  ExpectError(f, "trials.csv", "line 4, column repetition", "2.0", "an integer >= 1");
  f = GoodFiles();
  Replace(&f["tracks/op1_rep1.csv"], "0.1,0.1,0.2,0.89,", "0.1,0x1,0.2,0.89,");
  ExpectError(f, "tracks/op1_rep1.csv", "line 3, column part_x", "0x1", "decimal");
}

// ------------------------------------------------------------ ranges

TEST(LabDatasetTest, OutOfRangeValues) {
  Files f = GoodFiles();
  Replace(&f["trials.csv"], "good,piston_rod,1,15.2,", "good,piston_rod,1,-3,");
  ExpectError(f, "trials.csv", "line 3, column time", "-3", "an assembly time is > 0");
  f = GoodFiles();
  Replace(&f["trials.csv"], "1,15.2,1,\n", "1,15.2,2,\n");
  ExpectError(f, "trials.csv", "line 3, column success", "2", "an integer from 0 to 1");
  f = GoodFiles();
  Replace(&f["segments.csv"], "2,15,30,25,20,16.9", "2,15,30,25,26,16.9");
  ExpectError(f, "segments.csv", "line 3, column successes", "26",
              "successes are at most the attempts, 25");
  f = GoodFiles();
  Replace(&f["trials.csv"], "male 1,male,1.75,0.74,good,piston_rod,1,",
          "male 1,male,25,0.74,good,piston_rod,1,");
  ExpectError(f, "trials.csv", "line 3, column height", "25",
              "a stature lies in [1, 2.5] m");
  f = GoodFiles();
  Replace(&f["trials.csv"], "male 1,male,1.75,0.74,good,piston_rod,1,",
          "male 1,male,1.75,1.74,good,piston_rod,1,");
  ExpectError(f, "trials.csv", "line 3, column arm_length", "1.74", "[0.4, 1.2] m");
  f = GoodFiles();
  Replace(&f["trials.csv"], "male 1,male,1.75,0.74,good,piston_rod,1,15.2,1,",
          "male 1,male,1.75,0.74,good,piston_rod,1,,1,");
  ExpectError(f, "trials.csv", "line 3, column time", "(empty)",
              "may be empty only when success = 0");
  f = GoodFiles();
  Replace(&f["trials.csv"], "male 1,male,1.75,0.74,good,piston_rod,1,",
          "male 1,mail,1.75,0.74,good,piston_rod,1,");
  ExpectError(f, "trials.csv", "line 3, column sex", "mail", "male, female");
  f = GoodFiles();
  Replace(&f["summaries.csv"], ",0.92,", ",92,");
  ExpectError(f, "summaries.csv", "line 4, column value", "92",
              "success_rate is a proportion or factor in [0, 1]");
  f = GoodFiles();
  Replace(&f["summaries.csv"], ",0.05,,,,Table 1", ",0.05,,,,");
  ExpectError(f, "summaries.csv", "line 5, column source", "(empty)",
              "must not be empty");
  f = GoodFiles();
  Replace(&f["summaries.csv"], "eta,piston_rod", "ETA,piston_rod");
  ExpectError(f, "summaries.csv", "line 5, column quantity", "ETA",
              "one of: assembly_time");
  f = GoodFiles();
  Replace(&f["tracks/op1_rep1.csv"], "1.1,0.5\r\n", "1.1,1.5\r\n");
  ExpectError(f, "tracks/op1_rep1.csv", "line 4, column visibility", "1.5", "[0, 1]");
}

TEST(LabDatasetTest, RowsAgreeWithEachOther) {
  // A trial appears once.
  Files f = GoodFiles();
  Replace(&f["trials.csv"], "all,2,1e1", "all,1,1e1");
  ExpectError(f, "trials.csv", "line 8, column repetition", "1",
              "line 6 has the same operator, condition, part and repetition");
  // An operator is one person.
  f = GoodFiles();
  Replace(&f["trials.csv"], "female 1,female,1.62,0.68,good,all,2",
          "female 1,female,1.63,0.68,good,all,2");
  ExpectError(f, "trials.csv", "line 8, column height", "1.63",
              "operator 'female 1' has height 1.62 m on line 6");
  // Segments are numbered 1, 2, ... within their series, and do not overlap.
  f = GoodFiles();
  Replace(&f["segments.csv"], "2,15,30,25,19", "3,15,30,25,19");
  ExpectError(f, "segments.csv", "line 5, column segment", "3",
              "segments of condition 'virtual' are numbered 1, 2, ... in file order: 2 "
              "expected");
  f = GoodFiles();
  Replace(&f["segments.csv"], "2,15,30,25,19", "2,14,30,25,19");
  ExpectError(f, "segments.csv", "line 5, column start", "14",
              "segments do not overlap: segment 1 ends at 15 min (line 4)");
  f = GoodFiles();
  Replace(&f["segments.csv"], "1,0,15,25,24,16.1", "1,0,15,25,0,16.1");
  ExpectError(f, "segments.csv", "line 2, column mean_time", "16.1", "successes = 0");
}

TEST(LabDatasetTest, NonIncreasingTrackTime) {
  Files f = GoodFiles();
  Replace(&f["tracks/op1_rep1.csv"], "0.2,0.1,0.2,0.88", "0.1,0.1,0.2,0.88");
  ExpectError(f, "tracks/op1_rep1.csv", "line 4, column time", "0.1",
              "a track's time increases strictly: line 3 has 0.1 s");
  // ... and has at least two samples.
  f = GoodFiles();
  f["tracks/op1_rep1.csv"] = f["tracks/op1_rep1.csv"].substr(
      0, f["tracks/op1_rep1.csv"].find("0.1,0.1,0.2,0.89"));
  ExpectError(f, "tracks/op1_rep1.csv", "line 1", "1 data row", "at least 2 data rows");
}

// ------------------------------------------------------------ the manifest

TEST(LabDatasetTest, MissingFile) {
  Files f = GoodFiles();
  f.erase("segments.csv");
  ExpectError(f, "dataset.json", "/segments/file", "\"segments.csv\"", "no such file");
}

TEST(LabDatasetTest, UnknownManifestKey) {
  Files f = GoodFiles();
  Replace(&f["dataset.json"], R"("trials": {"file": "trials.csv", "units")",
          R"("trials": {"file": "trials.csv", "unit")");
  ExpectError(f, "dataset.json", "/trials/unit",
              R"({"arm_length":"m","height":"m","time":"s"})", "did you mean 'units'?");
  f = GoodFiles();
  Replace(&f["dataset.json"], R"("name": "test_lab",)",
          R"("name": "test_lab", "kind": 1,)");
  ExpectError(f, "dataset.json", "/kind", "1", "unknown key 'kind'");
}

TEST(LabDatasetTest, BadUnit) {
  Files f = GoodFiles();
  Replace(&f["dataset.json"], R"("height": "m")", R"("height": "ft")");
  ExpectError(f, "dataset.json", "/trials/units/height", "\"ft\"",
              "must be one of: m, cm, mm");
  // Every column with a physical unit is given one.
  f = GoodFiles();
  Replace(&f["dataset.json"], R"({"time": "s", "position": "m"})", R"({"time": "s"})");
  ExpectError(f, "dataset.json", "/tracks/0/units/position", "(missing)", "is missing");
  // Segment bounds are a schedule: minutes or seconds.
  f = GoodFiles();
  Replace(&f["dataset.json"], R"("start": "min")", R"("start": "ms")");
  ExpectError(f, "dataset.json", "/segments/units/start", "\"ms\"", "one of: min, s");
}

TEST(LabDatasetTest, ManifestRules) {
  Files f = GoodFiles();
  Replace(&f["dataset.json"], R"("format": "vahf-lab/1")", R"("format": "vahf-lab/2")");
  ExpectError(f, "dataset.json", "/format", "\"vahf-lab/2\"", "\"vahf-lab/1\"");
  f = GoodFiles();
  Replace(&f["dataset.json"], R"("name": "test_lab")", R"("name": "test lab")");
  ExpectError(f, "dataset.json", "/name", "\"test lab\"", "letters, digits");
  f = GoodFiles();
  Replace(&f["dataset.json"], R"("source": "synthetic: written by lab_dataset_test", )",
          "");
  ExpectError(f, "dataset.json", "/provenance/source", "(missing)", "is missing");
  f = GoodFiles();
  Replace(&f["dataset.json"], R"("recorded": "2026-11-01")", R"("recorded": 2026)");
  ExpectError(f, "dataset.json", "/provenance/recorded", "2026", "must be a string");
  f = GoodFiles();
  Replace(&f["dataset.json"], R"("file": "trials.csv")", R"("file": "../trials.csv")");
  ExpectError(f, "dataset.json", "/trials/file", "\"../trials.csv\"", "inside");
  f = GoodFiles();
  Replace(&f["dataset.json"], R"("file": "summaries.csv")",
          R"("file": "./segments.csv")");
  ExpectError(f, "dataset.json", "/summaries/file", "\"./segments.csv\"",
              "names the same file as /segments/file");
  f = GoodFiles();
  f["dataset.json"] = R"({"format": "vahf-lab/1", "name": "x", "description": "-",
                          "provenance": {"source": "t"}})";
  ExpectError(
      f, "dataset.json", "/",
      R"({"description":"-","format":"vahf-lab/1","name":"x","provenance":{"source":"t"}})",
      "at least one of trials, segments, summaries and tracks");
  f = GoodFiles();
  f["segments.csv"] = "# no rows yet\nsegment,start,end,attempts,successes,mean_time\n";
  ExpectError(f, "segments.csv", "line 2", "0 data rows", "at least 1 data row");
}

}  // namespace
}  // namespace vahf::data
