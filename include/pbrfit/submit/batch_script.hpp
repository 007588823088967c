#pragma once
// Slurm batch scripts for pbrfit jobs, rendered from a template (cluster/sbatch.template) whose
// {{placeholders}} are filled with values that are either validated to a safe character set or
// single-quoted for the shell: a job file can never inject a command into the script.
#include <map>
#include <string>

#include "pbrfit/spec/job_spec.hpp"

namespace pbrfit::submit {

// Command-line overrides of the job's `resources`; empty / 0 keeps the job's value.
struct ResourceOverrides {
  int ranks = 0;
  int threads = 0;
  std::string time_limit;
  std::string partition;
  std::string account;
};

struct BatchJob {
  std::string name;
  int ranks = 1;
  int threads = 1;              // CPUs per task
  std::string time_limit;       // Slurm format
  double time_limit_seconds = 0;
  int warning_seconds = 60;     // SIGUSR1 this long before the time limit
  std::string partition, account;
  std::string job_file;         // absolute
  std::string output;           // absolute result path
  std::string log;              // absolute Slurm log path (%j: job id)
  std::string script;           // absolute path the script is written to
  std::string workdir;          // absolute
  std::string pbrfit;           // absolute path of the pbrfit binary
  std::string launcher = "srun --mpi=pmix";
};

// Resolves paths and overrides; throws InputError for values that cannot go into a batch script.
BatchJob batch_job_for(const spec::JobSpec& job, const ResourceOverrides& overrides, const std::string& pbrfit,
                       const std::string& workdir);

// Fills {{key}} placeholders; an unknown placeholder or a missing value throws InputError naming the template.
std::string render_template(const std::string& text, const std::map<std::string, std::string>& values,
                            const std::string& template_path);

std::string render_batch_script(const BatchJob& job, const std::string& template_text,
                                const std::string& template_path);

// 'text' quoted for POSIX shells.
std::string shell_quote(const std::string& text);

}  // namespace pbrfit::submit
