#pragma once
// SIGINT and SIGTERM ask the running simulation to stop (parix/host/interruption.hpp): the command
// then writes what it finished and exits with kExitInterrupted. The handler restores the default
// action, so a second signal ends the process at once.
namespace gcsim::cli {

void install_interrupt_handlers();

}  // namespace gcsim::cli
