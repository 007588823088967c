#pragma once
// An append-only file of checksummed records: an 8-byte magic, a u32 format version, then records of
// (u64 length, payload, u64 FNV-1a of length and payload). Appending is durable (fsync) record by
// record, so a crash can cut short at most the last record. Reading accepts exactly that: a damaged
// record that reaches the end of the file is a torn append and ends the log; a damaged record with more
// data after it means the file was altered, and is refused.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>

#include "pbrfit/core/bytes.hpp"

namespace pbrfit::store {

using LogMagic = std::array<char, 8>;

struct LogFormat {
  LogMagic magic;
  std::uint32_t version;
  const char* what;  // for messages, e.g. "checkpoint"
};

class RecordLog {
 public:
  // Atomically replaces PATH with a log holding `records` (temporary file, fsync, rename).
  static RecordLog create(const std::string& path, const LogFormat& format, std::span<const Bytes> records);
  // Continues an existing log after its first `valid_length` bytes, cutting off anything beyond.
  static RecordLog reopen(const std::string& path, std::uint64_t valid_length);

  RecordLog(RecordLog&&) noexcept;
  RecordLog& operator=(RecordLog&&) noexcept;
  ~RecordLog();

  // Appends one record and makes it durable; throws RunError. Returns the log's new length.
  std::uint64_t append(std::span<const std::byte> payload);
  std::uint64_t length() const { return length_; }
  std::uint64_t bytes_appended() const { return appended_; }  // since this object was made

 private:
  struct File;
  RecordLog(std::unique_ptr<File> file, std::uint64_t length);
  std::unique_ptr<File> file_;
  std::uint64_t length_ = 0;
  std::uint64_t appended_ = 0;
};

struct LogReading {
  std::uint64_t valid_length = 0;  // bytes up to the end of the last good record
  bool torn_tail = false;          // a cut-short last record was dropped
};

// Calls visit(payload, end_offset) for each good record in order; `stop_at` (if not 0) ends the read at
// that offset, which must be a record boundary. Throws InputError naming the file and byte offset for a
// file that is not such a log, has another version, or was altered; exceptions from visit (ByteFormatError
// included) are reported the same way at the record's offset.
LogReading read_record_log(const std::string& path, const LogFormat& format,
                           const std::function<void(std::span<const std::byte>, std::uint64_t)>& visit,
                           std::uint64_t stop_at = 0);

}  // namespace pbrfit::store
