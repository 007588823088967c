#pragma once
// Writing blocks into an open result file: one open of each table per batch, the table extended once to
// the rows the batch reaches, touching blocks merged into one hyperslab. Private to the store.
#include <hdf5.h>

#include <vector>

#include "pbrfit/store/result_layout.hpp"

namespace pbrfit::store {

void write_blocks(hid_t file, const ResultLayout& layout, std::vector<Block> blocks);

}  // namespace pbrfit::store
