#include "pbrfit/gp/program_bytes.hpp"

#include <cmath>
#include <cstdint>

namespace pbrfit::gp {
namespace {

constexpr std::uint32_t program_tag = 0x31505047;     // "GPP1"
constexpr std::uint32_t population_tag = 0x31535047;  // "GPS1"
constexpr std::uint32_t migrants_tag = 0x314d5047;    // "GPM1"
constexpr std::uint32_t archive_tag = 0x31415047;     // "GPA1"
constexpr std::uint16_t format_version = 1;
constexpr std::size_t smallest_individual = 1 + 1 + 1 + 2 + 3 * 8 + 1 + 8;  // bytes, to bound counts

[[noreturn]] void reject(const ByteReader& in, const char* what) { throw ByteFormatError(in.offset(), what); }

void write_header(ByteWriter& out, std::uint32_t tag) {
  out.put(tag);
  out.put(format_version);
}

void read_header(ByteReader& in, std::uint32_t tag) {
  if (in.get<std::uint32_t>() != tag) reject(in, "not the expected kind of GP data");
  if (in.get<std::uint16_t>() != format_version) reject(in, "unsupported GP data version");
}

void read_end(const ByteReader& in) {
  if (in.remaining() != 0) reject(in, "trailing bytes after GP data");
}

std::size_t read_count(ByteReader& in, std::size_t smallest_item) {
  const auto count = in.get<std::uint64_t>();
  if (count > in.remaining() / smallest_item) reject(in, "count exceeds the data");
  return static_cast<std::size_t>(count);
}

Operand read_operand(ByteReader& in, std::size_t position, std::size_t input_count, double& constant) {
  const auto source = in.get<std::uint8_t>();
  if (source == static_cast<std::uint8_t>(Source::constant)) {
    constant = in.get<double>();
    if (!std::isfinite(constant)) reject(in, "a constant that is not finite");
    return constant_operand();
  }
  const auto index = in.get<std::uint16_t>();
  if (source == static_cast<std::uint8_t>(Source::input) && index < input_count) return input_operand(index);
  if (source == static_cast<std::uint8_t>(Source::instruction) && index < position) return result_operand(index);
  reject(in, "an operand with an invalid source or index");
}

void write_fitness(ByteWriter& out, const Fitness& fitness) {
  out.put(fitness.error);
  out.put(fitness.cost);
  out.put(fitness.piecewise);
  out.put(std::uint8_t(fitness.evaluated));
}

Fitness read_fitness(ByteReader& in) {
  Fitness fitness;
  fitness.error = in.get<double>();
  fitness.cost = in.get<double>();
  fitness.piecewise = in.get<double>();
  const auto evaluated = in.get<std::uint8_t>();
  const bool plausible = evaluated <= 1 && fitness.error >= 0.0 && std::isfinite(fitness.cost) && fitness.cost >= 0.0 &&
                         std::isfinite(fitness.piecewise) && fitness.piecewise >= 0.0;
  if (!plausible) reject(in, "an implausible fitness");
  fitness.evaluated = evaluated == 1;
  if (!fitness.evaluated && !(fitness == Fitness{})) reject(in, "an unevaluated fitness with values");
  return fitness;
}

}  // namespace

void write_program(ByteWriter& out, const Program& program) {
  out.put(std::uint8_t(program.length));
  for (const Instruction& instruction : program.instructions()) {
    out.put(static_cast<std::uint8_t>(instruction.op));
    for (int j = 0; j < arity(instruction.op); ++j) {
      out.put(static_cast<std::uint8_t>(instruction.operands[j].source));
      if (instruction.operands[j].source == Source::constant) {
        out.put(instruction.constants[j]);
      } else {
        out.put(instruction.operands[j].index);
      }
    }
  }
}

Program read_program(ByteReader& in, std::size_t input_count) {
  Program program;
  const auto length = in.get<std::uint8_t>();
  if (length < 1 || length > max_program_length) reject(in, "a program length out of range");
  for (std::size_t i = 0; i < length; ++i) {
    const auto op = in.get<std::uint8_t>();
    if (!is_valid_opcode(op)) reject(in, "an unknown opcode");
    Instruction& instruction = program.code[i];
    instruction.op = static_cast<Opcode>(op);
    for (int j = 0; j < arity(instruction.op); ++j) {
      instruction.operands[j] = read_operand(in, i, input_count, instruction.constants[j]);
    }
  }
  program.length = length;
  return program;
}

void write_individual(ByteWriter& out, const Individual& individual) {
  write_program(out, individual.program);
  write_fitness(out, individual.fitness);
  out.put(individual.born);
}

Individual read_individual(ByteReader& in, std::size_t input_count) {
  Individual individual;
  individual.program = read_program(in, input_count);
  individual.fitness = read_fitness(in);
  individual.born = in.get<std::uint64_t>();
  return individual;
}

Bytes program_to_bytes(const Program& program) {
  ByteWriter out;
  write_header(out, program_tag);
  write_program(out, program);
  return out.take();
}

Program program_from_bytes(std::span<const std::byte> bytes, std::size_t input_count) {
  ByteReader in(bytes);
  read_header(in, program_tag);
  Program program = read_program(in, input_count);
  read_end(in);
  return program;
}

Bytes population_to_bytes(const Population& population) {
  ByteWriter out;
  write_header(out, population_tag);
  out.put(population.generation);
  out.put(population.stalled);
  out.put(std::uint64_t(population.members.size()));
  for (const Individual& member : population.members) write_individual(out, member);
  return out.take();
}

Population population_from_bytes(std::span<const std::byte> bytes, std::size_t input_count) {
  ByteReader in(bytes);
  read_header(in, population_tag);
  Population population;
  population.generation = in.get<std::uint64_t>();
  population.stalled = in.get<std::uint64_t>();
  population.members.resize(read_count(in, smallest_individual));
  for (Individual& member : population.members) member = read_individual(in, input_count);
  read_end(in);
  return population;
}

Bytes individuals_to_bytes(std::span<const Individual> individuals) {
  ByteWriter out;
  write_header(out, migrants_tag);
  out.put(std::uint64_t(individuals.size()));
  for (const Individual& individual : individuals) write_individual(out, individual);
  return out.take();
}

std::vector<Individual> individuals_from_bytes(std::span<const std::byte> bytes, std::size_t input_count) {
  ByteReader in(bytes);
  read_header(in, migrants_tag);
  std::vector<Individual> individuals(read_count(in, smallest_individual));
  for (Individual& individual : individuals) individual = read_individual(in, input_count);
  read_end(in);
  return individuals;
}

Bytes archive_to_bytes(std::span<const ArchiveEntry> entries) {
  ByteWriter out;
  write_header(out, archive_tag);
  out.put(std::uint64_t(entries.size()));
  for (const ArchiveEntry& entry : entries) write_individual(out, {entry.program, entry.fitness, entry.generation});
  return out.take();
}

std::vector<ArchiveEntry> archive_from_bytes(std::span<const std::byte> bytes, std::size_t input_count) {
  ByteReader in(bytes);
  read_header(in, archive_tag);
  std::vector<ArchiveEntry> entries(read_count(in, smallest_individual));
  for (ArchiveEntry& entry : entries) {
    Individual individual = read_individual(in, input_count);
    entry = {individual.program, individual.fitness, individual.born};
  }
  read_end(in);
  return entries;
}

}  // namespace pbrfit::gp
