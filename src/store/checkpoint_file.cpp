#include "pbrfit/store/checkpoint_file.hpp"

#include <array>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/atomic_file.hpp"

namespace pbrfit::store {

namespace {

constexpr std::array<char, 8> magic = {'P', 'B', 'R', 'F', 'I', 'T', 'C', 'K'};
constexpr std::uint32_t format_version = 1;

[[noreturn]] void reject(const std::string& path, std::size_t offset, const std::string& what) {
  throw InputError({path}, "corrupt checkpoint at byte " + std::to_string(offset) + ": " + what);
}

}  // namespace

std::string checkpoint_path_for(const std::string& result_path) { return result_path + ".checkpoint"; }

void write_checkpoint(const std::string& path, const Checkpoint& checkpoint) {
  ByteWriter out;
  for (char c : magic) out.put(c);
  out.put(format_version);
  out.put_string(checkpoint.job_text);
  out.put(checkpoint.stage);
  out.put(checkpoint.elapsed_seconds);
  out.put<std::uint64_t>(checkpoint.results.size());
  for (const auto& [id, result] : checkpoint.results) {
    out.put(id.stage);
    out.put(id.item);
    out.put_bytes(result);
  }
  out.put(fnv1a64(out.bytes()));
  replace_file_atomically(path, out.bytes());
}

Checkpoint read_checkpoint(const std::string& path) {
  const Bytes bytes = read_whole_file(path);
  if (bytes.size() < magic.size() + sizeof(std::uint64_t)) reject(path, bytes.size(), "file too short");
  const std::size_t body = bytes.size() - sizeof(std::uint64_t);
  const std::span<const std::byte> all(bytes);
  ByteReader trailer(all.subspan(body));
  if (trailer.get<std::uint64_t>() != fnv1a64(all.first(body)))
    reject(path, body, "checksum mismatch (truncated or modified)");

  ByteReader in(all.first(body));
  try {
    for (char c : magic)
      if (in.get<char>() != c) reject(path, 0, "not a pbrfit checkpoint");
    if (const auto v = in.get<std::uint32_t>(); v != format_version)
      reject(path, 8, "unsupported format version " + std::to_string(v));
    Checkpoint checkpoint;
    checkpoint.job_text = in.get_string();
    checkpoint.stage = in.get<std::uint32_t>();
    checkpoint.elapsed_seconds = in.get<double>();
    const auto count = in.get<std::uint64_t>();
    for (std::uint64_t i = 0; i < count; ++i) {
      WorkItemId id;
      id.stage = in.get<std::uint32_t>();
      id.item = in.get<std::uint64_t>();
      checkpoint.results[id] = in.get_bytes();
    }
    if (in.remaining() != 0) reject(path, in.offset(), "unexpected trailing data");
    return checkpoint;
  } catch (const ByteFormatError& e) {
    reject(path, e.offset(), e.what());
  }
}

}  // namespace pbrfit::store
