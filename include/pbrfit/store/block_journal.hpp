#pragma once
// The block journal: every block written to the result file, kept durable beside it until the job is
// complete, because an HDF5 file killed while it is written can be unreadable. It is a record log
// (record_log.hpp) whose first record is the job text and whose other records each hold a batch of
// encoded blocks (block_codec.hpp) at their final positions. It is only ever appended to, so a
// checkpoint never rewrites blocks it has written before; replaying it rebuilds the result file.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "pbrfit/store/block_codec.hpp"
#include "pbrfit/store/record_log.hpp"

namespace pbrfit::store {

class BlockJournal {
 public:
  // Starts an empty journal for the job, replacing any file at `path`.
  static BlockJournal create(const std::string& path, const std::string& job_text);
  // Continues a journal after its first `length` bytes (what a checkpoint relies on).
  static BlockJournal reopen(const std::string& path, std::uint64_t length);

  // Appends one batch: `count` blocks encoded one after the other. Durable when it returns.
  void append(std::uint64_t count, std::span<const std::byte> encoded_blocks);
  std::uint64_t length() const { return log_.length(); }
  std::uint64_t bytes_written() const { return log_.bytes_appended(); }

 private:
  explicit BlockJournal(RecordLog log) : log_(std::move(log)) {}
  RecordLog log_;
};

// Calls visit(block) for every block in the journal's first `length` bytes, in order. Throws InputError
// naming the file when it is shorter than that, belongs to another job text, or holds anything that is
// not a block of the layout.
void replay_block_journal(const std::string& path, const std::string& job_text, const BlockCodec& codec,
                          std::uint64_t length, const std::function<void(Block)>& visit);

}  // namespace pbrfit::store
