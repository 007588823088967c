#include "global_heap_check.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "pbrfit/core/error.hpp"
#include "posix_file.hpp"

namespace pbrfit::store {

namespace {

// The collection layout (HDF5 file format, "Global Heap"): signature "GCOL", version 1, 3 reserved bytes,
// the collection's size in bytes (8, the default size of lengths); then objects of a 16-byte header (index
// 2, reference count 2, reserved 4, size 8) and their data padded to 8 bytes. Index 0 is the free space,
// whose size covers its header and the rest of the collection.
constexpr std::array<char, 5> signature = {'G', 'C', 'O', 'L', 1};
constexpr std::uint64_t header_bytes = 16;
constexpr std::uint64_t object_header_bytes = 16;

std::uint64_t little_endian(const std::byte* p, int bytes) {
  std::uint64_t value = 0;
  for (int i = bytes - 1; i >= 0; --i) value = (value << 8) | std::to_integer<std::uint64_t>(p[i]);
  return value;
}

enum class Walk { intact, damaged, not_walked };

// Walks the collection at `offset` as HDF5 does: intact when the walk ends and every object lies inside
// it (`size` is then its size); not walked when HDF5 refuses it before walking (smaller than its header,
// or past the end of the file).
Walk walk_collection(const PosixFile& file, std::uint64_t offset, std::uint64_t& size) {
  std::array<std::byte, header_bytes> header{};
  if (!file.read_at(offset, header)) return Walk::not_walked;
  size = little_endian(header.data() + 8, 8);
  if (size < header_bytes || size > file.size() - offset) return Walk::not_walked;
  std::vector<std::byte> collection(size);
  if (!file.read_at(offset, collection)) return Walk::not_walked;
  std::uint64_t p = header_bytes;
  while (p < size) {
    if (p + object_header_bytes > size) return Walk::intact;  // a tail too short for a header is free space
    const std::uint64_t index = little_endian(collection.data() + p, 2);
    const std::uint64_t object_size = little_endian(collection.data() + p + 8, 8);
    const std::uint64_t room = size - p;
    if (index == 0) {
      // The free space covers its own header and the rest: of size 0 HDF5's walk never advances.
      if (object_size < object_header_bytes || object_size > room) return Walk::damaged;
      p += object_size;
    } else {
      // An object past the collection's end would make HDF5 copy (H5HG_read) or step beyond it.
      if (object_size > room - object_header_bytes) return Walk::damaged;
      p += object_header_bytes + ((object_size + 7) & ~std::uint64_t(7));
    }
  }
  return Walk::intact;
}

}  // namespace

void check_global_heaps(const std::string& path) {
  std::optional<PosixFile> opened;
  try {
    opened.emplace(PosixFile::open_for_reading(path));
  } catch (const std::runtime_error&) {
    return;  // missing, not a regular file, unreadable: HDF5's open says so in the caller's words
  }
  const PosixFile& file = *opened;
  const std::uint64_t length = file.size();
  constexpr std::uint64_t chunk = std::uint64_t(1) << 20;
  constexpr std::uint64_t overlap = signature.size() - 1;  // so that a signature across two chunks is seen
  std::vector<std::byte> buffer;
  // Collections do not overlap: a signature inside an intact one is its objects' data (a string that
  // happens to read "GCOL"), not walked again, which keeps the whole check linear in the file's size.
  std::uint64_t intact_until = 0;
  for (std::uint64_t start = 0; start < length; start += chunk) {
    buffer.resize(std::min(chunk + overlap, length - start));
    if (!file.read_at(start, buffer)) return;
    const char* data = reinterpret_cast<const char*>(buffer.data());
    const char* const end = data + buffer.size();
    for (const char* hit = data;
         (hit = std::search(hit, end, signature.begin(), signature.end())) != end; ++hit) {
      if (std::uint64_t(hit - data) >= chunk) break;  // the next chunk's
      const std::uint64_t offset = start + std::uint64_t(hit - data);
      if (offset < intact_until) continue;
      std::uint64_t size = 0;
      const Walk walk = walk_collection(file, offset, size);
      if (walk == Walk::intact) intact_until = offset + size;
      if (walk == Walk::damaged)
        throw RunError("HDF5: damaged global heap collection at byte " + std::to_string(offset) +
                       " (an object's size runs past the collection or never advances)");
    }
  }
}

}  // namespace pbrfit::store
