#include "pbrfit/store/result_file.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <ctime>

#include "hdf5_handle.hpp"
#include "pbrfit/core/version.hpp"
#include "pbrfit/core/error.hpp"
#include "posix_file.hpp"
#include "table_creation.hpp"
#include "table_writer.hpp"

namespace pbrfit::store {

using h5::check;
using h5::Handle;

std::string utc_now_iso8601() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}

std::string run_status_name(RunStatus status) {
  switch (status) {
    case RunStatus::running: return "running";
    case RunStatus::complete: return "complete";
    case RunStatus::interrupted: return "interrupted";
    case RunStatus::failed: return "failed";
  }
  return "running";
}

RunStatus parse_run_status(const std::string& path, const std::string& text) {
  for (RunStatus s : {RunStatus::running, RunStatus::complete, RunStatus::interrupted, RunStatus::failed})
    if (text == run_status_name(s)) return s;
  throw InputError({path}, "state attribute '" + text + "' is none of running, complete, interrupted, failed");
}

std::string host_name() {
  char buffer[256] = {};
  gethostname(buffer, sizeof buffer - 1);
  return buffer;
}

namespace {

void write_progress(hid_t file, const Progress& progress) {
  h5::write_string_attribute(file, "state", run_status_name(progress.state));
  h5::write_u64_attribute(file, "items_done", progress.items_done);
  h5::write_u64_attribute(file, "items_total", progress.items_total);
  h5::write_f64_attribute(file, "elapsed_seconds", progress.elapsed_seconds);
  h5::write_string_attribute(file, "headline", progress.headline);
  h5::write_string_attribute(file, "finished_utc", progress.finished_utc);
  h5::write_string_attribute(file, "updated_utc", utc_now_iso8601());
}

void write_run_info(hid_t file, const RunInfo& info) {
  h5::write_string_attribute(file, "pbrfit_version", version);
  h5::write_string_attribute(file, "job_name", info.job_name);
  h5::write_string_attribute(file, "job_kind", info.job_kind);
  h5::write_string_attribute(file, "job_yaml", info.job_yaml);
  h5::write_u64_attribute(file, "seed", info.seed);
  h5::write_i64_attribute(file, "ranks", info.ranks);
  h5::write_i64_attribute(file, "threads", info.threads);
  h5::write_string_attribute(file, "started_utc", info.started_utc);
  h5::write_string_attribute(file, "writer_host", host_name());
  h5::write_i64_attribute(file, "writer_pid", getpid());
  h5::write_string_attribute(file, "scheduler_job", info.scheduler_job);
}

}  // namespace

ResultFile::ResultFile(std::string path, ResultLayout layout, const RunInfo& info)
    : path_(std::move(path)), working_(path_ + ".writing"), layout_(std::move(layout)) {
  h5::silence_error_stack();
  Handle fapl = h5::file_access();
  check(H5Pset_libver_bounds(fapl, H5F_LIBVER_V110, H5F_LIBVER_LATEST), "set file format");
  PosixFile::create(working_).close();  // reports a missing or read-only directory with the OS's reason
  Handle file(check(H5Fcreate(working_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), "create " + working_), h5::close_file_id);
  write_run_info(file, info);
  write_progress(file, Progress{});
  for (const auto& group : layout_.groups) create_group(file, group);
  h5::close_file(file);
}

void ResultFile::write(std::vector<Block> blocks, const Progress& progress) {
  Handle file = h5::open_file(working_, true);
  write_blocks(file, layout_, std::move(blocks));
  write_progress(file, progress);
  check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush " + working_);
  h5::close_file(file);
}

void ResultFile::publish() { copy_then_rename(working_, path_); }

void ResultFile::complete() {
  PosixFile file = PosixFile::open_for_writing(working_);
  file.sync();
  file.close();
  if (std::rename(working_.c_str(), path_.c_str()) != 0)
    throw RunError("cannot rename " + working_ + " to " + path_ + ": " + os_reason());
  sync_directory_of(path_);
}


}  // namespace pbrfit::store
