#pragma once
// How a run's processors spent its time, as the run summary line says it: busy, communicating and
// waiting (docs/run-records.md), means per processor.
#include <string>

#include "parix/run_result.hpp"

namespace gcsim::pipeline {

// "busy 5.21 s, communicating 1.02 s, waiting 0.30 s: means per processor", and, when those add up
// to more than the run's time, why: a processor's spawned threads are counted with it.
std::string time_split(const parix::RunResult& r);

}  // namespace gcsim::pipeline
