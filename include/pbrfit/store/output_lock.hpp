#pragma once
// One run per output at a time: an exclusive lock on R.h5.lock beside the result, held for the life of
// this object and released by the operating system if the process dies. The lock file holds the
// holder's host and pid, so a refused run can say who has it.
#include <string>

namespace pbrfit::store {

class OutputLock {
 public:
  // Throws InputError naming the result file and the holder when another process holds the lock, and
  // RunError when the lock file cannot be created.
  explicit OutputLock(const std::string& result_path);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  // Removes the lock file while still holding it (after a complete run).
  void remove_file();

 private:
  std::string path_;
  int fd_ = -1;
};

std::string lock_path_for(const std::string& result_path);

}  // namespace pbrfit::store
