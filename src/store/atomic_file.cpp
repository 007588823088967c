#include "pbrfit/store/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "pbrfit/core/error.hpp"

namespace pbrfit::store {

namespace {

[[noreturn]] void fail(const std::string& what, const std::string& path) {
  throw RunError("cannot " + what + " " + path + ": " + std::strerror(errno));
}

void write_all(int fd, std::span<const std::byte> content, const std::string& path) {
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail("write", path);
    written += std::size_t(n);
  }
}

void fsync_directory_of(const std::string& path) {
  auto dir = std::filesystem::path(path).parent_path();
  if (dir.empty()) dir = ".";
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;  // the rename is done; a directory we cannot open cannot be synced
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

void replace_file_atomically(const std::string& path, std::span<const std::byte> content) {
  const std::string temporary = path + ".tmp";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("create", temporary);
  try {
    write_all(fd, content, temporary);
    if (::fsync(fd) != 0) fail("sync", temporary);
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) fail("close", temporary);
  if (std::rename(temporary.c_str(), path.c_str()) != 0) fail("rename over", path);
  fsync_directory_of(path);
}

Bytes read_whole_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path}, std::string("cannot read file: ") + std::strerror(errno));
  in.seekg(0, std::ios::end);
  Bytes bytes(std::size_t(in.tellg()));
  in.seekg(0);
  in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!in) throw InputError({path}, "cannot read file: read failed");
  return bytes;
}

}  // namespace pbrfit::store
