#pragma once
// Reading a data file a job key names. A file that cannot be opened at all (its InputError has no line)
// is reported at the key that names it, "'KEY' names PATH: REASON"; problems inside a file keep their own
// position in it.
#include <string>

#include "pbrfit/core/error.hpp"
#include "pbrfit/spec/schema.hpp"

namespace pbrfit::jobs {

template <class Read>
auto read_at_key(const spec::Section& s, const std::string& key, const std::string& path, Read&& read) {
  try {
    return read();
  } catch (const InputError& e) {
    if (e.where().line != 0) throw;
    s.reject(key, "names " + path + ": " + e.message());
  }
}

// The same inside a spec::Keys check: "" once `read` has run, or "names PATH: REASON" for the check to
// report at its key.
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
