#pragma once
// What every libFuzzer target of pbrfit shares. The contract each target checks is the one the program
// promises for hostile input: any bytes give either a result or pbrfit::InputError (a one-line message,
// exit code 2); anything else that escapes (another exception, a crash, a hang, an allocation beyond
// libFuzzer's -rss_limit_mb) is a defect the fuzzer reports. Readers of files get the bytes in a file of
// their own (per process, in $TMPDIR or /tmp), as the program reads them.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>
#include <string_view>

#include "pbrfit/core/error.hpp"

namespace pbrfit::fuzz {

inline std::string_view text_of(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// The bytes in a scratch file named after this process and `suffix` (an extension the reader may want).
inline const std::string& scratch_file(const std::uint8_t* data, std::size_t size, const std::string& suffix) {
  static std::string path;
  const char* tmp = std::getenv("TMPDIR");
  const bool first = path.empty();
  path = std::string(tmp && *tmp ? tmp : "/tmp") + "/pbrfit-fuzz-" + std::to_string(::getpid()) + suffix;
  if (first) std::atexit([] { std::remove(path.c_str()); });
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  if (!out) {
    std::fprintf(stderr, "fuzz: cannot write %s\n", path.c_str());
    std::abort();
  }
  return path;
}

// Runs `body`; an InputError is the accepted answer to bad input, anything else thrown aborts (a finding).
template <class Body>
void expect_result_or_input_error(Body&& body) {
  try {
    body();
  } catch (const InputError& e) {
    const std::string_view message = e.what();
    // The one-line promise: a rejected input is told on exactly one line.
    if (message.find('\n') != std::string_view::npos) {
      std::fprintf(stderr, "fuzz: a message of more than one line: %s\n", e.what());
      std::abort();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: not an InputError: %s\n", e.what());
    std::abort();
  }
}

}  // namespace pbrfit::fuzz
