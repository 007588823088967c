#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "exit_on_error.hpp"
#include "pbrfit/cli/commands.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/core/kernel_set.hpp"
#include "pbrfit/core/quoted_text.hpp"
#include "pbrfit/core/version.hpp"
#include "pbrfit/runtime/mpi_session.hpp"

namespace pbrfit::cli {

namespace {

// PBRFIT_KERNELS=generic|avx2|avx512 chooses the kernel set instead of the machine's best
// (core/kernel_set.hpp): to compare sets, or to reproduce a result of another machine's set.
void use_kernels_from_environment() {
  const char* text = std::getenv("PBRFIT_KERNELS");
  if (!text || !*text) return;
  const auto set = parse_kernel_set(text);
  if (!set)
    throw InputError({"PBRFIT_KERNELS"}, "must be generic, avx2 or avx512, not " + quote(text));
  if (!kernel_set_available(*set))
    throw InputError({"PBRFIT_KERNELS"}, "this machine cannot run the " + std::string(text) +
                                             " kernels (it has " + available_kernel_sets() + ")");
  use_kernel_set(*set);
}

}  // namespace

int main_entry(int argc, char** argv) {
  if (const int code = exit_on_error([] { return use_kernels_from_environment(), 0; }, runtime::launcher_rank() == 0))
    return code;
  CLI::App app{"pbrfit: fits approximate models for physically based rendering, as MPI batch jobs"};
  app.set_version_flag("--version", std::string("pbrfit ") + version + " (commit " + build_commit + ")\nkernels: " +
                                        std::string(kernel_set_name(active_kernel_set())) + " (this machine has " +
                                        available_kernel_sets() + "; PBRFIT_KERNELS chooses)");
  app.require_subcommand(1);

  RunOptions run;
  bool quiet = false, verbose = false;
  auto* run_cmd = app.add_subcommand("run", "run a job on the ranks mpirun gives (one included)");
  run_cmd->add_option("job", run.job_file, "job file (YAML)")->required();
  run_cmd->add_option("-o,--output", run.output, "result file, instead of the job's output");
  run_cmd->add_flag("--resume", run.resume, "continue from the job's checkpoint, if there is one");
  run_cmd->add_flag("--force", run.force, "overwrite a result or checkpoint of a different job text");
  run_cmd->add_option("-t,--threads", run.threads,
                      "compute threads per rank (default: SLURM_CPUS_PER_TASK, else the machine's hardware threads "
                      "shared among the ranks on it)")
      ->check(CLI::Range(1, 4096));
  run_cmd->add_option("--rank-timeout", run.rank_timeout,
                      "seconds without a word from a rank (they send one every second) before it is taken for dead "
                      "or hung and the job stops with a checkpoint (default 60)")
      ->check(CLI::Range(2.0, 86400.0));
  auto* quiet_flag = run_cmd->add_flag("-q,--quiet", quiet, "log warnings and errors only");
  run_cmd->add_flag("-v,--verbose", verbose, "log details, from every rank")->excludes(quiet_flag);

  std::string validate_file;
  auto* validate_cmd = app.add_subcommand("validate", "check a job file without running it");
  validate_cmd->add_option("job", validate_file, "job file (YAML)")->required();

  std::string status_file;
  auto* status_cmd = app.add_subcommand("status", "state and progress of a result file, also while it runs");
  status_cmd->add_option("result", status_file, "result file (HDF5)")->required();

  ReportOptions report;
  auto* report_cmd = app.add_subcommand("report", "an HTML page of figures and tables of a result file, also while it runs");
  report_cmd->add_option("result", report.result_file, "result file (HDF5)")->required();
  report_cmd->add_option("-o,--out", report.out_dir, "directory for index.html and its figures (default: the result "
                         "path with .h5 replaced by .report)");
  report_cmd->add_option("--watch", report.watch_seconds,
                         "while the job runs, make the report again every SECONDS (the page reloads itself); "
                         "ends when the job stops")
      ->check(CLI::Range(1.0, 86400.0));

  ExportOptions export_options;
  auto* export_cmd = app.add_subcommand("export", "a table (lut, sweep, ebrdf) as a texture or source file an engine "
                                        "loads (docs/export.md), or a front member (symreg, brdf_search) as an HLSL, "
                                        "GLSL or C++ function on stdout");
  export_cmd->add_option("result", export_options.result_file, "result file (HDF5)")->required();
  export_cmd->add_option("--format", export_options.format, "a table: dds, ktx2, exr, hdr, png, npy, cpp, glsl, hlsl "
                         "or js; a front member: hlsl (default), glsl or cpp");
  export_cmd->add_option("--table", export_options.table, "the table (default: the result's main one: dfg, "
                         "disney_diffuse, ltc, specular); a wrong name lists those there are");
  export_cmd->add_option("--model", export_options.model, "a sweep's model (default: the only one)");
  export_cmd->add_option("-o,--out", export_options.out, "the file to write (default: RESULT.TABLE.EXT beside the result)");
  export_cmd->add_option("--precision", export_options.precision, "float (default) or half");
  export_cmd->add_option("--channels", export_options.channels, "channels by name, comma-separated, in R, G, B, A order");
  export_cmd->add_option("--u-axis", export_options.u_axis, "a 2D table's axis to run along u (x)");
  export_cmd->add_flag("--flip-v", export_options.flip_v, "write the rows last to first");
  export_cmd->add_option("--prefix", export_options.prefix, "cpp, glsl, hlsl, js: prefix of every generated symbol");
  export_cmd->add_option("--output", export_options.output, "front member: the output (group) whose front to read "
                         "(default: the only one)");
  export_cmd->add_option("--member", export_options.member, "front member: row of the front, from 0, or 'test': the lowest test error (default: the knee)");
  export_cmd->add_option("--name", export_options.name, "front member: the function's name (default: the output's)");
  export_cmd->add_flag("--double", export_options.cpp_double, "front member, C++ only: double instead of float");

  SubmitOptions submit;
  auto* submit_cmd = app.add_subcommand("submit", "submit jobs to Slurm (requeueable, resumed after preemption)");
  submit_cmd->add_option("jobs", submit.job_files, "job files (YAML), one Slurm job each")->required();
  submit_cmd->add_flag("--dry-run", submit.dry_run, "print the batch script instead of submitting it");
  submit_cmd->add_option("--ranks", submit.ranks, "MPI ranks (Slurm tasks), instead of resources.ranks")
      ->check(CLI::Range(1, 65536));
  submit_cmd->add_option("--threads", submit.threads, "compute threads (CPUs) per rank, instead of resources.threads")
      ->check(CLI::Range(1, 1024));
  submit_cmd->add_option("--time", submit.time_limit, "time limit, instead of resources.time_limit");
  submit_cmd->add_option("--partition", submit.partition, "partition, instead of resources.partition");
  submit_cmd->add_option("--account", submit.account, "account, instead of resources.account");
  submit_cmd->add_option("--template", submit.template_file, "batch script template")->check(CLI::ExistingFile);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return exit_invalid_input;
  }
  run.verbosity = quiet ? runtime::Verbosity::quiet : verbose ? runtime::Verbosity::verbose : runtime::Verbosity::normal;
  if (*run_cmd) return run_command(run);
  if (*validate_cmd) return validate_command(validate_file);
  if (*submit_cmd) return submit_command(submit);
  if (*report_cmd) return report_command(report);
  if (*export_cmd) return export_command(export_options);
  return status_command(status_file);
}

}  // namespace pbrfit::cli
