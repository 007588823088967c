#pragma once
// Creating a result file's groups, axes and tables from the layout. Private to the store.
#include <hdf5.h>

#include "pbrfit/store/result_layout.hpp"

namespace pbrfit::store {

// The group with its description, attributes, axes (as dimension scales) and empty tables.
void create_group(hid_t file, const Group& layout);

// A table's dimension extents: its axes' sizes, and 0 (unbounded) for a growing first dimension.
std::vector<std::uint64_t> table_extent(const Group& group, const Table& table);

}  // namespace pbrfit::store
