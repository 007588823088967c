#include "pbrfit/store/result_file.hpp"

#include <hdf5_hl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <numeric>

#include "hdf5_handle.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/core/version.hpp"

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

std::string host_name() {
  char buffer[256] = {};
  gethostname(buffer, sizeof buffer - 1);
  return buffer;
}

namespace {

Handle create_axis(hid_t group, const Axis& axis) {
  const hsize_t n = axis.values.size();
  Handle space(check(H5Screate_simple(1, &n, nullptr), "create axis space"), H5Sclose);
  Handle data(check(H5Dcreate2(group, axis.name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT,
                               H5P_DEFAULT),
                    "create axis " + axis.name),
              H5Dclose);
  check(H5Dwrite(data, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, axis.values.data()),
        "write axis " + axis.name);
  check(H5DSset_scale(data, axis.name.c_str()), "make " + axis.name + " a dimension scale");
  h5::write_string_attribute(data, "description", axis.description);
  return data;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// The first dimension starts empty and grows as rows arrive; missing values read as NaN. Every
// dimension carries its axis as a dimension scale and its name as a label.
void create_table(hid_t group, const Group& layout, const Table& table) {
  const std::size_t rank = table.axes.size();
  std::vector<hsize_t> dims(rank), max_dims(rank), chunk(rank);
  hsize_t row_size = 1;
  for (std::size_t d = 0; d < rank; ++d) {
    dims[d] = max_dims[d] = chunk[d] = layout.axis(table.axes[d]).values.size();
    if (d > 0) row_size *= dims[d];
  }
  dims[0] = 0;
  max_dims[0] = H5S_UNLIMITED;
  chunk[0] = std::clamp<hsize_t>(16384 / std::max<hsize_t>(row_size, 1), 1, std::max<hsize_t>(chunk[0], 1));
  Handle space(check(H5Screate_simple(int(rank), dims.data(), max_dims.data()), "create table space"), H5Sclose);
  Handle dcpl(check(H5Pcreate(H5P_DATASET_CREATE), "create dataset properties"), H5Pclose);
  check(H5Pset_chunk(dcpl, int(rank), chunk.data()), "set chunking");
  const double fill = std::numeric_limits<double>::quiet_NaN();
  check(H5Pset_fill_value(dcpl, H5T_NATIVE_DOUBLE, &fill), "set fill value");
  Handle data(check(H5Dcreate2(group, table.name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
                    "create table " + table.name),
              H5Dclose);
  for (std::size_t d = 0; d < rank; ++d) {
    Handle axis(check(H5Dopen2(group, table.axes[d].c_str(), H5P_DEFAULT), "open axis " + table.axes[d]), H5Dclose);
    check(H5DSattach_scale(data, axis, unsigned(d)), "attach axis " + table.axes[d]);
    check(H5DSset_label(data, unsigned(d), table.axes[d].c_str()), "label dimension " + table.axes[d]);
  }
  h5::write_string_attribute(data, "description", table.description);
  h5::write_string_attribute(data, "axes", joined(table.axes));
}

void create_group(hid_t file, const Group& layout) {
  Handle group(check(H5Gcreate2(file, layout.name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                     "create group " + layout.name),
               H5Gclose);
  h5::write_string_attribute(group, "description", layout.description);
  for (const auto& [key, value] : layout.attributes) h5::write_string_attribute(group, key, value);
  for (const auto& axis : layout.axes) create_axis(group, axis);
  for (const auto& table : layout.tables) create_table(group, layout, table);
}

void write_block(hid_t file, const Block& block) {
  const std::string path = block.group + "/" + block.table;
  Handle data(check(H5Dopen2(file, path.c_str(), H5P_DEFAULT), "open table " + path), H5Dclose);
  Handle space(check(H5Dget_space(data), "read extent of " + path), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank != int(block.offset.size()) || rank != int(block.count.size()))
    throw RunError("block for " + path + " has the wrong number of dimensions");
  std::vector<hsize_t> dims(rank);
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  const std::vector<hsize_t> offset(block.offset.begin(), block.offset.end());
  const std::vector<hsize_t> count(block.count.begin(), block.count.end());
  if (offset[0] + count[0] > dims[0]) {
    dims[0] = offset[0] + count[0];
    check(H5Dset_extent(data, dims.data()), "extend " + path);
    space = Handle(check(H5Dget_space(data), "read extent of " + path), H5Sclose);
  }
  check(H5Sselect_hyperslab(space, H5S_SELECT_SET, offset.data(), nullptr, count.data(), nullptr),
        "select block of " + path);
  Handle memory(check(H5Screate_simple(rank, count.data(), nullptr), "create block space"), H5Sclose);
  check(H5Dwrite(data, H5T_NATIVE_DOUBLE, memory, space, H5P_DEFAULT, block.values.data()), "write " + path);
}

void write_progress(hid_t file, const Progress& progress) {
  h5::write_string_attribute(file, "state", progress.state);
  h5::write_u64_attribute(file, "items_done", progress.items_done);
  h5::write_u64_attribute(file, "items_total", progress.items_total);
  h5::write_f64_attribute(file, "elapsed_seconds", progress.elapsed_seconds);
  h5::write_string_attribute(file, "headline", progress.headline);
  h5::write_string_attribute(file, "finished_utc", progress.finished_utc);
  h5::write_string_attribute(file, "updated_utc", utc_now_iso8601());
}

}  // namespace

ResultFile::ResultFile(std::string path, ResultLayout layout, const RunInfo& info)
    : path_(std::move(path)), layout_(std::move(layout)) {
  h5::silence_error_stack();
  Handle fapl = h5::file_access();
  check(H5Pset_libver_bounds(fapl, H5F_LIBVER_V110, H5F_LIBVER_LATEST), "set file format");
  Handle file(check(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), "create " + path_), H5Fclose);
  h5::write_string_attribute(file, "pbrfit_version", version);
  h5::write_string_attribute(file, "job_name", info.job_name);
  h5::write_string_attribute(file, "job_kind", info.job_kind);
  h5::write_string_attribute(file, "job_yaml", info.job_yaml);
  h5::write_u64_attribute(file, "seed", info.seed);
  h5::write_i64_attribute(file, "ranks", info.ranks);
  h5::write_string_attribute(file, "started_utc", info.started_utc);
  h5::write_string_attribute(file, "writer_host", host_name());
  h5::write_i64_attribute(file, "writer_pid", getpid());
  h5::write_string_attribute(file, "scheduler_job", info.scheduler_job);
  write_progress(file, Progress{});
  for (const auto& group : layout_.groups) create_group(file, group);
}

void ResultFile::add(std::vector<Block> blocks) {
  for (auto& b : blocks) pending_.push_back(std::move(b));
}

void ResultFile::flush(const Progress& progress) {
  Handle file = h5::open_file(path_, true);
  for (const auto& block : pending_) write_block(file, block);
  write_progress(file, progress);
  check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush " + path_);
  file.reset();
  pending_.clear();
}

ResultSummary read_result_summary(const std::string& path) {
  if (access(path.c_str(), R_OK) != 0) throw InputError({path}, "cannot read result file: no such file or no permission");
  Handle file;
  try {
    file = h5::open_file(path, false);
  } catch (const RunError&) {
    throw InputError({path}, "not a readable HDF5 file (damaged, or not a pbrfit result)");
  }
  if (!h5::has_attribute(file, "pbrfit_version") || !h5::has_attribute(file, "job_yaml"))
    throw InputError({path}, "not a pbrfit result file (no pbrfit_version or job_yaml attribute)");
  try {
    ResultSummary s;
    s.pbrfit_version = h5::read_string_attribute(file, "pbrfit_version");
    s.job_name = h5::read_string_attribute(file, "job_name");
    s.job_kind = h5::read_string_attribute(file, "job_kind");
    s.job_yaml = h5::read_string_attribute(file, "job_yaml");
    s.state = h5::read_string_attribute(file, "state");
    s.started_utc = h5::read_string_attribute(file, "started_utc");
    s.finished_utc = h5::read_string_attribute(file, "finished_utc");
    s.headline = h5::read_string_attribute(file, "headline");
    s.updated_utc = h5::read_string_attribute(file, "updated_utc");
    s.writer_host = h5::read_string_attribute(file, "writer_host");
    s.scheduler_job = h5::read_string_attribute(file, "scheduler_job");
    s.seed = std::uint64_t(h5::read_i64_attribute(file, "seed"));
    s.items_done = std::uint64_t(h5::read_i64_attribute(file, "items_done"));
    s.items_total = std::uint64_t(h5::read_i64_attribute(file, "items_total"));
    s.ranks = h5::read_i64_attribute(file, "ranks");
    s.writer_pid = h5::read_i64_attribute(file, "writer_pid");
    s.elapsed_seconds = h5::read_f64_attribute(file, "elapsed_seconds");
    return s;
  } catch (const RunError& e) {
    throw InputError({path}, std::string("incomplete pbrfit result file: ") + e.what());
  }
}

std::vector<double> read_table(const std::string& path, const std::string& dataset,
                               std::vector<std::uint64_t>* dims_out) {
  Handle file = h5::open_file(path, false);
  Handle data(check(H5Dopen2(file, dataset.c_str(), H5P_DEFAULT), "open " + dataset), H5Dclose);
  Handle space(check(H5Dget_space(data), "read extent of " + dataset), H5Sclose);
  std::vector<hsize_t> dims(H5Sget_simple_extent_ndims(space));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  const auto n = std::accumulate(dims.begin(), dims.end(), hsize_t{1}, std::multiplies<>());
  std::vector<double> values(n);
  if (n > 0) check(H5Dread(data, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "read " + dataset);
  if (dims_out) dims_out->assign(dims.begin(), dims.end());
  return values;
}

}  // namespace pbrfit::store
