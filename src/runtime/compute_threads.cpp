#include "pbrfit/runtime/compute_threads.hpp"

#include <sched.h>

#include <algorithm>
#include <cstdlib>
#include <thread>

namespace pbrfit::runtime {

int usable_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return int(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, CPU_COUNT(&set));
}

int compute_threads(int requested, int ranks_on_this_node) {
  if (requested > 0) return requested;
  if (const char* slurm = std::getenv("SLURM_CPUS_PER_TASK")) {
    const int cpus = std::atoi(slurm);
    if (cpus > 0) return cpus;
  }
  const int hardware = int(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, std::min(usable_cpus(), hardware / std::max(1, ranks_on_this_node)));
}

}  // namespace pbrfit::runtime
