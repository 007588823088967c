#pragma once
// A guard against damaged HDF5 global heap collections (where variable-length strings live), which
// HDF5 1.10.8 (Debian 12) trusts: it walks a collection object by object, advancing by each object's
// declared size, so a free-space object of size 0 makes the walk loop forever; and it copies an object by
// its declared size, so one larger than its collection reads (and writes) past the buffers (both found by
// the result_file fuzzer). Before a reader opens a file, this walks every collection the same way and
// refuses the file if the walk would not end or an object would leave its collection (collections do not
// overlap: one found inside an intact one is taken for its data and not walked, which keeps the check
// linear in the file's size; a crafted file could hide a damaged one there). Not guarded: a
// string whose length in its attribute or dataset differs from its heap object's size (HDF5 copies the
// object's size into a buffer of the string's). Private to the store.
#include <string>

namespace pbrfit::store {

// Throws RunError naming the byte offset of a global heap collection whose walk would not end or whose
// object leaves it;
// returns quietly for an intact file (and for any file it cannot read: HDF5's own open reports that).
void check_global_heaps(const std::string& path);

}  // namespace pbrfit::store
