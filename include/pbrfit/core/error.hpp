#pragma once
// Error types and the process exit codes they map to.
#include <stdexcept>
#include <string>

namespace pbrfit {

enum ExitCode : int {
  exit_success = 0,
  exit_invalid_input = 2,  // job file, data file or checkpoint rejected
  exit_run_failure = 3,    // the run itself failed
  exit_interrupted = 75,   // stopped by a signal, checkpoint saved (EX_TEMPFAIL)
};

// A place in an input file; line and column are 1-based, 0 when unknown.
struct SourcePosition {
  std::string file;
  int line = 0;
  int column = 0;
};

// Rejected input. what() is the complete one-line message: "FILE:LINE:COL: error: MESSAGE".
class InputError : public std::runtime_error {
 public:
  InputError(SourcePosition where, const std::string& message);
  const SourcePosition& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  SourcePosition where_;
  std::string message_;
};

// Failure while running a job (I/O, numerics, a lost rank).
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "FILE:LINE:COL: error: MESSAGE" on one line: control characters in the file name and the message are
// escaped (core/quoted_text.hpp).
std::string format_error(const SourcePosition& where, const std::string& message);

}  // namespace pbrfit
