// gcsim calibrate, gcsim validate and gcsim accuracy network: fit a machine file to measured tables,
// predict the tables that played no part in the fit, and compare the network models. A command
// family registered from its own folder (apps/pipeline/app_registry.hpp), not an application; each
// command lives in its own file (commands.hpp), their shared prediction flags in prediction_flags.hpp.
#include "apps/calibration/app/commands.hpp"
#include "apps/pipeline/app_registry.hpp"

namespace gcsim::calibration::app {
namespace {

const pipeline::CommandFamilyRegistrar registrar{{.name = "calibration", .commands = [](pipeline::CommandGroups& g) {
                                                    add_calibrate_command(g);
                                                    add_validate_command(g);
                                                    add_network_accuracy_command(g);
                                                  }}};

}  // namespace
}  // namespace gcsim::calibration::app
