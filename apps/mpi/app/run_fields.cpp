#include "apps/mpi/app/run_fields.hpp"

#include "apps/pipeline/run_provenance.hpp"

namespace gcsim::mpi_layer::app {

nlohmann::json run_fields(const MpirunOptions& o, const std::string& machine_name) {
  std::string command = o.program;
  for (const std::string& a : o.args) command += " " + a;
  nlohmann::json j;
  j["app"] = "mpi";
  j["experiment"] = command;  // the report's heading: "gcsim run · mpi · ./jacobi 48 400 · 16 nodes"
  j["machine"] = machine_name;
  j["program"] = o.program;
  j["arguments"] = o.args;
  j["mpi_ranks"] = o.np;
  if (o.ranks_per_node > 1) j["ranks_per_node"] = o.ranks_per_node;  // one per node: the JSON as before
  j["mpi"] = {{"compute", o.compute}, {"collectives", o.collectives_spec.empty() ? "auto" : o.collectives_spec}};
  const std::vector<std::string> files = pipeline::trace_files(o.machine.trace);
  if (!files.empty()) j["trace_files"] = files;
  return j;
}

}  // namespace gcsim::mpi_layer::app
