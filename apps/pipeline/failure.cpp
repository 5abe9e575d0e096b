#include "apps/pipeline/failure.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

namespace gcsim::pipeline {

std::string exit_code_table() {
  return "Exit codes:\n"
         "    0  ok\n"
         "    1  the run failed or did not reach its goal (e.g. radiosity threshold not reached)\n"
         "    2  usage: unknown option, bad or inconsistent values\n"
         "    3  a file cannot be read, parsed or written (scene, machine file, output path)\n"
         "    4  resources: host or node memory exhausted\n"
         "    5  deadlock in the simulated program\n"
         "    6  an MPI program's error under MPI_ERRORS_ARE_FATAL (gcsim mpirun)\n"
         "   70  a simulated processor overflowed its fiber stack (raise [runtime] fiber_stack_kib)\n"
         "  130  interrupted (SIGINT or SIGTERM): finished results written, marked \"interrupted\"";
}

namespace {

// Messages echo what they were given (an argument, a file's field); a word of a megabyte would
// be echoed whole. Words longer than kLongWord keep their first kKeptChars, then say how long.
std::string shorten_long_words(std::string_view message) {
  constexpr std::size_t kLongWord = 120, kKeptChars = 80;
  std::string out;
  std::size_t i = 0;
  while (i < message.size()) {
    const std::size_t end = std::min(message.find_first_of(" \n\t", i), message.size());
    if (end - i > kLongWord)
      out += fmt::format("{}... ({} characters)", message.substr(i, kKeptChars), end - i);
    else
      out += message.substr(i, end - i);
    if (end < message.size()) out += message[end];
    i = end + 1;
  }
  return out;
}

}  // namespace

void print_error(std::string_view message) {
  std::string line = fmt::format("gcsim: error: {}", shorten_long_words(message));
  if (line.empty() || line.back() != '\n') line += '\n';
  std::fputs(line.c_str(), stderr);
  std::fflush(stderr);
}

void check_writable(const std::string& path, std::string_view option) {
  if (path.empty()) return;
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw FileError(fmt::format("{} {}: is a directory, expected a file name", option, path));
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty() && !fs::is_directory(parent, ec))
    throw FileError(fmt::format("{} {}: directory '{}' does not exist", option, path, parent.string()));
  const bool existed = fs::exists(path, ec);
  std::FILE* f = std::fopen(path.c_str(), "a");  // "a": an existing file is neither truncated nor changed
  if (!f) throw FileError(fmt::format("{} {}: cannot write ({})", option, path, std::strerror(errno)));
  std::fclose(f);
  if (!existed) fs::remove(path, ec);
}

}  // namespace gcsim::pipeline
