#pragma once
// A scratch directory for the store's tests.
#include <filesystem>
#include <string>

inline std::string temporary_path(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "pbrfit-store-tests";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}
