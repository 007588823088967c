#pragma once
// A guard against one way a damaged HDF5 file hangs the library. HDF5 1.10.8 (Debian 12) walks a global
// heap collection (where variable-length strings live) object by object, advancing by each object's
// declared size; a free-space object of size 0, or a size that wraps the address around, never advances
// and the walk loops forever (found by the result_file fuzzer). Before a reader opens a file, this walks
// every collection the same way and refuses the file if a walk would not end. Private to the store.
#include <string>

namespace pbrfit::store {

// Throws RunError naming the byte offset of a global heap collection whose object list would not end;
// returns quietly for an intact file (and for any file it cannot read: HDF5's own open reports that).
void check_global_heaps(const std::string& path);

}  // namespace pbrfit::store
