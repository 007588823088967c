#pragma once
// Whole-file reads and atomic whole-file replacement.
#include <cstdint>
#include <span>
#include <string>

#include "pbrfit/core/bytes.hpp"

namespace pbrfit::store {

// Writes PATH.<pid>.tmp (processes racing to write one file do not share a temporary), fsyncs it,
// renames it over PATH and fsyncs the directory, so that a crash at any instant leaves either the old or
// the new content. On failure PATH is untouched, the temporary removed and RunError thrown with the
// operating system's reason.
void replace_file_atomically(const std::string& path, std::span<const std::byte> content);

// The whole of a regular file of at most max_bytes; throws InputError naming the file for anything else
// (missing, unreadable, a directory, FIFO or device, or too large).
Bytes read_whole_file(const std::string& path, std::uint64_t max_bytes);

}  // namespace pbrfit::store
