#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <filesystem>
#include <fstream>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/atomic_file.hpp"
#include "pbrfit/store/checkpoint_file.hpp"
#include "store_test_paths.hpp"

using namespace pbrfit;
using Catch::Matchers::ContainsSubstring;
using Catch::Matchers::StartsWith;

namespace {

constexpr std::uint64_t any_size = std::uint64_t(1) << 30;

store::CheckpointState sample() {
  store::CheckpointState s;
  s.job_text = "name: x\nkind: lut\n";
  s.stage = 1;
  s.elapsed_seconds = 12.5;
  s.summary = Bytes{std::byte{9}};
  s.rows = {4, 0};
  s.journal_length = 100;
  s.retained[{0, 3}] = Bytes{std::byte{1}, std::byte{2}};
  s.done = {5};
  s.retained[{1, 5}] = Bytes{};
  s.appends[5] = Bytes{std::byte{7}};
  return s;
}

store::CheckpointProgress more() {
  return {20.0, Bytes{std::byte{10}}, {6, 1}, 180, {{2, Bytes{std::byte{3}}, {}}, {0, std::nullopt, Bytes{std::byte{8}}}}};
}

void write_bytes(const std::string& path, const Bytes& bytes) {
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

void check_sample(const store::CheckpointState& s) {
  CHECK(s.job_text == sample().job_text);
  CHECK(s.stage == 1);
  CHECK(s.elapsed_seconds == 12.5);
  CHECK(s.summary == sample().summary);
  CHECK(s.rows == sample().rows);
  CHECK(s.journal_length == 100);
  CHECK(s.retained == sample().retained);
  CHECK(s.done == sample().done);
  CHECK(s.appends == sample().appends);
}

}  // namespace

TEST_CASE("a snapshot and the progress appended after it read back as one state") {
  const auto path = temporary_path("roundtrip.checkpoint");
  store::CheckpointFile file(path);
  file.write_snapshot(sample());
  check_sample(store::read_checkpoint(path).state);

  file.append(more());
  const auto reading = store::read_checkpoint(path);
  CHECK_FALSE(reading.torn_tail);
  CHECK(reading.valid_length == std::filesystem::file_size(path));
  const auto& s = reading.state;
  CHECK(s.elapsed_seconds == 20.0);
  CHECK(s.summary == Bytes{std::byte{10}});
  CHECK(s.rows == std::vector<std::uint64_t>{6, 1});
  CHECK(s.journal_length == 180);
  CHECK(s.done == std::vector<std::uint64_t>{5, 2, 0});
  CHECK(s.retained.at({1, 2}) == Bytes{std::byte{3}});
  CHECK_FALSE(s.retained.contains({1, 0}));
  CHECK(s.appends.at(0) == Bytes{std::byte{8}});
  CHECK_FALSE(temporary_left_beside(path));
}

TEST_CASE("a checkpoint cut short in its last record falls back to the record before; earlier damage is refused") {
  const auto path = temporary_path("torn.checkpoint");
  store::CheckpointFile file(path);
  file.write_snapshot(sample());
  const auto snapshot_end = std::filesystem::file_size(path);
  file.append(more());
  const Bytes good = store::read_whole_file(path, any_size);
  const auto damaged = temporary_path("torn-copy.checkpoint");

  for (std::size_t cut = snapshot_end; cut < good.size(); ++cut) {
    write_bytes(damaged, Bytes(good.begin(), good.begin() + std::ptrdiff_t(cut)));
    const auto reading = store::read_checkpoint(damaged);
    CHECK(reading.torn_tail == (cut > snapshot_end));
    CHECK(reading.valid_length == snapshot_end);
    check_sample(reading.state);
  }
  for (std::size_t cut = 0; cut < snapshot_end; ++cut) {
    write_bytes(damaged, Bytes(good.begin(), good.begin() + std::ptrdiff_t(cut)));
    REQUIRE_THROWS_WITH(store::read_checkpoint(damaged), StartsWith(damaged + ": error: damaged checkpoint"));
  }
  for (std::size_t i = 0; i < snapshot_end; ++i) {
    Bytes flipped = good;
    flipped[i] ^= std::byte{0x40};
    write_bytes(damaged, flipped);
    REQUIRE_THROWS_AS(store::read_checkpoint(damaged), InputError);
  }
}

TEST_CASE("checkpoints of another format version, or records that make no sense, are refused") {
  const auto path = temporary_path("version.checkpoint");
  store::CheckpointFile(path).write_snapshot(sample());
  Bytes bytes = store::read_whole_file(path, any_size);
  bytes[8] = std::byte{1};  // format version 1: the whole-file checkpoints of earlier releases
  write_bytes(path, bytes);
  REQUIRE_THROWS_WITH(store::read_checkpoint(path), ContainsSubstring("format version 1 (this pbrfit reads version 2)"));

  auto bad = sample();
  bad.retained[{7, 0}] = Bytes{};  // a kept result of a later stage than the checkpoint's
  store::CheckpointFile(path).write_snapshot(bad);
  REQUIRE_THROWS_WITH(store::read_checkpoint(path), ContainsSubstring("later stage"));
}

TEST_CASE("a missing checkpoint is an input error naming it") {
  REQUIRE_THROWS_WITH(store::read_checkpoint(temporary_path("absent.checkpoint")),
                      ContainsSubstring("absent.checkpoint: error: cannot read file"));
}

TEST_CASE("atomic replacement leaves the new content and no temporary file") {
  const auto path = temporary_path("atomic.bin");
  store::replace_file_atomically(path, Bytes{std::byte{1}});
  store::replace_file_atomically(path, Bytes{std::byte{2}, std::byte{3}});
  CHECK(store::read_whole_file(path, 10) == Bytes{std::byte{2}, std::byte{3}});
  CHECK_FALSE(temporary_left_beside(path));
}

TEST_CASE("only regular files of bounded size are read whole") {
  const auto path = temporary_path("limit.bin");
  write_bytes(path, Bytes(100));
  CHECK(store::read_whole_file(path, 100).size() == 100);
  REQUIRE_THROWS_WITH(store::read_whole_file(path, 99), ContainsSubstring("is too large (100 bytes; at most 99"));
  REQUIRE_THROWS_WITH(store::read_whole_file(temporary_path(""), 10), ContainsSubstring("is a directory"));
  REQUIRE_THROWS_WITH(store::read_whole_file("/dev/zero", 10), ContainsSubstring("is not a regular file"));
}
