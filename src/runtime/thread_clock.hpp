#pragma once
// The processor time the calling thread has used, in seconds: what the coordinating cost rank 0's main
// thread, however many other processes share its core (wall time would count their turns too). A system
// call, not a vDSO read: for once-a-run use. Measured for the log and the cluster model only; no result
// depends on it. Private to the runtime.
#include <time.h>

namespace pbrfit::runtime {

inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace pbrfit::runtime
