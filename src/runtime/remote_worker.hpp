#pragma once
#include "pbrfit/runtime/workload.hpp"

namespace pbrfit::runtime {

// The loop of every rank but 0: compute assigned items until told to stop. Between items it reports
// its own stop signal and stops starting new items; a failing item is reported, never thrown.
void serve_as_worker(const Workload& workload);

}  // namespace pbrfit::runtime
