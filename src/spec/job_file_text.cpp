#include "job_file_text.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "pbrfit/core/error.hpp"
#include "pbrfit/spec/job_spec.hpp"

namespace pbrfit::spec {

namespace {

[[noreturn]] void reject_unreadable(const std::string& path, int error_number) {
  throw InputError(SourcePosition{path}, "cannot read job file: " + std::string(std::strerror(error_number)));
}

// Closes the descriptor on every path out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

void require_regular(const std::string& path, int fd) {
  struct stat info {};
  if (::fstat(fd, &info) != 0) reject_unreadable(path, errno);
  if (S_ISDIR(info.st_mode)) throw InputError(SourcePosition{path}, "is a directory, not a job file");
  if (!S_ISREG(info.st_mode)) throw InputError(SourcePosition{path}, "is not a regular file");
}

}  // namespace

// Opened without blocking and checked on the open descriptor, so a FIFO or device swapped in after any
// earlier check is refused too; never more than the limit is read, even from a file that grows meanwhile.
std::string read_job_file_text(const std::string& path) {
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) reject_unreadable(path, errno);
  require_regular(path, file.fd);
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t count = ::read(file.fd, buffer, sizeof buffer);
    if (count < 0 && errno == EINTR) continue;
    if (count < 0) reject_unreadable(path, errno);
    if (count == 0) return text;
    text.append(buffer, std::size_t(count));
    if (text.size() > max_job_file_bytes)
      throw InputError(SourcePosition{path}, "is larger than " + std::to_string(max_job_file_bytes >> 10) +
                                                 " KiB, the most a job file may hold");
  }
}

}  // namespace pbrfit::spec
