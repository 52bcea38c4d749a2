#include "vahf/report/manifest.h"

#include <algorithm>
#include <cstdint>
#include <string_view>

#include "vahf/core/error.h"
#include "vahf/report/digest.h"
#include "vahf/scene/parameter_table.h"

namespace vahf::report {

InputFile DescribeInputFile(const std::string& path) {
  return {path, Sha256OfFile(path)};
}

nlohmann::json ParametersToJson(const scene::Parameters& p) {
  scene::Parameters copy = p;  // the table's accessors return mutable references
  nlohmann::json out = nlohmann::json::object();
  for (const scene::ParamSpec& spec : scene::ParameterTable()) {
    nlohmann::json& slot = out[spec.group][spec.key];
    if (spec.real && spec.rule == scene::ParamRule::kCount) {
      slot = static_cast<std::int64_t>(spec.real(copy));  // a declared count
    } else if (spec.real) {
      slot = spec.real(copy);
    } else if (spec.count) {
      slot = spec.count(copy);
    } else {
      slot = spec.text(copy);
    }
  }
  return out;
}

namespace {

// One file's share of the results digest: name, NUL, bytes, NUL.
template <class AddBytes>
void AddResultFile(Sha256& sha, const std::string& name, AddBytes add_bytes) {
  const std::string_view nul("\0", 1);
  sha.Update(name);
  sha.Update(nul);
  add_bytes();
  sha.Update(nul);
}

}  // namespace

std::string ResultsDigest(const std::map<std::string, std::string>& files) {
  Sha256 sha;
  for (const auto& [name, bytes] : files) {
    AddResultFile(sha, name, [&, &b = bytes] { sha.Update(b); });
  }
  return sha.HexDigest();
}

std::string ResultsDigestOfFiles(const std::string& root,
                                 const std::vector<std::string>& names) {
  std::vector<std::string> sorted = names;
  std::sort(sorted.begin(), sorted.end());
  VAHF_CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end(),
             "a result file is named twice");
  Sha256 sha;
  for (const std::string& name : sorted) {
    AddResultFile(sha, name, [&] { sha.UpdateFromFile(root + "/" + name); });
  }
  return sha.HexDigest();
}

nlohmann::json ManifestJson(const ManifestFields& f) {
  const auto input = [](const InputFile& file) {
    return nlohmann::json{{"path", file.path}, {"sha256", file.sha256}};
  };
  const BuildInfo& b = f.build;
  nlohmann::json libraries = nlohmann::json::object();
  for (const auto& [name, version] : b.libraries) libraries[name] = version;
  return {
      {"format", kManifestFormat},
      {"experiment", input(f.experiment)},
      {"scene", input(f.scene)},
      {"seed", f.seed},
      {"trials", f.trials},
      {"threads", f.threads},
      {"parameters", ParametersToJson(f.parameters)},
      {"build",
       {{"version", b.version},
        {"git_describe", b.git_describe},
        {"compiler", b.compiler_id},
        {"compiler_version", b.compiler_version},
        {"build_type", b.build_type},
        {"cxx_flags", b.cxx_flags},
        {"libraries", libraries}}},
      {"result_files", f.result_files},
      {"results_digest", f.results_digest},
  };
}

}  // namespace vahf::report
