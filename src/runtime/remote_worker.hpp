#pragma once
#include "pbrfit/runtime/mpi_session.hpp"
#include "pbrfit/runtime/workload.hpp"

namespace pbrfit::runtime {

// The life of every rank but 0: relay stage contexts down the tree, compute assigned items on `threads`
// threads and send their results, until rank 0 says stop; then report what finished, say bye and wait
// for rank 0's farewell. Returns the exit code rank 0 sent. On a signal the rank tells rank 0 and starts
// nothing new; a failing item is reported, never thrown.
int serve_as_worker(const MpiSession& mpi, const Workload& workload, std::uint64_t seed, int threads);

}  // namespace pbrfit::runtime
