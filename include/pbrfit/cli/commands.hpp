#pragma once
// The pbrfit command line: run, validate, status, submit, report, export. Each returns the process exit code
// (core/error.hpp) and never lets an exception escape.
#include <string>
#include <vector>

#include "pbrfit/runtime/logging.hpp"

namespace pbrfit::cli {

struct RunOptions {
  std::string job_file;
  std::string output;  // overrides the job's output when set
  bool resume = false;
  bool force = false;
  int threads = 0;     // compute threads per rank; 0: see runtime/compute_threads.hpp
  double rank_timeout = 60.0;  // seconds of silence after which a rank is taken for dead or hung
  runtime::Verbosity verbosity = runtime::Verbosity::normal;
};

struct SubmitOptions {
  std::vector<std::string> job_files;
  bool dry_run = false;
  int ranks = 0;  // 0: the job's resources
  int threads = 0;  // 0: the job's resources
  std::string time_limit, partition, account;
  std::string template_file;  // empty: the installed cluster/sbatch.template
};

struct ReportOptions {
  std::string result_file;
  std::string out_dir;  // empty: the result path with .h5 replaced by .report
  double watch_seconds = 0.0;  // > 0: remade at this interval while the job runs
};

struct ExportOptions {
  std::string result_file;
  std::string format;                 // a front member: hlsl (default), glsl or cpp; a table: texture/format.hpp
  // A front member (symreg, brdf_search) as a function:
  std::string output;                 // empty: the only output
  std::string member;                 // row of the front, as written; empty: the knee
  std::string name;                   // empty: the output's name
  bool cpp_double = false;
  // A table (lut, sweep, ebrdf) as a texture or source file (jobs/table_export.hpp):
  std::string table, model;           // empty: the result's main table, its only model
  std::string out;                    // the file written; empty: RESULT.<model.>TABLE.<extension> beside it
  std::string precision = "float";    // float or half
  std::string channels;               // comma-separated channel names; empty: the table's defaults
  std::string u_axis;                 // the axis along u; empty: the table's default
  bool flip_v = false;
  std::string prefix;                 // source formats: the symbol prefix; empty: from the table's name
};

int run_command(const RunOptions& options);
int submit_command(const SubmitOptions& options);
int validate_command(const std::string& job_file);
int status_command(const std::string& result_file);
int report_command(const ReportOptions& options);
int export_command(const ExportOptions& options);

int main_entry(int argc, char** argv);

}  // namespace pbrfit::cli
