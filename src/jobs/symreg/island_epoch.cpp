#include "pbrfit/jobs/symreg/island_epoch.hpp"

#include "pbrfit/core/error.hpp"
#include "pbrfit/gp/program_bytes.hpp"

namespace pbrfit::jobs::symreg {
namespace {

void write_state(ByteWriter& out, const IslandState& state) {
  out.put_bytes(gp::population_to_bytes(state.population));
  out.put_bytes(gp::archive_to_bytes(state.front));
  out.put(std::uint8_t(state.reached_target));
}

IslandState read_state(ByteReader& in, std::size_t inputs) {
  IslandState state;
  state.population = gp::population_from_bytes(in.get_bytes(), inputs);
  state.front = gp::archive_from_bytes(in.get_bytes(), inputs);
  state.reached_target = in.get<std::uint8_t>() != 0;
  return state;
}

template <class Read>
auto decoded(std::span<const std::byte> bytes, const char* what, Read&& read) {
  try {
    ByteReader in(bytes);
    auto value = read(in);
    if (in.remaining() != 0) throw ByteFormatError(in.offset(), "trailing bytes");
    return value;
  } catch (const ByteFormatError& e) {
    throw RunError(std::string("a symbolic-regression ") + what + " is damaged: " + e.what());
  }
}

}  // namespace

Bytes encode_epoch(const IslandEpoch& epoch) {
  ByteWriter out;
  write_state(out, epoch.state);
  out.put_bytes(gp::archive_to_bytes(epoch.additions));
  out.put_varint(epoch.evaluations);
  out.put(epoch.best_error);
  return out.take();
}

IslandEpoch decode_epoch(std::span<const std::byte> bytes, std::size_t inputs) {
  return decoded(bytes, "island epoch", [&](ByteReader& in) {
    IslandEpoch epoch;
    epoch.state = read_state(in, inputs);
    epoch.additions = gp::archive_from_bytes(in.get_bytes(), inputs);
    epoch.evaluations = in.get_varint();
    epoch.best_error = in.get<double>();
    return epoch;
  });
}

Bytes encode_input(const EpochInput& input) {
  ByteWriter out;
  out.put(std::uint8_t(input.has_state));
  if (input.has_state) write_state(out, input.state);
  out.put_bytes(gp::individuals_to_bytes(input.migrants));
  out.put(std::uint8_t(input.solved));
  return out.take();
}

EpochInput decode_input(std::span<const std::byte> bytes, std::size_t inputs) {
  return decoded(bytes, "island input", [&](ByteReader& in) {
    EpochInput input;
    input.has_state = in.get<std::uint8_t>() != 0;
    if (input.has_state) input.state = read_state(in, inputs);
    input.migrants = gp::individuals_from_bytes(in.get_bytes(), inputs);
    input.solved = in.get<std::uint8_t>() != 0;
    return input;
  });
}

}  // namespace pbrfit::jobs::symreg
