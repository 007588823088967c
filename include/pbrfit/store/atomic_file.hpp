#pragma once
// Replaces a file's content so that a crash at any instant leaves either the old or the new content.
#include <span>
#include <string>

#include "pbrfit/core/bytes.hpp"

namespace pbrfit::store {

// Writes PATH.tmp, fsyncs it, renames it over PATH and fsyncs the directory. Throws RunError.
void replace_file_atomically(const std::string& path, std::span<const std::byte> content);

// The whole file; throws InputError naming the file when it cannot be read.
Bytes read_whole_file(const std::string& path);

}  // namespace pbrfit::store
