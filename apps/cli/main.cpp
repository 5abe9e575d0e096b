// gcsim: simulate the Parsytec GC-PowerPlus and run parallel graphics applications on it.
#include "apps/cli/cli_app.hpp"

int main(int argc, char** argv) { return gcsim::cli::run_gcsim(argc, argv); }
