#pragma once
// HDF5 types of table elements: in the file, each value in its declared precision (little-endian) and
// texts as variable-length UTF-8; in memory, every real as a double, every integer as a 64-bit integer of
// its signedness and every text as a char*, eight bytes a value, records packed field after field. HDF5
// converts between the two. Private to the store.
#include <cstddef>
#include <vector>

#include "hdf5_handle.hpp"
#include "pbrfit/store/result_layout.hpp"

namespace pbrfit::store {

h5::Handle file_type_of(const Table& table);
h5::Handle memory_type_of(const Table& table);

// A block's elements in the memory layout of memory_type_of; text pointers point into block.texts.
std::vector<std::byte> pack_elements(const Table& table, const Block& block);

}  // namespace pbrfit::store
