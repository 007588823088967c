#include "posix_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <sys/sendfile.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "pbrfit/core/error.hpp"

namespace pbrfit::store {

std::string os_reason() { return std::strerror(errno); }

namespace {

[[noreturn]] void fail(const std::string& what, const std::string& path) {
  throw RunError("cannot " + what + " " + path + ": " + os_reason());
}

}  // namespace

PosixFile PosixFile::open_for_reading(const std::string& path) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused below anyway.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) throw InputError({path}, "cannot read file: " + os_reason());
  PosixFile file(fd, path);
  struct stat info {};
  if (::fstat(fd, &info) != 0) throw InputError({path}, "cannot read file: " + os_reason());
  if (!S_ISREG(info.st_mode))
    throw InputError({path}, S_ISDIR(info.st_mode) ? "is a directory, not a file" : "is not a regular file");
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  return file;
}

PosixFile PosixFile::create(const std::string& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("create", path);
  return PosixFile(fd, path);
}

PosixFile PosixFile::open_for_writing(const std::string& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) fail("open", path);
  PosixFile file(fd, path);
  struct stat info {};
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) throw RunError("cannot write " + path + ": not a regular file");
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  return file;
}

PosixFile::PosixFile(PosixFile&& other) noexcept : fd_(other.fd_), path_(std::move(other.path_)) { other.fd_ = -1; }

PosixFile::~PosixFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::uint64_t PosixFile::size() const {
  struct stat info {};
  if (::fstat(fd_, &info) != 0) fail("read the size of", path_);
  return std::uint64_t(info.st_size);
}

bool PosixFile::read_at(std::uint64_t offset, std::span<std::byte> buffer) const {
  std::size_t done = 0;
  while (done < buffer.size()) {
    const ssize_t n = ::pread(fd_, buffer.data() + done, buffer.size() - done, off_t(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError({path_}, "cannot read file: " + os_reason());
    if (n == 0) return false;
    done += std::size_t(n);
  }
  return true;
}

void PosixFile::write_all(std::span<const std::byte> content) {
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd_, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail("write", path_);
    written += std::size_t(n);
  }
}

void PosixFile::copy_to(PosixFile& target) const {
  const std::uint64_t total = size();
  std::uint64_t done = 0;
  off_t offset = 0;
  while (done < total) {
    const ssize_t n = ::sendfile(target.fd_, fd_, &offset, std::size_t(total - done));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail("copy " + path_ + " to", target.path_);
    if (n == 0) throw RunError("cannot copy " + path_ + ": it shrank while being copied");
    done += std::uint64_t(n);
  }
}

void PosixFile::truncate(std::uint64_t length) {
  if (::ftruncate(fd_, off_t(length)) != 0) fail("truncate", path_);
}

void PosixFile::seek_to_end() {
  if (::lseek(fd_, 0, SEEK_END) < 0) fail("seek in", path_);
}

void PosixFile::sync() {
  if (::fsync(fd_) != 0) fail("sync", path_);
}

void PosixFile::close() {
  const int fd = fd_;
  fd_ = -1;
  if (fd >= 0 && ::close(fd) != 0) fail("close", path_);
}

void sync_directory_of(const std::string& path) {
  auto dir = std::filesystem::path(path).parent_path();
  if (dir.empty()) dir = ".";
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;  // the rename is done; a directory we cannot open cannot be synced
  ::fsync(fd);
  ::close(fd);
}

void copy_then_rename(const std::string& from, const std::string& to) {
  const std::string temporary = to + ".tmp";
  try {
    const PosixFile source = PosixFile::open_for_reading(from);
    PosixFile target = PosixFile::create(temporary);
    source.copy_to(target);
    target.close();
    if (std::rename(temporary.c_str(), to.c_str()) != 0) fail("rename over", to);
  } catch (const InputError& e) {
    std::remove(temporary.c_str());
    throw RunError(e.what());
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
}

}  // namespace pbrfit::store
