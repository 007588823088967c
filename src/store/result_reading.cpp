#include <unistd.h>

#include <algorithm>
#include <numeric>

#include "hdf5_handle.hpp"
#include "posix_file.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/store/result_file.hpp"

namespace pbrfit::store {

using h5::check;
using h5::Handle;

namespace {

ResultSummary read_summary_attributes(const std::string& path, hid_t file) {
  ResultSummary s;
  s.pbrfit_version = h5::read_string_attribute(file, "pbrfit_version");
  s.job_name = h5::read_string_attribute(file, "job_name");
  s.job_kind = h5::read_string_attribute(file, "job_kind");
  s.job_yaml = h5::read_string_attribute(file, "job_yaml");
  s.state = parse_run_status(path, h5::read_string_attribute(file, "state"));
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
  s.threads = h5::has_attribute(file, "threads") ? h5::read_i64_attribute(file, "threads") : 1;
  s.writer_pid = h5::read_i64_attribute(file, "writer_pid");
  s.elapsed_seconds = h5::read_f64_attribute(file, "elapsed_seconds");
  return s;
}

Handle open_dataset(const std::string& path, const std::string& dataset, Handle& file) {
  file = h5::open_file(path, false);
  return h5::open_dataset(file, dataset);
}

hsize_t element_count(const std::vector<hsize_t>& dims) {
  return std::accumulate(dims.begin(), dims.end(), hsize_t{1}, std::multiplies<>());
}

}  // namespace

ResultSummary read_result_summary(const std::string& path) {
  PosixFile::open_for_reading(path);  // a missing, unreadable or special file is refused before HDF5 opens it
  Handle file;
  try {
    file = h5::open_file(path, false);
  } catch (const RunError&) {
    throw InputError({path}, "not a readable HDF5 file (damaged, or not a pbrfit result)");
  }
  if (!h5::has_attribute(file, "pbrfit_version") || !h5::has_attribute(file, "job_yaml"))
    throw InputError({path}, "not a pbrfit result file (no pbrfit_version or job_yaml attribute)");
  try {
    return read_summary_attributes(path, file);
  } catch (const RunError& e) {
    throw InputError({path}, std::string("incomplete pbrfit result file: ") + e.what());
  }
}

std::vector<double> read_table(const std::string& path, const std::string& dataset, std::vector<std::uint64_t>* dims_out) {
  Handle file;
  Handle data = open_dataset(path, dataset, file);
  const auto dims = h5::dimensions(data, dataset);
  std::vector<double> values(element_count(dims));
  if (!values.empty())
    check(H5Dread(data, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "read " + dataset);
  if (dims_out) dims_out->assign(dims.begin(), dims.end());
  return values;
}

std::vector<std::string> read_text_table(const std::string& path, const std::string& dataset) {
  Handle file;
  Handle data = open_dataset(path, dataset, file);
  std::vector<char*> texts(element_count(h5::dimensions(data, dataset)), nullptr);
  if (texts.empty()) return {};
  Handle type = h5::string_type();
  check(H5Dread(data, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, texts.data()), "read " + dataset);
  std::vector<std::string> out;
  for (char* t : texts) {
    out.emplace_back(t ? t : "");
    H5free_memory(t);
  }
  return out;
}

std::string read_text_attribute(const std::string& path, const std::string& object, const std::string& name) {
  Handle file = h5::open_file(path, false);
  const std::string where = object.empty() ? "/" : object;
  Handle target(check(H5Oopen(file, where.c_str(), H5P_DEFAULT), "open " + where), H5Oclose);
  return h5::read_string_attribute(target, name);
}

std::vector<std::string> read_name_list_attribute(const std::string& path, const std::string& object,
                                                  const std::string& name) {
  const std::string text = read_text_attribute(path, object, name);
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto first = item.find_first_not_of(' '), last = item.find_last_not_of(' ');
    if (first != std::string::npos) names.push_back(item.substr(first, last - first + 1));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return names;
}

namespace {

herr_t collect_name(hid_t, const char* name, const H5L_info_t*, void* names) {
  static_cast<std::vector<std::string>*>(names)->emplace_back(name);
  return 0;
}

// The group's members of one type, in name order. Listed in one pass in the storage's native order and
// sorted here (strcmp's order, as HDF5's increasing name index): asking HDF5 for names in increasing order
// makes it build and free a table of decoded links, where HDF5 1.10.8 frees pointers read from a damaged
// file (the SEGV of tests/fuzz/regressions/result_file/hdf5-dense-link-table-free.h5).
std::vector<std::string> member_names(const std::string& path, const std::string& group, H5I_type_t type) {
  Handle file = h5::open_file(path, false);
  const std::string where = group.empty() ? "/" : group;
  Handle parent(check(H5Gopen2(file, where.c_str(), H5P_DEFAULT), "open group " + where), H5Gclose);
  std::vector<std::string> links;
  check(H5Literate(parent, H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, collect_name, &links), "list group " + where);
  std::sort(links.begin(), links.end());
  std::vector<std::string> names;
  for (const auto& name : links) {
    Handle child(check(H5Oopen(parent, name.c_str(), H5P_DEFAULT), "open " + name), H5Oclose);
    if (H5Iget_type(child) == type) names.push_back(name);
  }
  return names;
}

}  // namespace

std::vector<std::string> read_group_names(const std::string& path, const std::string& group) {
  return member_names(path, group, H5I_GROUP);
}

std::vector<std::string> read_dataset_names(const std::string& path, const std::string& group) {
  return member_names(path, group, H5I_DATASET);
}

}  // namespace pbrfit::store
