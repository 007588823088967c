#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <filesystem>
#include <fstream>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/atomic_file.hpp"
#include "pbrfit/store/checkpoint_file.hpp"

using namespace pbrfit;
using Catch::Matchers::ContainsSubstring;
using Catch::Matchers::StartsWith;

namespace {

std::string temporary_path(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "pbrfit-store-tests";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

store::Checkpoint sample() {
  store::Checkpoint c;
  c.job_text = "name: x\nkind: lut\n";
  c.stage = 1;
  c.elapsed_seconds = 12.5;
  c.results[{0, 3}] = Bytes{std::byte{1}, std::byte{2}};
  c.results[{1, 0}] = Bytes{};
  return c;
}

void write_bytes(const std::string& path, const Bytes& bytes) {
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

}  // namespace

TEST_CASE("a checkpoint reads back exactly what was written") {
  const auto path = temporary_path("roundtrip.checkpoint");
  store::write_checkpoint(path, sample());
  const auto back = store::read_checkpoint(path);
  CHECK(back.job_text == sample().job_text);
  CHECK(back.stage == 1);
  CHECK(back.elapsed_seconds == 12.5);
  CHECK(back.results == sample().results);
  CHECK_FALSE(std::filesystem::exists(path + ".tmp"));
}

TEST_CASE("every truncation and every flipped byte of a checkpoint is rejected with the file named") {
  const auto path = temporary_path("damaged.checkpoint");
  store::write_checkpoint(path, sample());
  const Bytes good = store::read_whole_file(path);
  const auto damaged = temporary_path("damaged-copy.checkpoint");
  for (std::size_t cut = 0; cut < good.size(); ++cut) {
    write_bytes(damaged, Bytes(good.begin(), good.begin() + std::ptrdiff_t(cut)));
    REQUIRE_THROWS_WITH(store::read_checkpoint(damaged), StartsWith(damaged + ": error: corrupt checkpoint at byte"));
  }
  for (std::size_t i = 0; i < good.size(); ++i) {
    Bytes flipped = good;
    flipped[i] ^= std::byte{0x40};
    write_bytes(damaged, flipped);
    REQUIRE_THROWS_AS(store::read_checkpoint(damaged), InputError);
  }
}

TEST_CASE("a missing checkpoint is an input error naming it") {
  REQUIRE_THROWS_WITH(store::read_checkpoint(temporary_path("absent.checkpoint")),
                      ContainsSubstring("absent.checkpoint: error: cannot read file"));
}

TEST_CASE("atomic replacement leaves the new content and no temporary file") {
  const auto path = temporary_path("atomic.bin");
  store::replace_file_atomically(path, Bytes{std::byte{1}});
  store::replace_file_atomically(path, Bytes{std::byte{2}, std::byte{3}});
  CHECK(store::read_whole_file(path) == Bytes{std::byte{2}, std::byte{3}});
  CHECK_FALSE(std::filesystem::exists(path + ".tmp"));
}
