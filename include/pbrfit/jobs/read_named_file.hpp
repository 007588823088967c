#pragma once
// Reading a data file a job key names, inside a spec::Keys check. A file that cannot be opened at all (its
// InputError has no line) becomes the check's message, "names PATH: REASON", which the check reports at its
// key ("'KEY' names PATH: REASON"); problems inside a file keep their own position in it.
#include <string>

#include "pbrfit/core/error.hpp"

namespace pbrfit::jobs {

// "" once `read` has run, or "names PATH: REASON".
template <class Read>
std::string read_named_file(const std::string& path, Read&& read) {
  try {
    read();
    return {};
  } catch (const InputError& e) {
    if (e.where().line != 0) throw;
    return "names " + path + ": " + e.message();
  }
}

}  // namespace pbrfit::jobs
