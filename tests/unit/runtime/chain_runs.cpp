#include "chain_runs.hpp"

#include "pbrfit/runtime/logging.hpp"
#include "pbrfit/runtime/mpi_session.hpp"
#include "pbrfit/runtime/stop_signal.hpp"

namespace pbrfit::testing {

namespace {

// MPI is initialized once per process: every test shares this singleton session.
runtime::MpiSession& session() {
  static runtime::MpiSession mpi;
  static const bool quiet = (runtime::setup_logging(0, runtime::Verbosity::quiet), true);
  (void)quiet;
  return mpi;
}

}  // namespace

std::string scratch_path(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "pbrfit-runtime-tests";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

int run_chain(const ChainRun& run, const std::string& output) {
  runtime::install_stop_handlers();
  const ChainWorkload workload(run.chain);
  runtime::RunSettings s;
  s.job_text = "chain test " + std::to_string(run.chain.stages) + "x" + std::to_string(run.chain.items);
  s.job_name = "chain";
  s.job_kind = "synthetic";
  s.seed = 11;
  s.output = output;
  s.threads = run.threads;
  s.resume = run.resume;
  s.checkpoint_interval_seconds = run.checkpoint_seconds;
  s.progress_interval_seconds = 1e9;
  const int code = runtime::run_workload(session(), workload, s);
  runtime::clear_stop_request();
  return code;
}

}  // namespace pbrfit::testing
