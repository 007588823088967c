#include "pbrfit/store/block_journal.hpp"

#include "pbrfit/core/error.hpp"

namespace pbrfit::store {

namespace {

const LogFormat journal_format{{'P', 'B', 'R', 'F', 'I', 'T', 'B', 'J'}, 1, "block journal"};

}  // namespace

BlockJournal BlockJournal::create(const std::string& path, const std::string& job_text) {
  ByteWriter header;
  header.put_string(job_text);
  const Bytes record = header.take();
  return BlockJournal(RecordLog::create(path, journal_format, std::span(&record, 1)));
}

BlockJournal BlockJournal::reopen(const std::string& path, std::uint64_t length) {
  return BlockJournal(RecordLog::reopen(path, length));
}

void BlockJournal::append(std::uint64_t count, std::span<const std::byte> encoded_blocks) {
  ByteWriter record;
  record.put(count);
  Bytes bytes = record.take();
  bytes.insert(bytes.end(), encoded_blocks.begin(), encoded_blocks.end());
  log_.append(bytes);
}

void replay_block_journal(const std::string& path, const std::string& job_text, const BlockCodec& codec,
                          std::uint64_t length, const std::function<void(Block)>& visit) {
  bool first = true;
  const auto on_record = [&](std::span<const std::byte> payload, std::uint64_t) {
    ByteReader in(payload);
    if (first) {
      if (in.get_string() != job_text) throw InputError({path}, "this block journal belongs to a different job text");
      first = false;
    } else {
      const auto count = in.get<std::uint64_t>();
      for (std::uint64_t i = 0; i < count; ++i) visit(codec.decode(in));
    }
    if (in.remaining() != 0) throw ByteFormatError(in.offset(), "unexpected data after the blocks");
  };
  read_record_log(path, journal_format, on_record, length);
  if (first) throw InputError({path}, "damaged block journal: no job text");
}

}  // namespace pbrfit::store
