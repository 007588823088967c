#include <catch2/catch_test_macros.hpp>
#include <cstddef>
#include <cstring>
#include <limits>
#include <vector>

#include "gp_test_support.hpp"
#include "pbrfit/gp/program_builder.hpp"
#include "pbrfit/gp/program_bytes.hpp"

using namespace pbrfit::gp;
using pbrfit::ByteFormatError;
using pbrfit::Bytes;

namespace {

Population sample_population(std::size_t size, std::uint64_t seed) {
  Population population;
  population.generation = 42;
  population.stalled = 3;
  for (std::size_t i = 0; i < size; ++i) {
    Individual member{gp_test::random_program(gp_test::wide_shape(3), seed, i), {}, i};
    if (i % 3 != 0) member.fitness = {0.5 * static_cast<double>(i), 3.0, 1.0, true};
    if (i == 4) member.fitness.error = worst_error;
    population.members.push_back(member);
  }
  return population;
}

// Either rejected with ByteFormatError or read as a valid population; anything else fails the test.
bool rejected_or_valid(const Bytes& bytes) {
  try {
    const Population population = population_from_bytes(bytes, 3);
    for (const Individual& member : population.members) {
      if (!is_valid(member.program, 3)) return false;
    }
    return true;
  } catch (const ByteFormatError&) {
    return true;
  }
}

Bytes program_bytes(std::initializer_list<unsigned> values) {
  Bytes bytes = program_to_bytes(ProgramBuilder().finish(input_argument(0)));
  bytes.resize(6);  // the header
  for (unsigned v : values) bytes.push_back(static_cast<std::byte>(v));
  return bytes;
}

}  // namespace

TEST_CASE("Programs, populations, migrants and archives round-trip through bytes", "[gp]") {
  const Population population = sample_population(30, 1);
  const Bytes bytes = population_to_bytes(population);
  CHECK(population_from_bytes(bytes, 3) == population);
  CHECK(population_to_bytes(population_from_bytes(bytes, 3)) == bytes);
  const auto migrants = individuals_from_bytes(individuals_to_bytes(population.members), 3);
  CHECK(migrants == population.members);
  for (const Individual& member : population.members)
    CHECK(program_from_bytes(program_to_bytes(member.program), 3) == member.program);
  std::vector<ArchiveEntry> archive{{population.members[1].program, population.members[1].fitness, 7}};
  const auto entries = archive_from_bytes(archive_to_bytes(archive), 3);
  REQUIRE(entries.size() == 1);
  CHECK(entries[0].program == archive[0].program);
  CHECK(entries[0].generation == 7);
}

TEST_CASE("Truncated or corrupted bytes are rejected, never read as an invalid program", "[gp]") {
  const Bytes bytes = population_to_bytes(sample_population(4, 2));
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    const Bytes truncated(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(length));
    CHECK_THROWS_AS(population_from_bytes(truncated, 3), ByteFormatError);
  }
  Bytes longer = bytes;
  longer.push_back(std::byte{0});
  CHECK_THROWS_AS(population_from_bytes(longer, 3), ByteFormatError);
  for (std::size_t at = 0; at < bytes.size(); ++at) {
    for (unsigned flip : {0x01u, 0x10u, 0x80u, 0xffu}) {
      Bytes corrupted = bytes;
      corrupted[at] ^= static_cast<std::byte>(flip);
      CAPTURE(at, flip);
      CHECK(rejected_or_valid(corrupted));
    }
  }
  // Programs read for fewer inputs than they use are rejected.
  CHECK_THROWS_AS(population_from_bytes(bytes, 1), ByteFormatError);
}

TEST_CASE("Crafted programs are rejected with a reason", "[gp]") {
  // length, then per instruction: opcode, then per operand: source and index (u16) or constant (f64).
  const unsigned add = static_cast<unsigned>(Opcode::add);
  const unsigned sin = static_cast<unsigned>(Opcode::sin);
  const unsigned input = static_cast<unsigned>(Source::input);
  const unsigned result = static_cast<unsigned>(Source::instruction);
  CHECK(program_from_bytes(program_bytes({1, sin, input, 0, 0}), 1).length == 1);                  // well formed
  CHECK_THROWS_AS(program_from_bytes(program_bytes({0}), 1), ByteFormatError);                     // empty
  CHECK_THROWS_AS(program_from_bytes(program_bytes({65}), 1), ByteFormatError);                    // too long
  CHECK_THROWS_AS(program_from_bytes(program_bytes({1, 200, input, 0, 0}), 1), ByteFormatError);   // opcode
  CHECK_THROWS_AS(program_from_bytes(program_bytes({1, sin, 9, 0, 0}), 1), ByteFormatError);       // source
  CHECK_THROWS_AS(program_from_bytes(program_bytes({1, sin, input, 1, 0}), 1), ByteFormatError);   // input 1
  CHECK_THROWS_AS(program_from_bytes(program_bytes({1, sin, result, 0, 0}), 1), ByteFormatError);  // self
  CHECK_THROWS_AS(program_from_bytes(program_bytes({2, sin, input, 0, 0, add, result, 1, 0, input, 0, 0}), 1),
                  ByteFormatError);  // a forward reference
  Bytes nan_constant = program_bytes({1, sin, static_cast<unsigned>(Source::constant)});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto* raw = reinterpret_cast<const std::byte*>(&nan);
  nan_constant.insert(nan_constant.end(), raw, raw + sizeof(double));
  CHECK_THROWS_AS(program_from_bytes(nan_constant, 1), ByteFormatError);
  Bytes wrong_tag = program_bytes({1, sin, input, 0, 0});
  wrong_tag[0] ^= std::byte{1};
  CHECK_THROWS_AS(program_from_bytes(wrong_tag, 1), ByteFormatError);
}

TEST_CASE("A crafted member count cannot make the reader allocate beyond the data", "[gp]") {
  Bytes bytes = population_to_bytes(sample_population(1, 3));
  const std::uint64_t absurd = std::numeric_limits<std::uint64_t>::max() / 2;
  std::memcpy(bytes.data() + 6 + 16, &absurd, sizeof absurd);  // after the header and the two counters
  CHECK_THROWS_AS(population_from_bytes(bytes, 3), ByteFormatError);
}
