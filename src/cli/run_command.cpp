#include <spdlog/spdlog.h>

#include <cstdio>

#include "exit_on_error.hpp"
#include "pbrfit/cli/commands.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/core/quoted_text.hpp"
#include "pbrfit/jobs/job_kinds.hpp"
#include "pbrfit/runtime/compute_threads.hpp"
#include "pbrfit/runtime/job_runner.hpp"
#include "pbrfit/runtime/mpi_session.hpp"

namespace pbrfit::cli {

namespace {

runtime::RunSettings settings_for(const spec::JobSpec& job, const RunOptions& options, int ranks_on_node) {
  runtime::RunSettings s;
  s.threads = runtime::compute_threads(options.threads, ranks_on_node);
  s.rank_timeout_seconds = options.rank_timeout;
  s.job_text = job.text;
  s.job_name = job.name;
  s.job_kind = job.kind;
  s.seed = job.seed;
  s.output = options.output.empty() ? job.output : options.output;
  s.checkpoint_interval_seconds = job.checkpoint.interval_seconds;
  s.checkpoint_interval_items = job.checkpoint.interval_items;
  s.resume = options.resume;
  s.force = options.force;
  return s;
}

// Ranks on nodes of different CPU generations use the best kernel set all of them have, so that no result
// depends on the rank that computed it (core/kernel_set.hpp). The sets nest: the least is available on all.
KernelSet agree_on_kernel_set(const runtime::MpiSession& mpi) {
  const auto agreed = static_cast<KernelSet>(mpi.minimum_over_ranks(static_cast<int>(active_kernel_set())));
  if (agreed != active_kernel_set())
    spdlog::info("rank {} uses the {} kernels, the best every rank has, instead of its own {}", mpi.rank(),
                 kernel_set_name(agreed), kernel_set_name(active_kernel_set()));
  use_kernel_set(agreed);
  return agreed;
}

int run_validated(const spec::JobSpec& job, const runtime::Workload& workload, const RunOptions& options) {
  runtime::MpiSession mpi;
  runtime::setup_logging(mpi.rank(), options.verbosity);
  const KernelSet kernels = agree_on_kernel_set(mpi);
  const auto settings = settings_for(job, options, mpi.ranks_on_this_node());
  if (settings.threads > runtime::usable_cpus())
    spdlog::warn("{} compute threads share {} CPU{} on rank {} (mpirun binds each rank to one core unless run with "
                 "--bind-to none or --map-by slot:PE={})",
                 settings.threads, runtime::usable_cpus(), runtime::usable_cpus() == 1 ? "" : "s", mpi.rank(),
                 settings.threads);
  if (mpi.coordinator())
    spdlog::info("job '{}' ({}) on {} rank{} x {} thread{}, {} kernels: {} work items -> {}", job.name, job.kind,
                 mpi.size(), mpi.size() == 1 ? "" : "s", settings.threads, settings.threads == 1 ? "" : "s",
                 kernel_set_name(kernels), workload.total_items(), settings.output);
  return runtime::run_workload(mpi, workload, settings);
}

void check_output_option(const std::string& output) {
  if (output.empty()) return;
  if (has_control_character(output))
    throw InputError({"--output"}, "must not contain control characters (such as NUL or a newline), got " + quote(output));
  if (!output.ends_with(".h5")) throw InputError({"--output"}, "must end in .h5, got " + quote(output));
}

}  // namespace

int run_command(const RunOptions& options) {
  // Every rank validates the same file; only the one that will be rank 0 reports a rejection.
  const bool reporter = runtime::launcher_rank() == 0;
  return exit_on_error(
      [&] {
        check_output_option(options.output);
        const auto job = spec::load_job_file(options.job_file, jobs::kind_catalogue());
        const auto workload = jobs::make_workload(job);
        return run_validated(job, *workload, options);
      },
      reporter);
}

}  // namespace pbrfit::cli
