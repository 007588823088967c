#pragma once
// Reading a record that must fill its bytes exactly: read(reader) on all of `bytes`, with trailing bytes
// an error. A ByteFormatError becomes a RunError "a <what> is damaged: <reason> at byte N" (records are
// written by pbrfit itself; damage means a bug or a corrupted checkpoint, not bad user input).
#include <span>
#include <string>

#include "pbrfit/core/bytes.hpp"
#include "pbrfit/core/error.hpp"

namespace pbrfit {

template <class Read>
auto decoded_record(std::span<const std::byte> bytes, const std::string& what, Read&& read) {
  try {
    ByteReader in(bytes);
    auto value = read(in);
    if (in.remaining() != 0) throw ByteFormatError(in.offset(), "trailing bytes");
    return value;
  } catch (const ByteFormatError& e) {
    throw RunError("a " + what + " is damaged: " + e.what());
  }
}

}  // namespace pbrfit
