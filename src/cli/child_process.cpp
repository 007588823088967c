// Spawns with posix_spawnp and waits through EINTR; the contract is in child_process.hpp.
#include "child_process.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>

#include "pbrfit/core/error.hpp"
#include "pbrfit/core/quoted_text.hpp"

extern char** environ;

namespace pbrfit::cli {

ChildExit run_program(const std::vector<std::string>& argv) {
  std::vector<std::string> args = argv;
  std::vector<char*> pointers;
  for (auto& a : args) pointers.push_back(a.data());
  pointers.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, pointers[0], nullptr, nullptr, pointers.data(), environ);
  if (spawned != 0) throw RunError("cannot run " + quote(argv[0]) + ": " + std::strerror(spawned));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw RunError("lost " + quote(argv[0]) + ": " + std::strerror(errno));
  }
  if (WIFSIGNALED(status)) return {true, WTERMSIG(status)};
  return {false, WEXITSTATUS(status)};
}

}  // namespace pbrfit::cli
