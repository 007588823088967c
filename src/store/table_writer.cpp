#include "table_writer.hpp"

#include <map>

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
  std::map<std::pair<std::string, std::string>, std::vector<Block>> by_table;
  for (auto& b : blocks) by_table[{b.group, b.table}].push_back(std::move(b));
  for (const auto& group : layout.groups) {
    for (const auto& table : group.tables) {
      auto found = by_table.find({group.name, table.name});
      if (found == by_table.end()) continue;
      write_table(file, group, table, std::move(found->second));
      by_table.erase(found);
    }
  }
  if (!by_table.empty())
    throw std::logic_error("a block names table " + by_table.begin()->first.first + "/" +
                           by_table.begin()->first.second + ", which the layout does not have");
}

}  // namespace pbrfit::store
