// A run's output directory, written whole or not at all (docs/design.md, "Outputs";
// docs/outputs.md). Every file is staged in a sibling directory PATH.partial;
// Commit() swaps it in for PATH with renames, so PATH holds either the previous
// complete output or the new complete output, never a mixture or a part.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace vahf::report {

class OutputDirectory {
 public:
  // An existing PATH is replaced only if it is a directory that is empty or
  // holds this file (a previous run's output): a mistyped path never deletes
  // someone's files.
  static constexpr const char* kMarkerFile = "manifest.json";

  // Checks that PATH may be replaced, creates its parent folders, and creates
  // PATH.partial fresh (removing one a crashed run left). Failures are
  // InputErrors naming the path and the operating system's reason.
  explicit OutputDirectory(const std::string& path);
  // Without Commit(), removes the staging directory: PATH is untouched.
  ~OutputDirectory();
  OutputDirectory(const OutputDirectory&) = delete;
  OutputDirectory& operator=(const OutputDirectory&) = delete;

  const std::string& path() const { return path_; }        // where Commit() puts it
  const std::string& staging() const { return staging_; }  // PATH.partial

  // Writes `bytes` to `relative` ("table.csv", "plots/time.png") in staging,
  // creating folders on the way. `relative` must be a plain relative path
  // without "." or ".." parts (else a bug).
  void Write(const std::string& relative, std::string_view bytes);

  // The staging path of `relative`, its folders created, for a file another
  // program writes (a gnuplot plot).
  std::string Path(const std::string& relative);

  // The regular files staged so far, relative, '/'-separated, sorted by name.
  std::vector<std::string> Files() const;

  // Replaces PATH by the staged directory: renames PATH to PATH.old (removing
  // a stale one), renames PATH.partial to PATH, then removes PATH.old. If the
  // second rename fails, PATH.old is renamed back. Once only.
  void Commit();
  bool committed() const { return committed_; }

 private:
  std::string StagedPath(const std::string& relative) const;

  std::string path_;
  std::string staging_;
  bool committed_ = false;
};

}  // namespace vahf::report
