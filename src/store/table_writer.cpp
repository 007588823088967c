#include "table_writer.hpp"

#include "block_merge.hpp"
#include "element_types.hpp"
#include "hdf5_handle.hpp"
#include "pbrfit/core/error.hpp"
#include "table_creation.hpp"

namespace pbrfit::store {

using h5::check;
using h5::Handle;

namespace {

void extend_to(hid_t data, const std::string& path, const std::vector<Block>& blocks) {
  Handle space(check(H5Dget_space(data), "read extent of " + path), H5Sclose);
  std::vector<hsize_t> dims(std::size_t(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  hsize_t rows = dims[0];
  for (const auto& b : blocks) rows = std::max<hsize_t>(rows, b.offset[0] + b.count[0]);
  if (rows == dims[0]) return;
  dims[0] = rows;
  check(H5Dset_extent(data, dims.data()), "extend " + path);
}

void write_block(hid_t data, hid_t memory_type, const std::string& path, const Table& table, const Block& block) {
  Handle space(check(H5Dget_space(data), "read extent of " + path), H5Sclose);
  const std::vector<hsize_t> offset(block.offset.begin(), block.offset.end());
  const std::vector<hsize_t> count(block.count.begin(), block.count.end());
  check(H5Sselect_hyperslab(space, H5S_SELECT_SET, offset.data(), nullptr, count.data(), nullptr),
        "select block of " + path);
  Handle memory(check(H5Screate_simple(int(count.size()), count.data(), nullptr), "create block space"), H5Sclose);
  const std::vector<std::byte> packed = pack_elements(table, block);
  check(H5Dwrite(data, memory_type, memory, space, H5P_DEFAULT, packed.data()), "write " + path);
}

void write_table(hid_t file, const Group& group, const Table& table, std::vector<Block> blocks) {
  const std::string path = group.name + "/" + table.name;
  for (const auto& b : blocks) check_block(b, table);
  blocks = merge_touching_blocks(std::move(blocks), table_extent(group, table));
  Handle data(check(H5Dopen2(file, path.c_str(), H5P_DEFAULT), "open table " + path), H5Dclose);
  extend_to(data, path, blocks);
  Handle memory_type = memory_type_of(table);
  for (const auto& block : blocks) write_block(data, memory_type, path, table, block);
}

}  // namespace

void write_blocks(hid_t file, const ResultLayout& layout, std::vector<Block> blocks) {
  // Bucketed by table in layout order; a block names the table of the block before it more often than not.
  const TableIndex index(layout);
  std::vector<std::vector<Block>> by_table(index.size());
  std::uint32_t last = index.size();
  for (auto& b : blocks) {
    if (last == index.size() || b.table != index.table(last).name || b.group != index.group_of(last))
      last = index.find(b.group, b.table);
    by_table[last].push_back(std::move(b));
  }
  std::uint32_t t = 0;
  for (const auto& group : layout.groups)
    for (const auto& table : group.tables)
      if (auto& of_table = by_table[t++]; !of_table.empty()) write_table(file, group, table, std::move(of_table));
}

}  // namespace pbrfit::store
