#include "pbrfit/store/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <string>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/result_file.hpp"
#include "posix_file.hpp"

namespace pbrfit::store {

namespace {

std::string holder_of(int fd) {
  char buffer[256] = {};
  const ssize_t n = ::pread(fd, buffer, sizeof buffer - 1, 0);
  std::string text = n > 0 ? std::string(buffer, std::size_t(n)) : "";
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text.empty() ? "another process" : text;
}

// The lock file may have been removed and recreated between open and lock: the lock is only good if it
// is on the file the path names now.
bool still_at_path(int fd, const std::string& path) {
  struct stat opened {}, named {};
  return ::fstat(fd, &opened) == 0 && ::stat(path.c_str(), &named) == 0 && opened.st_ino == named.st_ino &&
         opened.st_dev == named.st_dev;
}

}  // namespace

std::string lock_path_for(const std::string& result_path) { return result_path + ".lock"; }

OutputLock::OutputLock(const std::string& result_path) : path_(lock_path_for(result_path)) {
  for (;;) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NONBLOCK, 0644);
    if (fd_ < 0) throw RunError("cannot create the lock file " + path_ + ": " + os_reason());
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const std::string holder = holder_of(fd_);
      ::close(fd_);
      fd_ = -1;
      throw InputError({result_path}, "is in use by another pbrfit run (" + holder +
                                          "); wait for it to end, stop it, or use --output");
    }
    if (still_at_path(fd_, path_)) break;
    ::close(fd_);
  }
  // Only the message of a refused run depends on this note; the lock holds without it.
  const std::string me = "host " + host_name() + ", pid " + std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) == 0) (void)!::pwrite(fd_, me.data(), me.size(), 0);
}

OutputLock::~OutputLock() {
  if (fd_ >= 0) ::close(fd_);
}

void OutputLock::remove_file() { ::unlink(path_.c_str()); }

}  // namespace pbrfit::store
