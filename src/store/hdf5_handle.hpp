#pragma once
// RAII ownership of HDF5 identifiers and small typed helpers for datasets and attributes. Private to the
// store.
#include <hdf5.h>

#include <cstdint>
#include <utility>
#include <string>
#include <vector>

namespace pbrfit::store::h5 {

// Owns one hid_t; closes it with the matching H5?close.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept : id_(other.id_), closer_(other.closer_) { other.id_ = H5I_INVALID_HID; }
  Handle& operator=(Handle&& other) noexcept;
  ~Handle() { reset(); }
  void reset();
  hid_t release() { return std::exchange(id_, H5I_INVALID_HID); }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  operator hid_t() const { return id_; }

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

// Each throws RunError naming `what` when HDF5 reports failure.
hid_t check(hid_t id, const std::string& what);
void check(herr_t status, const std::string& what);

// File access without HDF5's file locks: readers come and go while the writer appends.
Handle file_access();
// Opens an HDF5 file; for reading, only after check_global_heaps (global_heap_check.hpp) finds no
// collection HDF5 would loop on.
Handle open_file(const std::string& path, bool writable);

// Variable-length UTF-8 strings, in files and in memory (as char*).
Handle string_type();

void write_string_attribute(hid_t object, const std::string& name, const std::string& value);
void write_u64_attribute(hid_t object, const std::string& name, std::uint64_t value);
void write_i64_attribute(hid_t object, const std::string& name, std::int64_t value);
void write_f64_attribute(hid_t object, const std::string& name, double value);

// A dataset of an open file, and the extent of each of its dimensions (`what` names it in errors).
Handle open_dataset(hid_t file, const std::string& dataset);
std::vector<hsize_t> dimensions(hid_t dataset, const std::string& what);

bool has_attribute(hid_t object, const std::string& name);
std::string read_string_attribute(hid_t object, const std::string& name);
std::int64_t read_i64_attribute(hid_t object, const std::string& name);
double read_f64_attribute(hid_t object, const std::string& name);

// Closes a file, reporting failure (a close flushes; on a full disk it fails).
void close_file(Handle& file);
// The closer of every file handle; a file whose close failed is left alone, not retried at exit.
herr_t close_file_id(hid_t id);

// Silences HDF5's own error stack printing for this process (errors are reported as exceptions).
void silence_error_stack();

}  // namespace pbrfit::store::h5
