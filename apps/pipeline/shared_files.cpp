#include "apps/pipeline/shared_files.hpp"

#include <sys/stat.h>

#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "apps/pipeline/failure.hpp"
#include "machine/trace_csv.hpp"

namespace gcsim::pipeline {

namespace {

namespace fs = std::filesystem;

// What two paths are compared by: device and inode when the file exists, else the resolved path.
struct FileIdentity {
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  std::string resolved;
  bool operator==(const FileIdentity& o) const {
    return exists == o.exists && (exists ? device == o.device && inode == o.inode : resolved == o.resolved);
  }
};

// Nothing for a path that exists and is not a regular file: writing a device twice loses nothing.
std::optional<FileIdentity> identity_of(const std::string& path) {
  FileIdentity id;
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    if (!S_ISREG(st.st_mode)) return std::nullopt;
    id.exists = true;
    id.device = st.st_dev;
    id.inode = st.st_ino;
    return id;
  }
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  id.resolved = ec ? path : p.string();
  return id;
}

struct Role {
  std::vector<NamedFile> outputs, inputs;
};

// How a command's option is read: as an output file, an input file, or neither.
void classify(const std::string& command, const CLI::Option& opt, Role& r) {
  const std::string name = opt.get_name();
  for (const std::string& value : opt.results()) {
    if (value.empty()) continue;
    const NamedFile f{name, value};
    if (command == "plot") return;  // inputs only; --out is a directory
    if (command == "report") {
      if (name == "run" || name == "--trace") r.inputs.push_back(f);
      continue;
    }
    if (command == "paje") {
      if (name == "csv") r.inputs.push_back({name, machine::trace_sibling_path(value, ".csv")});
      if (name == "--out") r.outputs.push_back(f);
      continue;
    }
    if (name == "--trace") {
      for (NamedFile& t : named_trace_files(value)) r.outputs.push_back(std::move(t));
    } else if (name == "--json" || name == "--csv" || name == "--image" || name == "--steps-csv" ||
               name == "--radiosities" || name == "--out") {
      r.outputs.push_back(f);
    } else if ((name == "--scene" || name == "scene" || name == "--config") && fs::exists(value)) {
      r.inputs.push_back(f);
    }
  }
}

void check_command_line(CLI::App* root) {
  Role role;
  std::vector<CLI::App*> chain{root};
  while (!chain.back()->get_subcommands().empty()) chain.push_back(chain.back()->get_subcommands().front());
  const std::string command = chain.back()->get_name();
  for (CLI::App* app : chain)
    for (const CLI::Option* opt : app->get_options())
      if (opt->count() > 0) classify(command, *opt, role);
  check_distinct_files(role.outputs, role.inputs);
}

std::string described(const NamedFile& f) {
  return f.option.rfind("--trace ", 0) == 0 ? f.option : fmt::format("{} {}", f.option, f.path);
}

}  // namespace

std::vector<NamedFile> named_trace_files(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    throw FileError(fmt::format("--trace {}: is not a regular file; a trace is FILE.json with FILE.csv and FILE.paje "
                                "written beside it, so --trace must name a file",
                                path));
  std::vector<NamedFile> files{{"--trace " + path, path}};  // the Chrome JSON is the path itself
  for (const char* ext : {".csv", ".paje"}) {
    const std::string file = machine::trace_sibling_path(path, ext);
    if (file == path)
      throw FileError(fmt::format("--trace {}: name the Chrome JSON (FILE.json); FILE.csv and FILE.paje go beside it", path));
    files.push_back({fmt::format("--trace {} (its {})", path, file), file});
  }
  return files;
}

void check_distinct_files(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs) {
  std::vector<std::optional<FileIdentity>> out_ids;
  for (const NamedFile& o : outputs) out_ids.push_back(identity_of(o.path));
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (!out_ids[i]) continue;
    for (const NamedFile& in : inputs)
      if (const auto id = identity_of(in.path); id && *id == *out_ids[i])
        throw FileError(fmt::format("{} would overwrite the input {} {}: they name the same file; write the output elsewhere",
                                    described(outputs[i]), in.option, in.path));
    for (std::size_t j = 0; j < i; ++j)
      if (out_ids[j] && *out_ids[j] == *out_ids[i])
        throw FileError(fmt::format("{} and {} name the same file; give each output its own file", described(outputs[j]),
                                    described(outputs[i])));
  }
}

void refuse_shared_files(CLI::App* root) {
  root->parse_complete_callback([root] { check_command_line(root); });
}

}  // namespace gcsim::pipeline
