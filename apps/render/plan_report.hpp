#pragma once
// The plan as `gcsim plan` prints it: one block per pass (on or off, estimated time and memory per
// node, what it needs, the reason), and the same as JSON.
#include <string>

#include <nlohmann/json.hpp>

#include "apps/render/plan.hpp"
#include "apps/render/plan_cost.hpp"

namespace gcsim::render {

std::string format_plan(const Plan& plan, const machine::MachineConfig& machine, int nodes,
                        const CostModel& model = {});
nlohmann::json plan_json(const Plan& plan, const machine::MachineConfig& machine, int nodes,
                         const CostModel& model = {});

}  // namespace gcsim::render
