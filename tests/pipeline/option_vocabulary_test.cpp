// The shared option vocabulary: help texts list every registered network model, topology and
// backend, and the checks refuse what the registries do not hold, so no command's help goes stale
// or accepts a value another command refuses.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "apps/pipeline/machine_options.hpp"
#include "apps/pipeline/option_vocabulary.hpp"
#include "machine/network_registry.hpp"
#include "machine/topology.hpp"
#include "parix/backend.hpp"

namespace gcsim::pipeline {
namespace {

// Parses args (without the program name) into app; the exception CLI11 throws, if any, propagates.
void parse(CLI::App& app, std::vector<std::string> args) {
  std::vector<const char*> argv{"gcsim"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  app.parse(int(argv.size()), argv.data());
}

std::string help_of(CLI::App& app, const std::string& option) { return app.get_option(option)->get_description(); }

TEST(OptionVocabulary, ModelHelpListsEveryRegisteredModelWithItsSummary) {
  CLI::App app;
  std::string model;
  add_model_option(&app, model, "Network model of the test", "the test's");
  const std::string help = help_of(app, "--model");
  ASSERT_FALSE(machine::network_models().empty());
  for (const machine::NetworkModelEntry& m : machine::network_models())
    EXPECT_NE(help.find(std::string(m.name) + ": " + std::string(m.summary)), std::string::npos) << help;
  EXPECT_EQ(help.rfind("Network model of the test: ", 0), 0u) << help;
  EXPECT_NE(help.find("default: the test's"), std::string::npos) << help;
}

TEST(OptionVocabulary, ModelAcceptsEveryRegisteredModelAndRefusesOthers) {
  for (const std::string& name : machine::network_model_names()) {
    CLI::App app;
    std::string model;
    add_model_option(&app, model);
    parse(app, {"--model", name});
    EXPECT_EQ(model, name);
  }
  CLI::App app;
  std::string model;
  add_model_option(&app, model);
  EXPECT_THROW(parse(app, {"--model", "bogus"}), CLI::ValidationError);
}

TEST(OptionVocabulary, MachineOptionsUseTheSharedModelAndBackendHelp) {
  CLI::App app;
  MachineOptions o;
  add_machine_options(&app, o, "4");
  const std::string model_help = help_of(app, "--model");
  for (const std::string& name : machine::network_model_names())
    EXPECT_NE(model_help.find(name + ": "), std::string::npos) << model_help;
  const std::string backend_help = help_of(app, "--backend");
  for (const parix::Backend& b : parix::backends()) EXPECT_NE(backend_help.find(std::string(b.name) + ": "), std::string::npos) << backend_help;
  EXPECT_NE(help_of(app, "--nodes").find("default: 4"), std::string::npos);
}

TEST(OptionVocabulary, NodesAreDecimalAndInRange) {
  auto nodes_of = [](const std::string& value) {
    CLI::App app;
    int nodes = 0;
    add_nodes_option(&app, nodes, "1", 64);
    parse(app, {"--nodes", value});
    return nodes;
  };
  EXPECT_EQ(nodes_of("8"), 8);
  EXPECT_EQ(nodes_of("010"), 10);  // CLI11 alone reads a leading 0 as octal: 8
  EXPECT_EQ(nodes_of("+16"), 16);
  for (const char* bad : {"0x10", "1e1", "8 nodes", "", "4.0"}) EXPECT_THROW(nodes_of(bad), CLI::ValidationError) << bad;
  for (const char* out_of_range : {"0", "65", "-1"}) EXPECT_THROW(nodes_of(out_of_range), CLI::ValidationError) << out_of_range;
}

TEST(OptionVocabulary, ModelListsTakeOnlyRegisteredModels) {
  std::string joined;
  for (const std::string& name : machine::network_model_names()) joined += (joined.empty() ? "" : ",") + name;
  auto check = [](std::string v) { return each_network_model()(v); };  // "" when valid
  EXPECT_EQ(check(joined), "");
  EXPECT_NE(check("bogus"), "");
  EXPECT_NE(check(joined + ",bogus"), "");
  EXPECT_NE(check("analytic,,flow"), "");
  EXPECT_NE(check("bogus").find(machine::network_model_list()), std::string::npos);
}

TEST(OptionVocabulary, TopologyChoicesNameEveryRegisteredTopology) {
  const std::string text = topology_choices();
  for (const std::string& name : machine::topology_names()) EXPECT_NE(text.find(name), std::string::npos) << text;
  EXPECT_EQ(or_list({"a", "b", "c"}), "a, b or c");
  EXPECT_EQ(and_list({"a", "b"}), "a and b");
  EXPECT_EQ(or_list({"a"}), "a");
}

TEST(OptionVocabulary, ConfigMustExistAndJsonSaysWhatItHolds) {
  CLI::App app;
  std::string config, json;
  add_config_option(&app, config, "Machine file for the test");
  add_json_option(&app, json, "the test's figures");
  EXPECT_NE(help_of(app, "--config").find("Machine file for the test; default: the built-in GC-PowerPlus"), std::string::npos);
  EXPECT_EQ(help_of(app, "--json"), "Write the test's figures as JSON");
  EXPECT_THROW(parse(app, {"--config", "no/such/machine.toml"}), CLI::ValidationError);
}

}  // namespace
}  // namespace gcsim::pipeline
