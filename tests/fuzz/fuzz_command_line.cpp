// Fuzz target: the gcsim command line of every subcommand, parsed with all its checks but never
// run (every command's callback is set aside). The input is the argument vector, one argument per
// line. Parsing must end normally or with a CLI11 error (the usage exit code); any other exception
// escapes and is a finding, as is a crash or a sanitizer report.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "apps/cli/cli_app.hpp"
#include "tests/fuzz/fuzz_input.hpp"

namespace {

// The commands' callbacks own their options' storage (a shared_ptr captured by the lambda), so a
// callback is moved aside, not destroyed, for as long as the parse runs. CLI11 has no getter; a
// pointer to the protected member, taken in a derived class, reaches it legally on any App.
struct CallbackAccess : CLI::App {
  static constexpr auto final_callback = &CallbackAccess::final_callback_;
  static constexpr auto parse_complete_callback = &CallbackAccess::parse_complete_callback_;
};

void set_callbacks_aside(CLI::App* app, std::vector<std::function<void()>>& kept) {
  for (auto member : {CallbackAccess::final_callback, CallbackAccess::parse_complete_callback}) {
    kept.push_back(std::move(app->*member));
    app->*member = nullptr;
  }
  for (CLI::App* sub : app->get_subcommands({})) set_callbacks_aside(sub, kept);
}

std::vector<std::string> arguments(std::string_view text) {
  std::vector<std::string> args{"gcsim"};
  std::size_t start = 0;
  while (start <= text.size() && args.size() < 64) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    args.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  if (args.size() > 1 && args.back().empty()) args.pop_back();  // a final newline
  return args;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::string> args = arguments(gcsim::fuzz::as_text(data, size));
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  std::vector<std::function<void()>> kept;  // destroyed after app, whose options point into them
  CLI::App app{gcsim::cli::gcsim_description(), "gcsim"};
  gcsim::cli::declare_commands(&app);
  set_callbacks_aside(&app, kept);
  try {
    app.parse(int(argv.size()), argv.data());
  } catch (const CLI::Error&) {
  }
  return 0;
}
