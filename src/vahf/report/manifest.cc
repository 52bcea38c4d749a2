#include "vahf/report/manifest.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string_view>

#include "vahf/core/digest.h"
#include "vahf/core/error.h"
#include "vahf/scene/json_reader.h"
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

namespace {

nlohmann::json BuildJson(const BuildInfo& b) {
  nlohmann::json libraries = nlohmann::json::object();
  for (const auto& [name, version] : b.libraries) libraries[name] = version;
  return {{"version", b.version},       {"git_describe", b.git_describe},
          {"compiler", b.compiler_id},  {"compiler_version", b.compiler_version},
          {"build_type", b.build_type}, {"cxx_flags", b.cxx_flags},
          {"libraries", libraries}};
}

nlohmann::json InvocationJson(const Invocation& i) {
  return {{"experiment", i.experiment},
          {"overrides", i.overrides},
          {"seed", i.seed},
          {"trials", i.trials}};
}

}  // namespace

nlohmann::json ManifestJson(const ManifestFields& f) {
  const auto input = [](const InputFile& file) {
    return nlohmann::json{{"path", file.path}, {"sha256", file.sha256}};
  };
  return {
      {"format", kManifestFormat},
      {"invocation", InvocationJson(f.invocation)},
      {"experiment", input(f.experiment)},
      {"scene", input(f.scene)},
      {"seed", f.seed},
      {"trials", f.trials},
      {"threads", f.threads},
      {"ranks", f.ranks},
      {"parameters", ParametersToJson(f.parameters)},
      {"build", BuildJson(f.build)},
      {"result_files", f.result_files},
      {"results_digest", f.results_digest},
  };
}

nlohmann::json RunIdentity(const Invocation& i, const std::vector<std::string>& files) {
  nlohmann::json digests = nlohmann::json::object();
  for (const std::string& f : files)
    if (!f.empty()) digests[f] = Sha256OfFile(f);
  return {{"invocation", InvocationJson(i)},
          {"inputs", digests},
          {"build", BuildJson(GetBuildInfo())}};
}

bool RecordsRun(const nlohmann::json& manifest, const nlohmann::json& identity) {
  if (!manifest.is_object() || !identity.is_object()) return false;
  for (const char* key : {"invocation", "build"})
    if (!manifest.contains(key) || !identity.contains(key) ||
        manifest.at(key) != identity.at(key))
      return false;
  const nlohmann::json digests = identity.value("inputs", nlohmann::json::object());
  std::vector<nlohmann::json> recorded = {manifest.value("experiment", nlohmann::json()),
                                          manifest.value("scene", nlohmann::json())};
  const nlohmann::json inputs = manifest.value("inputs", nlohmann::json::array());
  if (inputs.is_array()) recorded.insert(recorded.end(), inputs.begin(), inputs.end());
  for (const nlohmann::json& input : recorded) {
    if (!input.is_object() || !input.contains("path") || !input.at("path").is_string())
      continue;
    const std::string path = input.at("path").get<std::string>();
    if (digests.is_object() && digests.contains(path) &&
        input.value("sha256", nlohmann::json()) != digests.at(path))
      return false;
  }
  return true;
}

namespace {

bool IsHexDigest(const std::string& s) {
  return s.size() == 64 && std::all_of(s.begin(), s.end(), [](char c) {
           return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
         });
}

RecordedRun::Input ReadInput(const scene::JsonNode& node) {
  node.ExpectObject({"path", "sha256"});
  RecordedRun::Input in;
  in.file.path = node.Required("path").String();
  const scene::JsonNode sha = node.Required("sha256");
  in.file.sha256 = sha.String();
  if (!IsHexDigest(in.file.sha256)) sha.Fail("must be 64 lowercase hexadecimal digits");
  in.pointer = sha.path();
  return in;
}

// A result file's name: relative, '/'-separated, without empty, "." or ".."
// parts, so that it names a file inside the run directory.
std::string ResultFileName(const scene::JsonNode& node) {
  const std::string name = node.String();
  bool plain = !name.empty() && name.front() != '/';
  for (std::size_t start = 0; plain && start <= name.size();) {
    const std::size_t end = std::min(name.find('/', start), name.size());
    const std::string part = name.substr(start, end - start);
    plain = !part.empty() && part != "." && part != "..";
    start = end + 1;
  }
  if (!plain) node.Fail("must be a relative path inside the run directory");
  return name;
}

}  // namespace

RecordedRun ReadManifest(const std::string& path) {
  const nlohmann::json document = scene::ReadJsonFile(path);
  const scene::JsonNode root(document, path);
  RecordedRun run;
  run.file = path;
  const scene::JsonNode format = root.Required("format");
  if (format.String() != kManifestFormat)
    format.Fail(std::string("must be \"") + kManifestFormat +
                "\": not a vahf run's manifest");
  const std::optional<scene::JsonNode> invocation = root.Optional("invocation");
  if (!invocation)
    root.Fail(
        "has no \"invocation\": it was written by a vahf without `vahf verify`; run "
        "the experiment again for a manifest verify can read");
  invocation->ExpectObject({"experiment", "overrides", "seed", "trials"});
  Invocation& i = run.invocation;
  i.experiment = invocation->Required("experiment").String();
  i.overrides = invocation->Required("overrides").String();
  i.seed = invocation->Required("seed").Unsigned();
  i.trials = invocation->Required("trials").Integer(0, 10'000'000);
  run.threads = static_cast<int>(root.Required("threads").Integer(1, 1024));
  if (const auto ranks = root.Optional("ranks"))
    run.ranks = static_cast<int>(ranks->Integer(1, 1 << 24));
  run.inputs.push_back(ReadInput(root.Required("experiment")));
  run.inputs.push_back(ReadInput(root.Required("scene")));
  if (const auto inputs = root.Optional("inputs"))
    for (std::size_t k = 0; k < inputs->ArraySize(); ++k)
      run.inputs.push_back(ReadInput(inputs->At(k)));
  run.build = root.Required("build").json();
  if (!run.build.is_object()) root.Required("build").Fail("must be an object");
  const scene::JsonNode files = root.Required("result_files");
  for (std::size_t k = 0; k < files.ArraySize(1); ++k)
    run.result_files.push_back(ResultFileName(files.At(k)));
  const scene::JsonNode digest = root.Required("results_digest");
  run.results_digest = digest.String();
  if (!IsHexDigest(run.results_digest))
    digest.Fail("must be 64 lowercase hexadecimal digits");
  return run;
}

std::vector<std::string> BuildDifferences(const nlohmann::json& recorded,
                                          const BuildInfo& build) {
  const nlohmann::json mine = BuildJson(build);
  // Flattened to "key" and "libraries/NAME", both sides' keys in order.
  const auto flat = [](const nlohmann::json& j) {
    std::map<std::string, std::string> out;
    for (const auto& [key, value] : j.items()) {
      if (key == "libraries" && value.is_object()) {
        for (const auto& [name, version] : value.items())
          out["libraries/" + name] =
              version.is_string() ? version.get<std::string>() : version.dump();
      } else {
        out[key] = value.is_string() ? value.get<std::string>() : value.dump();
      }
    }
    return out;
  };
  const std::map<std::string, std::string> a = flat(recorded), b = flat(mine);
  std::map<std::string, std::pair<std::string, std::string>> both;
  for (const auto& [k, v] : a) both[k].first = v;
  for (const auto& [k, v] : b) both[k].second = v;
  std::vector<std::string> out;
  for (const auto& [key, values] : both)
    if (values.first != values.second)
      out.push_back(key + ": " + (values.first.empty() ? "(none)" : values.first) +
                    " (run) vs " + (values.second.empty() ? "(none)" : values.second) +
                    " (this program)");
  return out;
}

}  // namespace vahf::report
