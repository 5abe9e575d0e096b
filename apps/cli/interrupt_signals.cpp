#include "apps/cli/interrupt_signals.hpp"

#include <csignal>

#include "parix/host/interruption.hpp"

namespace gcsim::cli {

namespace {

extern "C" void on_interrupt(int) { parix::host::request_interruption(); }

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND | SA_RESTART;  // once only: the next signal has its default effect
  for (int sig : {SIGINT, SIGTERM}) sigaction(sig, &action, nullptr);
}

}  // namespace gcsim::cli
