// `gcsim help [COMMAND...]`: the help of any command, word for word what `gcsim COMMAND --help`
// prints (the same CLI11 formatter on the same App), for those who type help first.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "apps/cli/commands.hpp"

namespace gcsim::cli {

namespace {

// The help of the command the words name, below root, as `--help` formats it (with the command's
// whole path in its usage line); throws a usage error naming the first unknown word.
std::string command_help(CLI::App* root, const std::vector<std::string>& words) {
  CLI::App* at = root;
  std::string path = "gcsim";
  for (const std::string& w : words) {
    CLI::App* sub = nullptr;
    for (CLI::App* candidate : at->get_subcommands({}))
      if (candidate->get_name() == w) sub = candidate;
    if (sub == nullptr) {
      std::string known;
      for (CLI::App* candidate : at->get_subcommands({}))
        if (candidate->get_name() != "help") known += (known.empty() ? "" : ", ") + candidate->get_name();
      throw CLI::ValidationError("help", "'" + path + " " + w + "' is not a command; '" + path + "' has: " + known);
    }
    at = sub;
    path += " " + w;
  }
  return at->get_formatter()->make_help(at, path, CLI::AppFormatMode::Normal);
}

}  // namespace

void add_help_command(CLI::App* root) {
  CLI::App* cmd = root->add_subcommand("help", "Show a command's help: gcsim help run radiosity");
  auto words = std::make_shared<std::vector<std::string>>();
  cmd->add_option("command", *words, "The command's words, as typed after gcsim (none: gcsim's own help)");
  cmd->callback([root, words] { std::cout << command_help(root, *words); });
}

}  // namespace gcsim::cli
