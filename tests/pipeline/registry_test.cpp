// The app registry and the backend entry point: names are unique, lists are sorted, and an
// unknown backend is refused with the known ones named.
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "apps/pipeline/app_registry.hpp"
#include "parix/backend.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::pipeline {
namespace {

AppSpec spec(const std::string& name) {
  AppSpec s;
  s.name = name;
  s.summary = "a test application";
  s.options = [](CLI::App&, Verb) -> ExperimentFactory { return [] { return std::unique_ptr<Experiment>(); }; };
  return s;
}

TEST(AppRegistry, ListsAppsSortedByNameAndRefusesDuplicates) {
  register_app(spec("zz-registry-test"));
  register_app(spec("aa-registry-test"));
  const auto apps = registered_apps();
  for (std::size_t i = 1; i < apps.size(); ++i) EXPECT_LT(apps[i - 1]->name, apps[i]->name);
  EXPECT_THROW(register_app(spec("aa-registry-test")), std::logic_error);
  AppSpec nameless = spec("");
  EXPECT_THROW(register_app(nameless), std::logic_error);
}

TEST(AppRegistry, CommandFamiliesAddTheirCommandsAfterTheAppsAndShareTheirNames) {
  register_app(spec("family-clash-test"));
  std::vector<std::string> order;
  register_command_family({.name = "zz-family-test", .commands = [&](CommandGroups& g) {
                             order.push_back("zz");
                             g.app->add_subcommand("zz-family-cmd", "from a family");
                           }});
  register_command_family({.name = "aa-family-test", .commands = [&](CommandGroups&) { order.push_back("aa"); }});
  EXPECT_THROW(register_command_family({.name = "aa-family-test", .commands = [](CommandGroups&) {}}), std::logic_error);
  EXPECT_THROW(register_command_family({.name = "family-clash-test", .commands = [](CommandGroups&) {}}), std::logic_error);
  EXPECT_THROW(register_command_family({.name = "no-commands-test", .commands = {}}), std::logic_error);
  CLI::App app;
  CommandGroups g{&app, app.add_subcommand("run"), app.add_subcommand("sweep")};
  add_app_commands(g);
  EXPECT_EQ(order, (std::vector<std::string>{"aa", "zz"}));
  EXPECT_NO_THROW(app.get_subcommand("zz-family-cmd"));
  EXPECT_NO_THROW(g.run->get_subcommand("family-clash-test"));
}

TEST(AppRegistry, ExamplesAreListedWithTheirDescriptionsInOneColumn) {
  AppSpec s = spec("examples-test");
  s.examples = {"gcsim run examples-test --nodes 4  what it shows", "gcsim run examples-test --a-very-long-option-list  long",
                "gcsim run examples-test"};
  register_app(s);
  const std::string text = app_examples(40);
  const std::string command = "gcsim run examples-test --nodes 4";
  EXPECT_NE(text.find("  " + command + std::string(40 - command.size(), ' ') + "what it shows\n"), std::string::npos) << text;
  EXPECT_NE(text.find("--a-very-long-option-list  long\n"), std::string::npos) << text;  // too long: two spaces
  EXPECT_NE(text.find("  gcsim run examples-test\n"), std::string::npos) << text;        // no description
}

TEST(Backend, SimulatedRunsTheProgramOnEveryNode) {
  parix::RunOptions o;
  o.simulation.config = machine::with_nodes(machine::published_machine_config(), 4);
  int ran = 0;
  const parix::RunResult r = parix::run(o, [&](parix::Processor& p) {
    ++ran;
    p.compute("flop", 1000 * (p.id() + 1));
  });
  EXPECT_EQ(ran, 4);
  EXPECT_EQ(r.nodes, 4);
  // The slowest node did 4000 operations; the run takes exactly as long as run_simulated says.
  EXPECT_EQ(r.makespan, parix::run_simulated(o.simulation, [](parix::Processor& p) { p.compute("flop", 1000 * (p.id() + 1)); }).makespan);
}

TEST(Backend, UnknownBackendIsRefusedNamingTheKnownOnes) {
  parix::RunOptions o;
  o.backend = "carrier-pigeon";
  o.simulation.config = machine::published_machine_config();
  try {
    parix::run(o, [](parix::Processor&) {});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("simulated"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("carrier-pigeon"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace gcsim::pipeline
