#pragma once
#include "pbrfit/runtime/job_runner.hpp"
#include "pbrfit/runtime/mpi_session.hpp"
#include "pbrfit/runtime/workload.hpp"

namespace pbrfit::runtime {

struct WorkerEnd {
  int exit_code = 0;
  bool coordinator_lost = false;  // rank 0 went silent: leave without MPI_Finalize
};

// The life of every rank but 0: relay stage contexts down the tree, compute assigned items on the
// settings' threads and send their results, until rank 0 says stop; then report what finishes within the
// stop grace, say bye and wait for rank 0's farewell. On a signal the rank tells rank 0 and starts nothing
// new; a failing item is reported, never thrown. If rank 0 is silent for rank_timeout_seconds the rank
// gives up with exit code 75.
WorkerEnd serve_as_worker(const MpiSession& mpi, const Workload& workload, const RunSettings& settings);

}  // namespace pbrfit::runtime
