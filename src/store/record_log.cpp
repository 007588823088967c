#include "pbrfit/store/record_log.hpp"

#include <cstdio>

#include "pbrfit/core/error.hpp"
#include "posix_file.hpp"

namespace pbrfit::store {

namespace {

constexpr std::uint64_t header_size = 8 + sizeof(std::uint32_t);
constexpr std::uint64_t frame_size = 2 * sizeof(std::uint64_t);

std::uint64_t record_checksum(std::uint64_t length, std::span<const std::byte> payload) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  const auto mix = [&h](std::span<const std::byte> bytes) {
    for (std::byte b : bytes) h = (h ^ std::uint64_t(b)) * 0x100000001b3ULL;
  };
  mix(std::as_bytes(std::span(&length, 1)));
  mix(payload);
  return h;
}

Bytes framed(std::span<const std::byte> payload) {
  ByteWriter out;
  out.put<std::uint64_t>(payload.size());
  out.put_raw(payload);
  out.put(record_checksum(payload.size(), payload));
  return out.take();
}

[[noreturn]] void reject(const std::string& path, const LogFormat& format, std::uint64_t offset, const std::string& what) {
  throw InputError({path}, std::string("damaged ") + format.what + " at byte " + std::to_string(offset) + ": " + what);
}

}  // namespace

struct RecordLog::File {
  PosixFile posix;
};

RecordLog::RecordLog(std::unique_ptr<File> file, std::uint64_t length) : file_(std::move(file)), length_(length) {}
RecordLog::RecordLog(RecordLog&&) noexcept = default;
RecordLog& RecordLog::operator=(RecordLog&&) noexcept = default;
RecordLog::~RecordLog() = default;

RecordLog RecordLog::create(const std::string& path, const LogFormat& format, std::span<const Bytes> records) {
  const std::string temporary = path + ".tmp";
  std::uint64_t length = header_size;
  try {
    PosixFile file = PosixFile::create(temporary);
    ByteWriter header;
    for (char c : format.magic) header.put(c);
    header.put(format.version);
    file.write_all(header.bytes());
    for (const auto& record : records) {
      const Bytes frame = framed(record);
      file.write_all(frame);
      length += frame.size();
    }
    file.sync();
    file.close();
    if (std::rename(temporary.c_str(), path.c_str()) != 0) throw RunError("cannot rename over " + path + ": " + os_reason());
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  sync_directory_of(path);
  return reopen(path, length);
}

RecordLog RecordLog::reopen(const std::string& path, std::uint64_t valid_length) {
  auto file = std::make_unique<File>(File{PosixFile::open_for_writing(path)});
  if (file->posix.size() != valid_length) {
    file->posix.truncate(valid_length);
    file->posix.sync();
  }
  file->posix.seek_to_end();
  return RecordLog(std::move(file), valid_length);
}

std::uint64_t RecordLog::append(std::span<const std::byte> payload) {
  const Bytes frame = framed(payload);
  file_->posix.write_all(frame);
  file_->posix.sync();
  length_ += frame.size();
  appended_ += frame.size();
  return length_;
}

LogReading read_record_log(const std::string& path, const LogFormat& format,
                           const std::function<void(std::span<const std::byte>, std::uint64_t)>& visit,
                           std::uint64_t stop_at) {
  const PosixFile file = PosixFile::open_for_reading(path);
  const std::uint64_t size = file.size();
  Bytes header(header_size);
  if (!file.read_at(0, header)) reject(path, format, size, std::string("too short to be a ") + format.what);
  ByteReader head(header);
  for (char c : format.magic)
    if (head.get<char>() != c) reject(path, format, 0, std::string("not a pbrfit ") + format.what);
  if (const auto v = head.get<std::uint32_t>(); v != format.version)
    reject(path, format, 8, "format version " + std::to_string(v) + " (this pbrfit reads version " +
                                std::to_string(format.version) + ")");
  const std::uint64_t end = stop_at ? stop_at : size;
  if (end > size) reject(path, format, size, "shorter than the checkpoint that refers to it");
  LogReading reading{header_size, false};
  Bytes payload;
  while (reading.valid_length < end) {
    const std::uint64_t at = reading.valid_length;
    std::uint64_t frame[1];
    const bool have_length = end - at >= frame_size && file.read_at(at, std::as_writable_bytes(std::span(frame)));
    const std::uint64_t length = have_length ? frame[0] : 0;
    const bool fits = have_length && length <= end - at - frame_size;
    std::uint64_t sum[1] = {0};
    if (fits) {
      payload.resize(length);
      file.read_at(at + 8, payload);
      file.read_at(at + 8 + length, std::as_writable_bytes(std::span(sum)));
    }
    if (!fits || sum[0] != record_checksum(length, payload)) {
      // Only the last append can be cut short, and only when the log is read to its end.
      if (stop_at == 0 && (!fits || at + frame_size + length == size)) {
        reading.torn_tail = true;
        return reading;
      }
      reject(path, format, at, "record checksum mismatch (the file was altered or damaged)");
    }
    try {
      visit(payload, at + frame_size + length);
    } catch (const ByteFormatError& e) {
      reject(path, format, at + 8 + e.offset(), e.what());
    } catch (const std::logic_error& e) {
      reject(path, format, at, e.what());
    }
    reading.valid_length = at + frame_size + length;
  }
  return reading;
}

}  // namespace pbrfit::store
