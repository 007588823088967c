#include "pbrfit/store/atomic_file.hpp"

#include <unistd.h>

#include <cstdio>

#include "pbrfit/core/error.hpp"
#include "posix_file.hpp"

namespace pbrfit::store {

void replace_file_atomically(const std::string& path, std::span<const std::byte> content) {
  const std::string temporary = path + "." + std::to_string(::getpid()) + ".tmp";  // processes may race
  try {
    PosixFile file = PosixFile::create(temporary);
    file.write_all(content);
    file.sync();
    file.close();
    if (std::rename(temporary.c_str(), path.c_str()) != 0) throw RunError("cannot rename over " + path + ": " + os_reason());
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  sync_directory_of(path);
}

Bytes read_whole_file(const std::string& path, std::uint64_t max_bytes) {
  const PosixFile file = PosixFile::open_for_reading(path);
  const std::uint64_t size = file.size();
  if (size > max_bytes)
    throw InputError({path}, "is too large (" + std::to_string(size) + " bytes; at most " + std::to_string(max_bytes) +
                                 " are read)");
  Bytes bytes(size);
  if (!file.read_at(0, bytes)) throw InputError({path}, "cannot read file: it shrank while being read");
  return bytes;
}

}  // namespace pbrfit::store
