#pragma once
// A test process's own directory for scratch files, <temp>/<prefix>-<pid>: made when constructed, removed
// with everything in it when destroyed (as a function's static, when the process exits). ctest runs each
// test case as a process of its own, two at a time, so test cases that write the same scratch name never
// race for one file.
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

class ScratchDirectory {
 public:
  explicit ScratchDirectory(const std::string& prefix)
      : path_(std::filesystem::temp_directory_path() / (prefix + "-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};
