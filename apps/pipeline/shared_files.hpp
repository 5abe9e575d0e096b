#pragma once
// One check, before any work, that no two outputs of a command and no output and input name the
// same file: `--json` pointed at the `--scene` OBJ overwrote it, `--json X --trace X` replaced the
// trace, `--json x.csv --trace x.json` the trace's CSV. Files are compared by device and inode
// where they exist and by resolved path where not; a trace counts as the three files it writes.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace gcsim::pipeline {

// A file a command line names: the option (for the message) and the path.
struct NamedFile {
  std::string option;
  std::string path;
};

// Throws FileError naming both options when two of `outputs`, or an output and one of `inputs`,
// are the same file. Paths that exist and are not regular files (/dev/null) are not compared.
void check_distinct_files(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs);

// The files `--trace PATH` writes: PATH's .json, .csv and .paje. Throws FileError when PATH
// exists and is not a regular file (a device such as /dev/full): the other two would be
// created beside it, in /dev.
std::vector<NamedFile> named_trace_files(const std::string& path);

// Runs check_distinct_files on the options of the command being run, after parsing and before any
// command's callback: --json, --csv, --image, --steps-csv, --radiosities, --trace, a file --out
// are outputs; --scene, --config and the trace commands' files are inputs.
void refuse_shared_files(CLI::App* root);

}  // namespace gcsim::pipeline
