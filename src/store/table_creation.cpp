#include "table_creation.hpp"

#include <hdf5_hl.h>

#include <algorithm>
#include <limits>

#include "element_types.hpp"

namespace pbrfit::store {

using h5::check;
using h5::Handle;

namespace {

void create_axis(hid_t group, const Axis& axis) {
  const hsize_t n = axis.values.size();
  Handle space(check(H5Screate_simple(1, &n, nullptr), "create axis space"), H5Sclose);
  Handle data(check(H5Dcreate2(group, axis.name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                    "create axis " + axis.name),
              H5Dclose);
  check(H5Dwrite(data, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, axis.values.data()), "write axis " + axis.name);
  check(H5DSset_scale(data, axis.name.c_str()), "make " + axis.name + " a dimension scale");
  h5::write_string_attribute(data, "description", axis.description);
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// About 16384 numbers (1024 texts or records) a chunk, whole along the inner dimensions when they fit.
std::vector<hsize_t> default_chunk(const Table& table, const std::vector<std::uint64_t>& extent) {
  const hsize_t target = table.is_record() || !is_numeric(table.type) ? 1024 : 16384;
  std::vector<hsize_t> chunk(extent.begin(), extent.end());
  hsize_t inner = 1;
  for (std::size_t d = chunk.size(); d-- > 1;) {
    chunk[d] = std::clamp<hsize_t>(target / inner, 1, std::max<hsize_t>(chunk[d], 1));
    inner *= chunk[d];
  }
  const hsize_t outer_limit = table.growing ? target : std::max<hsize_t>(chunk[0], 1);
  chunk[0] = std::clamp<hsize_t>(target / inner, 1, outer_limit);
  return chunk;
}

Handle table_creation_properties(const Table& table, const std::vector<std::uint64_t>& extent) {
  Handle dcpl(check(H5Pcreate(H5P_DATASET_CREATE), "create dataset properties"), H5Pclose);
  std::vector<hsize_t> chunk = table.chunk.empty() ? default_chunk(table, extent)
                                                   : std::vector<hsize_t>(table.chunk.begin(), table.chunk.end());
  check(H5Pset_chunk(dcpl, int(chunk.size()), chunk.data()), "set chunking of " + table.name);
  if (!table.is_record() && (table.type == ValueType::f32 || table.type == ValueType::f64)) {
    const double fill = std::numeric_limits<double>::quiet_NaN();
    check(H5Pset_fill_value(dcpl, H5T_NATIVE_DOUBLE, &fill), "set fill value");
  }
  return dcpl;
}

void create_table(hid_t group, const Group& layout, const Table& table) {
  const auto extent = table_extent(layout, table);
  const std::size_t rank = extent.size();
  std::vector<hsize_t> dims(extent.begin(), extent.end()), max_dims(dims);
  dims[0] = 0;
  max_dims[0] = H5S_UNLIMITED;
  Handle space(check(H5Screate_simple(int(rank), dims.data(), max_dims.data()), "create table space"), H5Sclose);
  Handle dcpl = table_creation_properties(table, extent);
  Handle type = file_type_of(table);
  Handle data(check(H5Dcreate2(group, table.name.c_str(), type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
                    "create table " + table.name),
              H5Dclose);
  for (std::size_t d = 0; d < rank; ++d) {
    if (d > 0 || !table.growing) {
      Handle axis(check(H5Dopen2(group, table.axes[d].c_str(), H5P_DEFAULT), "open axis " + table.axes[d]), H5Dclose);
      check(H5DSattach_scale(data, axis, unsigned(d)), "attach axis " + table.axes[d]);
    }
    check(H5DSset_label(data, unsigned(d), table.axes[d].c_str()), "label dimension " + table.axes[d]);
  }
  h5::write_string_attribute(data, "description", table.description);
  h5::write_string_attribute(data, "axes", joined(table.axes));
  for (const auto& field : table.fields)
    h5::write_string_attribute(data, "field_" + field.name, field.description);
  for (const auto& [key, value] : table.attributes) h5::write_string_attribute(data, key, value);
}

}  // namespace

std::vector<std::uint64_t> table_extent(const Group& group, const Table& table) {
  std::vector<std::uint64_t> extent;
  for (std::size_t d = 0; d < table.axes.size(); ++d)
    extent.push_back(d == 0 && table.growing ? 0 : group.axis(table.axes[d]).values.size());
  return extent;
}

void create_group(hid_t file, const Group& layout) {
  Handle links(check(H5Pcreate(H5P_LINK_CREATE), "create link properties"), H5Pclose);
  check(H5Pset_create_intermediate_group(links, 1), "allow nested groups");
  Handle group(check(H5Gcreate2(file, layout.name.c_str(), links, H5P_DEFAULT, H5P_DEFAULT),
                     "create group " + layout.name),
               H5Gclose);
  h5::write_string_attribute(group, "description", layout.description);
  for (const auto& [key, value] : layout.attributes) h5::write_string_attribute(group, key, value);
  for (const auto& axis : layout.axes) create_axis(group, axis);
  for (const auto& table : layout.tables) create_table(group, layout, table);
}

}  // namespace pbrfit::store
