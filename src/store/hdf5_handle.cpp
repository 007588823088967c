#include "hdf5_handle.hpp"

#include <cerrno>
#include <cstring>

#include "global_heap_check.hpp"
#include "pbrfit/core/error.hpp"

namespace pbrfit::store::h5 {

Handle& Handle::operator=(Handle&& other) noexcept {
  if (this != &other) {
    reset();
    id_ = other.id_;
    closer_ = other.closer_;
    other.id_ = H5I_INVALID_HID;
  }
  return *this;
}

void Handle::reset() {
  if (id_ >= 0 && closer_) closer_(id_);
  id_ = H5I_INVALID_HID;
}

namespace {

// HDF5 does not report the OS's reason; errno still holds it after a failed write or open. Only reasons
// that can come from the storage itself are named, so a stale errno is never blamed.
std::string storage_reason() {
  switch (errno) {
    case ENOSPC: case EDQUOT: case EIO: case EROFS: case EFBIG: case EACCES: return std::string(": ") + std::strerror(errno);
    default: return "";
  }
}

}  // namespace

hid_t check(hid_t id, const std::string& what) {
  if (id < 0) throw RunError("HDF5: cannot " + what + storage_reason());
  return id;
}

void check(herr_t status, const std::string& what) {
  if (status < 0) throw RunError("HDF5: cannot " + what + storage_reason());
}

namespace {

// HDF5 closes what is still open when the process exits, and crashes doing so for a file whose close
// already failed (a full disk). Every file is closed explicitly here, so the library is told not to
// clean up at exit; this runs before main, hence before any other HDF5 call, as H5dont_atexit needs.
const bool no_cleanup_at_exit = (H5dont_atexit(), true);

}  // namespace

herr_t close_file_id(hid_t id) {
  (void)no_cleanup_at_exit;
  // A failed close leaves a half-closed file in HDF5's table that crashes the library when touched
  // again (by H5Idec_ref or at exit), so it is never touched again.
  return H5Fclose(id);
}

void close_file(Handle& file) {
  if (close_file_id(file.release()) < 0) throw RunError("HDF5: cannot close (flush) the file");
}

void silence_error_stack() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

Handle file_access() {
  Handle fapl(check(H5Pcreate(H5P_FILE_ACCESS), "create file access list"), H5Pclose);
  check(H5Pset_file_locking(fapl, false, true), "disable file locking");
  return fapl;
}

Handle open_file(const std::string& path, bool writable) {
  silence_error_stack();
  if (!writable) check_global_heaps(path);  // a damaged file must not hang a reader
  Handle fapl = file_access();
  hid_t id = H5Fopen(path.c_str(), writable ? H5F_ACC_RDWR : H5F_ACC_RDONLY, fapl);
  check(id, "open " + path);
  return Handle(id, close_file_id);
}

namespace {

Handle scalar_space() { return Handle(check(H5Screate(H5S_SCALAR), "create dataspace"), H5Sclose); }

template <class T>
void write_scalar_attribute(hid_t object, const std::string& name, hid_t file_type, hid_t mem_type,
                            const T& value) {
  if (H5Aexists(object, name.c_str()) > 0) check(H5Adelete(object, name.c_str()), "replace attribute " + name);
  Handle space = scalar_space();
  Handle attr(check(H5Acreate2(object, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT),
                    "create attribute " + name),
              H5Aclose);
  check(H5Awrite(attr, mem_type, &value), "write attribute " + name);
}

Handle open_attribute(hid_t object, const std::string& name) {
  return Handle(check(H5Aopen(object, name.c_str(), H5P_DEFAULT), "read attribute " + name), H5Aclose);
}

}  // namespace

Handle string_type() {
  Handle type(check(H5Tcopy(H5T_C_S1), "copy string type"), H5Tclose);
  check(H5Tset_size(type, H5T_VARIABLE), "set string size");
  check(H5Tset_cset(type, H5T_CSET_UTF8), "set string charset");
  return type;
}

void write_string_attribute(hid_t object, const std::string& name, const std::string& value) {
  Handle type = string_type();
  const char* text = value.c_str();
  write_scalar_attribute(object, name, type, type, text);
}

void write_u64_attribute(hid_t object, const std::string& name, std::uint64_t value) {
  write_scalar_attribute(object, name, H5T_STD_U64LE, H5T_NATIVE_UINT64, value);
}

void write_i64_attribute(hid_t object, const std::string& name, std::int64_t value) {
  write_scalar_attribute(object, name, H5T_STD_I64LE, H5T_NATIVE_INT64, value);
}

void write_f64_attribute(hid_t object, const std::string& name, double value) {
  write_scalar_attribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, value);
}

Handle open_dataset(hid_t file, const std::string& dataset) {
  return Handle(check(H5Dopen2(file, dataset.c_str(), H5P_DEFAULT), "open " + dataset), H5Dclose);
}

std::vector<hsize_t> dimensions(hid_t dataset, const std::string& what) {
  Handle space(check(H5Dget_space(dataset), "read extent of " + what), H5Sclose);
  std::vector<hsize_t> dims(std::size_t(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  return dims;
}

bool has_attribute(hid_t object, const std::string& name) { return H5Aexists(object, name.c_str()) > 0; }

std::string read_string_attribute(hid_t object, const std::string& name) {
  Handle attr = open_attribute(object, name);
  Handle type(check(H5Aget_type(attr), "read type of " + name), H5Tclose);
  if (H5Tget_class(type) != H5T_STRING) throw RunError("HDF5: attribute " + name + " is not a string");
  if (H5Tis_variable_str(type) > 0) {
    Handle mem = string_type();
    char* text = nullptr;
    check(H5Aread(attr, mem, &text), "read attribute " + name);
    std::string value = text ? text : "";
    H5free_memory(text);
    return value;
  }
  std::vector<char> buffer(H5Tget_size(type) + 1, '\0');
  check(H5Aread(attr, type, buffer.data()), "read attribute " + name);
  return std::string(buffer.data());
}

std::int64_t read_i64_attribute(hid_t object, const std::string& name) {
  Handle attr = open_attribute(object, name);
  std::int64_t value = 0;
  check(H5Aread(attr, H5T_NATIVE_INT64, &value), "read attribute " + name);
  return value;
}

double read_f64_attribute(hid_t object, const std::string& name) {
  Handle attr = open_attribute(object, name);
  double value = 0;
  check(H5Aread(attr, H5T_NATIVE_DOUBLE, &value), "read attribute " + name);
  return value;
}

}  // namespace pbrfit::store::h5
