#pragma once
// Running the synthetic chain workload in this process (one rank) through the real runtime.
#include <filesystem>
#include <string>

#include "chain_workload.hpp"
#include "pbrfit/runtime/job_runner.hpp"

namespace pbrfit::testing {

std::string scratch_path(const std::string& name);

struct ChainRun {
  ChainSettings chain;
  int threads = 1;
  bool resume = false;
  double checkpoint_seconds = 30;
};

// Runs to its end and returns the exit code; a stop signal raised by the run is forgotten afterwards.
int run_chain(const ChainRun& run, const std::string& output);

}  // namespace pbrfit::testing
