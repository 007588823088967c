#pragma once
// A scratch directory for the store's tests.
#include <filesystem>
#include <string>

inline std::string temporary_path(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "pbrfit-store-tests";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
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
