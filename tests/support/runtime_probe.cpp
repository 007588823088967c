// pbrfit_runtime_probe: runs the synthetic chain workload (chain_workload.hpp) through the real runtime,
// under mpirun like pbrfit itself, for the runtime's end-to-end tests and benchmarks.
//
//   pbrfit_runtime_probe OUTPUT [--stages S] [--items N] [--bytes B] [--spin US] [--threads T] [--resume]
//                        [--checkpoint-seconds X] [--signal SIG --at-stage S [--after K]] [--fail S:I] [-q]
#include <CLI/CLI.hpp>

#include <csignal>
#include <cstdio>

#include "chain_workload.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/runtime/compute_threads.hpp"
#include "pbrfit/runtime/job_runner.hpp"
#include "pbrfit/runtime/logging.hpp"
#include "pbrfit/runtime/stop_signal.hpp"

using namespace pbrfit;

int main(int argc, char** argv) {
  runtime::install_stop_handlers();
  testing::ChainSettings chain;
  runtime::RunSettings run;
  std::string fail;
  bool quiet = false;
  int threads = 0;
  CLI::App app{"runs the synthetic chain workload through the pbrfit runtime"};
  app.add_option("output", run.output)->required();
  app.add_option("--stages", chain.stages);
  app.add_option("--items", chain.items);
  app.add_option("--bytes", chain.result_bytes);
  app.add_option("--spin", chain.spin_microseconds);
  app.add_option("--threads", threads);
  app.add_flag("--resume", run.resume);
  app.add_option("--checkpoint-seconds", run.checkpoint_interval_seconds);
  app.add_option("--checkpoint-items", run.checkpoint_interval_items);
  app.add_option("--signal", chain.signal);
  app.add_option("--at-stage", chain.signal_stage);
  app.add_option("--after", chain.signal_after);
  app.add_option("--fail", fail, "STAGE:ITEM");
  app.add_flag("-q,--quiet", quiet);
  bool verbose = false, no_log = false;
  app.add_flag("-v,--verbose", verbose);
  app.add_flag("--no-log", no_log, "items append no rows to the growing table");
  app.add_option("--report-stages", chain.report_stages, "print rank 0's peak memory and file sizes as these stages start");
  CLI11_PARSE(app, argc, argv);
  if (!fail.empty()) {
    chain.fail_stage = std::uint32_t(std::stoul(fail.substr(0, fail.find(':'))));
    chain.fail_item = std::stoull(fail.substr(fail.find(':') + 1));
  }
  try {
    runtime::MpiSession mpi;
    runtime::setup_logging(mpi.rank(), quiet     ? runtime::Verbosity::quiet
                                       : verbose ? runtime::Verbosity::verbose
                                                 : runtime::Verbosity::normal);
    chain.output = run.output;
    chain.log_rows = !no_log;
    const testing::ChainWorkload workload(chain);
    run.threads = runtime::compute_threads(threads, mpi.ranks_on_this_node());
    run.job_text = "chain " + std::to_string(chain.stages) + "x" + std::to_string(chain.items) + " bytes " +
                   std::to_string(chain.result_bytes);
    run.job_name = "chain";
    run.job_kind = "synthetic";
    run.seed = 7;
    const int code = runtime::run_workload(mpi, workload, run);
    if (mpi.coordinator() && !chain.report_stages.empty())
      std::fprintf(stderr, "report: end peak_rss_kib %ld\n", testing::peak_rss_kib());
    return code;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pbrfit_runtime_probe: error: %s\n", e.what());
    return exit_run_failure;
  }
}
