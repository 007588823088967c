#pragma once
// Runs a program (found on PATH when the name has no slash) with the given arguments and this process's
// environment and standard streams, and waits for it. Throws RunError naming the program and the OS's
// reason when it cannot be started; otherwise returns how it ended.
#include <string>
#include <vector>

namespace pbrfit::cli {

struct ChildExit {
  bool signalled = false;  // ended by a signal rather than exit()
  int code = 0;            // the exit status, or the signal number when signalled
};

ChildExit run_program(const std::vector<std::string>& argv);

}  // namespace pbrfit::cli
