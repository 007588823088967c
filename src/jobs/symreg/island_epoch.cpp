#include "pbrfit/jobs/symreg/island_epoch.hpp"

#include "pbrfit/core/decoded_record.hpp"
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

}  // namespace

// An epoch: [u8 reached_target][varint generation][bytes emigrants][bytes state][bytes additions]
// [varint evaluations][f64 best]; the state is [bytes population][bytes front][u8 reached_target].
Bytes encode_epoch(const IslandEpoch& epoch) {
  ByteWriter out, state;
  out.put(std::uint8_t(epoch.state.reached_target));
  out.put_varint(epoch.state.population.generation);
  out.put_bytes(gp::individuals_to_bytes(epoch.emigrants));
  write_state(state, epoch.state);
  out.put_bytes(state.bytes());
  out.put_bytes(gp::archive_to_bytes(epoch.additions));
  out.put_varint(epoch.evaluations);
  out.put(epoch.best_error);
  return out.take();
}

IslandEpoch decode_epoch(std::span<const std::byte> bytes, std::size_t inputs) {
  return decoded_record(bytes, "symbolic-regression island epoch", [&](ByteReader& in) {
    IslandEpoch epoch;
    const bool reached = in.get<std::uint8_t>() != 0;
    const std::uint64_t generation = in.get_varint();
    epoch.emigrants = gp::individuals_from_bytes(in.get_bytes(), inputs);
    const Bytes state = in.get_bytes();
    ByteReader state_in(state);
    epoch.state = read_state(state_in, inputs);
    if (state_in.remaining() != 0 || reached != epoch.state.reached_target || generation != epoch.state.population.generation)
      throw ByteFormatError(in.offset(), "inconsistent island state");
    epoch.additions = gp::archive_from_bytes(in.get_bytes(), inputs);
    epoch.evaluations = in.get_varint();
    epoch.best_error = in.get<double>();
    return epoch;
  });
}

EpochRecord decode_record(std::span<const std::byte> bytes, std::size_t inputs) {
  return decoded_record(bytes, "symbolic-regression island epoch", [&](ByteReader& in) {
    EpochRecord record;
    in.get<std::uint8_t>();
    record.generation = in.get_varint();
    in.get_bytes();  // emigrants
    const Bytes state = in.get_bytes();
    ByteReader state_in(state);
    state_in.get_bytes();  // the population, left undecoded
    record.front = gp::archive_from_bytes(state_in.get_bytes(), inputs);
    record.additions = gp::archive_from_bytes(in.get_bytes(), inputs);
    record.evaluations = in.get_varint();
    record.best_error = in.get<double>();
    return record;
  });
}

EpochBytes split_epoch(std::span<const std::byte> bytes) {
  return decoded_record(bytes, "symbolic-regression island epoch", [&](ByteReader& in) {
    EpochBytes parts;
    parts.reached_target = in.get<std::uint8_t>() != 0;
    in.get_varint();  // generation
    parts.emigrants = in.get_bytes();
    parts.state = in.get_bytes();
    in.get_bytes();  // additions
    in.get_varint();
    in.get<double>();
    return parts;
  });
}

Bytes next_input(const EpochBytes& own, const EpochBytes& neighbour, bool solved) {
  ByteWriter out;
  out.put(std::uint8_t(1));
  Bytes input = out.take();
  input.insert(input.end(), own.state.begin(), own.state.end());  // as write_state wrote it
  ByteWriter rest;
  rest.put_bytes(neighbour.emigrants);
  rest.put(std::uint8_t(solved));
  input.insert(input.end(), rest.bytes().begin(), rest.bytes().end());
  return input;
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
  return decoded_record(bytes, "symbolic-regression island input", [&](ByteReader& in) {
    EpochInput input;
    input.has_state = in.get<std::uint8_t>() != 0;
    if (input.has_state) input.state = read_state(in, inputs);
    input.migrants = gp::individuals_from_bytes(in.get_bytes(), inputs);
    input.solved = in.get<std::uint8_t>() != 0;
    return input;
  });
}

}  // namespace pbrfit::jobs::symreg
