#pragma once
// Runs one workload on every rank of the MPI job: rank 0 coordinates (hands out work items, owns the
// result file and the checkpoint) and computes on its compute threads; every other rank computes.
#include <cstdint>
#include <string>

#include "pbrfit/runtime/mpi_session.hpp"
#include "pbrfit/runtime/workload.hpp"

namespace pbrfit::runtime {

struct RunSettings {
  std::string job_text;
  std::string job_name;
  std::string job_kind;
  std::uint64_t seed = 0;
  std::string output;                      // result file; its checkpoint and block journal sit beside it
  int threads = 1;                         // compute threads on each rank (see compute_threads.hpp)
  double checkpoint_interval_seconds = 30; // 0: never by time
  std::int64_t checkpoint_interval_items = 0;  // 0: never by count
  bool resume = false;                     // continue from the checkpoint if there is one
  bool force = false;                      // overwrite a result or checkpoint of a different job text
  double flush_interval_seconds = 1.0;     // how often finished results reach the result file
  double progress_interval_seconds = 3.0;  // how often progress is logged
  double stop_grace_seconds = 5.0;         // how long rank 0 waits for the other ranks when stopping
  double rank_timeout_seconds = 60.0;      // a rank silent this long is taken for dead or hung
};

// Collective: every rank calls it and every rank that is still alive returns the same exit code
// (see core/error.hpp). After a rank was lost, the session is told to leave without MPI_Finalize.
int run_workload(MpiSession& mpi, const Workload& workload, const RunSettings& settings);

}  // namespace pbrfit::runtime
