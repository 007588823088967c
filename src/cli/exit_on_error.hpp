#pragma once
// Runs a command body and turns what it throws into a one-line message and an exit code:
// InputError -> its own "FILE:LINE:COL: error: ..." line and 2; anything else -> 3. Never rethrows.
#include <cstdio>
#include <exception>

#include "pbrfit/core/error.hpp"
#include "pbrfit/core/quoted_text.hpp"

namespace pbrfit::cli {

template <class Body>
int exit_on_error(Body&& body, bool report = true) {
  try {
    return body();
  } catch (const InputError& e) {
    if (report) std::fprintf(stderr, "%s\n", e.what());
    return exit_invalid_input;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pbrfit: error: %s\n", one_line(e.what()).c_str());
    return exit_run_failure;
  }
}

}  // namespace pbrfit::cli
