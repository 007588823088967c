// Reads one member of a compound dataset through a memory type holding that member alone (HDF5 matches
// compound members by name); the contract is in record_fields.hpp.
#include "pbrfit/store/record_fields.hpp"

#include "hdf5_handle.hpp"
#include "pbrfit/core/error.hpp"
#include "pbrfit/core/quoted_text.hpp"

namespace pbrfit::store {

using h5::check;
using h5::Handle;

namespace {

enum class FieldKind { number, text };

struct OpenField {
  Handle file;
  Handle data;
  std::size_t rows = 0;
};

bool has_kind(H5T_class_t type_class, FieldKind kind) {
  if (kind == FieldKind::text) return type_class == H5T_STRING;
  return type_class == H5T_INTEGER || type_class == H5T_FLOAT;
}

void check_field(hid_t data, const std::string& dataset, const std::string& field, FieldKind kind) {
  Handle type(check(H5Dget_type(data), "read the type of " + dataset), H5Tclose);
  if (H5Tget_class(type) != H5T_COMPOUND) throw RunError(quote(dataset) + " is not a record table");
  const int index = H5Tget_member_index(type, field.c_str());
  if (index < 0) throw RunError(quote(dataset) + " has no field " + quote(field));
  if (!has_kind(H5Tget_member_class(type, unsigned(index)), kind))
    throw RunError("field " + quote(field) + " of " + quote(dataset) + " is not " +
                   (kind == FieldKind::text ? "a text" : "a number"));
}

OpenField open_field(const std::string& path, const std::string& dataset, const std::string& field, FieldKind kind) {
  OpenField out;
  out.file = h5::open_file(path, false);
  out.data = h5::open_dataset(out.file, dataset);
  check_field(out.data, dataset, field, kind);
  out.rows = 1;
  for (hsize_t n : h5::dimensions(out.data, dataset)) out.rows *= std::size_t(n);
  return out;
}

// A record type holding only `field`, of the given memory type.
Handle single_field_type(const std::string& field, hid_t value_type) {
  Handle record(check(H5Tcreate(H5T_COMPOUND, H5Tget_size(value_type)), "create a record type"), H5Tclose);
  check(H5Tinsert(record, field.c_str(), 0, value_type), "add field " + field);
  return record;
}

}  // namespace

std::vector<double> read_number_field(const std::string& path, const std::string& dataset, const std::string& field) {
  OpenField open = open_field(path, dataset, field, FieldKind::number);
  std::vector<double> values(open.rows);
  if (values.empty()) return values;
  Handle type = single_field_type(field, H5T_NATIVE_DOUBLE);
  check(H5Dread(open.data, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "read " + dataset + " " + field);
  return values;
}

std::vector<std::string> read_text_field(const std::string& path, const std::string& dataset, const std::string& field) {
  OpenField open = open_field(path, dataset, field, FieldKind::text);
  std::vector<char*> texts(open.rows, nullptr);
  if (texts.empty()) return {};
  Handle string = h5::string_type();
  Handle type = single_field_type(field, string);
  check(H5Dread(open.data, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, texts.data()), "read " + dataset + " " + field);
  std::vector<std::string> out;
  for (char* text : texts) {
    out.emplace_back(text ? text : "");
    H5free_memory(text);
  }
  return out;
}

}  // namespace pbrfit::store
