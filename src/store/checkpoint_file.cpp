#include "pbrfit/store/checkpoint_file.hpp"

#include "pbrfit/core/error.hpp"

namespace pbrfit::store {

namespace {

const LogFormat checkpoint_format{{'P', 'B', 'R', 'F', 'I', 'T', 'C', 'K'}, 2, "checkpoint"};
enum RecordKind : std::uint8_t { snapshot = 1, progress = 2 };
enum ItemFlags : std::uint8_t { has_retained = 1, has_appends = 2 };

void put_common(ByteWriter& out, double elapsed, const Bytes& summary, const std::vector<std::uint64_t>& rows,
                std::uint64_t journal_length) {
  out.put(elapsed);
  out.put_bytes(summary);
  out.put_array(std::span<const std::uint64_t>(rows));
  out.put(journal_length);
}

void get_common(ByteReader& in, CheckpointState& s) {
  s.elapsed_seconds = in.get<double>();
  s.summary = in.get_bytes();
  s.rows = in.get_array<std::uint64_t>();
  s.journal_length = in.get<std::uint64_t>();
}

Bytes encode_snapshot(const CheckpointState& s) {
  ByteWriter out;
  out.put(snapshot);
  out.put_string(s.job_text);
  out.put(s.stage);
  put_common(out, s.elapsed_seconds, s.summary, s.rows, s.journal_length);
  out.put<std::uint64_t>(s.retained.size());
  for (const auto& [id, result] : s.retained) {
    out.put(id.stage);
    out.put(id.item);
    out.put_bytes(result);
  }
  out.put_array(std::span<const std::uint64_t>(s.done));
  out.put<std::uint64_t>(s.appends.size());
  for (const auto& [item, appends] : s.appends) {
    out.put(item);
    out.put_bytes(appends);
  }
  return out.take();
}

Bytes encode_progress(const CheckpointProgress& p) {
  ByteWriter out;
  out.put(progress);
  put_common(out, p.elapsed_seconds, p.summary, p.rows, p.journal_length);
  out.put<std::uint64_t>(p.finished.size());
  for (const auto& f : p.finished) {
    out.put(f.item);
    out.put(std::uint8_t((f.retained ? has_retained : 0) | (f.appends.empty() ? 0 : has_appends)));
    if (f.retained) out.put_bytes(*f.retained);
    if (!f.appends.empty()) out.put_bytes(f.appends);
  }
  return out.take();
}

void apply_snapshot(ByteReader& in, CheckpointState& s) {
  s = CheckpointState{};
  s.job_text = in.get_string();
  s.stage = in.get<std::uint32_t>();
  get_common(in, s);
  const auto count = in.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < count; ++i) {
    const auto at = in.offset();
    WorkItemId id{in.get<std::uint32_t>(), in.get<std::uint64_t>()};
    if (id.stage > s.stage) throw ByteFormatError(at, "a kept result belongs to a later stage than the checkpoint's");
    s.retained[id] = in.get_bytes();
  }
  s.done = in.get_array<std::uint64_t>();
  const auto appends = in.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < appends; ++i) {
    const auto item = in.get<std::uint64_t>();
    s.appends[item] = in.get_bytes();
  }
}

void apply_progress(ByteReader& in, CheckpointState& s) {
  get_common(in, s);
  const auto count = in.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < count; ++i) {
    const auto item = in.get<std::uint64_t>();
    const auto flags = in.get<std::uint8_t>();
    if (flags & ~(has_retained | has_appends)) throw ByteFormatError(in.offset() - 1, "unknown item flags");
    s.done.push_back(item);
    if (flags & has_retained) s.retained[{s.stage, item}] = in.get_bytes();
    if (flags & has_appends) s.appends[item] = in.get_bytes();
  }
}

}  // namespace

std::string checkpoint_path_for(const std::string& result_path) { return result_path + ".checkpoint"; }
std::string journal_path_for(const std::string& result_path) { return result_path + ".journal"; }

void CheckpointFile::write_snapshot(const CheckpointState& state) {
  const Bytes record = encode_snapshot(state);
  log_.reset();
  log_ = RecordLog::create(path_, checkpoint_format, std::span(&record, 1));
  written_ += log_->length();
}

void CheckpointFile::continue_after(std::uint64_t valid_length) { log_ = RecordLog::reopen(path_, valid_length); }

void CheckpointFile::append(const CheckpointProgress& p) {
  const std::uint64_t before = log_->bytes_appended();
  log_->append(encode_progress(p));
  written_ += log_->bytes_appended() - before;
}

CheckpointReading read_checkpoint(const std::string& path) {
  CheckpointReading reading;
  bool first = true;
  const auto visit = [&](std::span<const std::byte> payload, std::uint64_t) {
    ByteReader in(payload);
    const auto kind = in.get<std::uint8_t>();
    if (first != (kind == snapshot)) throw ByteFormatError(0, first ? "does not start with a snapshot" : "a second snapshot");
    if (kind == snapshot) apply_snapshot(in, reading.state);
    else if (kind == progress) apply_progress(in, reading.state);
    else throw ByteFormatError(0, "unknown record kind " + std::to_string(kind));
    if (in.remaining() != 0) throw ByteFormatError(in.offset(), "unexpected data after the record");
    first = false;
  };
  const LogReading log = read_record_log(path, checkpoint_format, visit);
  if (first) throw InputError({path}, "damaged checkpoint: it holds no snapshot");
  reading.valid_length = log.valid_length;
  reading.torn_tail = log.torn_tail;
  return reading;
}

}  // namespace pbrfit::store
