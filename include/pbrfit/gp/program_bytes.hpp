#pragma once
// Programs, individuals, populations and archive entries as bytes (core/bytes.hpp), so an island's epoch
// can be carried between ranks and checkpoints: everything it needs is (these bytes, the dataset, the
// options, a random stream key).
//
// Format (little-endian): each top-level buffer starts with a 4-byte tag and a format version; a program
// is its length (u8) and, per instruction, the opcode (u8) and per operand the source (u8) with an index
// (u16) or a constant (f64); a fitness is error, cost, piecewise (f64) and evaluated (u8); an individual
// adds its birth generation (u64); a population is its generation and stall counters (u64) and members. Only the
// canonical form is written, so equal values give equal bytes.
//
// Contract: reading validates everything it reads and throws ByteFormatError (never crashes, never
// returns an invalid program) on a wrong tag or version, an early end, trailing bytes, an unknown opcode
// or source, a reference to a later instruction, an input index >= input_count, a non-finite constant or
// an implausible fitness or count.
#include <cstddef>
#include <span>
#include <vector>

#include "pbrfit/core/bytes.hpp"
#include "pbrfit/gp/pareto.hpp"
#include "pbrfit/gp/population.hpp"
#include "pbrfit/gp/program.hpp"

namespace pbrfit::gp {

void write_program(ByteWriter& out, const Program& program);
Program read_program(ByteReader& in, std::size_t input_count);
void write_individual(ByteWriter& out, const Individual& individual);
Individual read_individual(ByteReader& in, std::size_t input_count);

Bytes program_to_bytes(const Program& program);
Program program_from_bytes(std::span<const std::byte> bytes, std::size_t input_count);

Bytes population_to_bytes(const Population& population);
Population population_from_bytes(std::span<const std::byte> bytes, std::size_t input_count);

// Migrants and emigrants.
Bytes individuals_to_bytes(std::span<const Individual> individuals);
std::vector<Individual> individuals_from_bytes(std::span<const std::byte> bytes, std::size_t input_count);

Bytes archive_to_bytes(std::span<const ArchiveEntry> entries);
std::vector<ArchiveEntry> archive_from_bytes(std::span<const std::byte> bytes, std::size_t input_count);

}  // namespace pbrfit::gp
