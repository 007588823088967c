#pragma once
// How many compute threads each rank runs: --threads when given; else the CPUs Slurm gives each task
// (SLURM_CPUS_PER_TASK); else this machine's hardware threads shared evenly among the ranks on it, but
// never more than the CPUs this process may run on (mpirun binds each rank to one core unless told
// otherwise, e.g. `--bind-to none` or `--map-by slot:PE=N`). Always at least 1.
namespace pbrfit::runtime {

int compute_threads(int requested, int ranks_on_this_node);

// The CPUs this process may run on (its affinity mask).
int usable_cpus();

}  // namespace pbrfit::runtime
