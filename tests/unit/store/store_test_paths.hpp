#pragma once
// A scratch directory for the store's tests, one per process (scratch_directory.hpp): test cases of one file
// that write the same scratch name ran into each other under ctest -j2 (a rare failure of
// record_fields_test.cpp).
#include <filesystem>
#include <string>

#include "scratch_directory.hpp"

inline std::string temporary_path(const std::string& name) {
  static const ScratchDirectory directory("pbrfit-store-tests");
  return (directory.path() / name).string();
}

// Whether a temporary file of an atomic replacement of `path` (PATH.<pid>.tmp) is left beside it.
inline bool temporary_left_beside(const std::string& path) {
  const auto p = std::filesystem::path(path);
  const std::string stem = p.filename().string() + ".";
  for (const auto& entry : std::filesystem::directory_iterator(p.parent_path())) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with(stem) && name.ends_with(".tmp")) return true;
  }
  return false;
}
