#pragma once
// The HDF5 result file of one job, owned by rank 0. Readers never see it being written: blocks go into a
// working copy (R.h5.writing) and publish() copies that to R.h5.tmp and renames it over R.h5, so at every
// instant R.h5 is a complete, consistent file that h5dump, h5py and `pbrfit status` open with their
// defaults, and a kill during a write can damage only the working copy (which a resume rebuilds).
// complete() renames the working copy into place without a copy.
//
// Root attributes: pbrfit_version, job_name, job_kind, job_yaml, seed, ranks, threads, state
// (running | complete | interrupted | failed), started_utc, finished_utc, items_done, items_total,
// elapsed_seconds, headline, updated_utc, writer_host, writer_pid, scheduler_job.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "pbrfit/store/result_layout.hpp"

namespace pbrfit::store {

// Where a job stands, as the result file's `state` attribute says it (the names are what is written).
enum class RunStatus { running, complete, interrupted, failed };
std::string run_status_name(RunStatus status);
// Reads a `state` attribute back; throws InputError naming `path` for any other text.
RunStatus parse_run_status(const std::string& path, const std::string& text);

struct RunInfo {
  std::string job_name;
  std::string job_kind;
  std::string job_yaml;
  std::uint64_t seed = 0;
  int ranks = 1;
  int threads = 1;            // compute threads per rank
  std::string started_utc;
  std::string scheduler_job;  // e.g. "slurm job 1234, restart 1"; empty outside a batch system
};

struct Progress {
  RunStatus state = RunStatus::running;
  std::uint64_t items_done = 0;
  std::uint64_t items_total = 0;
  double elapsed_seconds = 0.0;
  std::string headline;
  std::string finished_utc;  // empty while running
};

class ResultFile {
 public:
  // Creates (truncating) the working copy with every group, axis and (empty, extendible) table of the
  // layout. R.h5 itself is untouched until the first publish().
  ResultFile(std::string path, ResultLayout layout, const RunInfo& info);

  // Writes the blocks (every table opened once, touching blocks merged) and the progress attributes
  // into the working copy; throws RunError on I/O failure. Blocks of growing tables carry their rows.
  void write(std::vector<Block> blocks, const Progress& progress);
  // Makes the working copy what readers of R.h5 see. Throws RunError (R.h5 keeps its previous content).
  void publish();
  // The last write becomes R.h5 for good: fsynced, renamed into place, the directory synced.
  void complete();

  const std::string& path() const { return path_; }
  const std::string& working_path() const { return working_; }
  const ResultLayout& layout() const { return layout_; }

 private:
  std::string path_;
  std::string working_;
  ResultLayout layout_;
};

// What `status` and the overwrite check read back; throws InputError if the file is not a pbrfit result.
struct ResultSummary {
  std::string pbrfit_version, job_name, job_kind, job_yaml, started_utc, finished_utc;
  RunStatus state = RunStatus::running;
  std::string headline, updated_utc, writer_host, scheduler_job;
  std::uint64_t seed = 0, items_done = 0, items_total = 0;
  std::int64_t ranks = 0, threads = 0, writer_pid = 0;
  double elapsed_seconds = 0.0;
};
ResultSummary read_result_summary(const std::string& path);

// Reads one whole numeric table, converted to double, as a flat row-major array with its dimensions.
std::vector<double> read_table(const std::string& path, const std::string& dataset,
                               std::vector<std::uint64_t>* dims = nullptr);
// Reads one whole table of texts.
std::vector<std::string> read_text_table(const std::string& path, const std::string& dataset);
// A string attribute of a group or dataset ("" names the root); throws RunError when it is missing.
std::string read_text_attribute(const std::string& path, const std::string& object, const std::string& name);
// A string attribute holding a comma-separated list of names ("axes", "inputs": "x, y"), split, with the
// spaces around each name trimmed and empty names dropped; throws RunError when it is missing.
std::vector<std::string> read_name_list_attribute(const std::string& path, const std::string& object,
                                                  const std::string& name);
// The names of the groups directly inside a group ("" names the root), in name order; throws RunError when
// the group is missing.
std::vector<std::string> read_group_names(const std::string& path, const std::string& group);
// The names of the datasets directly inside a group, in name order; throws RunError when it is missing.
std::vector<std::string> read_dataset_names(const std::string& path, const std::string& group);

std::string utc_now_iso8601();
// This machine's name, as recorded in writer_host.
std::string host_name();

}  // namespace pbrfit::store
