#pragma once
// What the texture tests share: textures with awkward values, the reference conversions (the double -> float
// cast, Imath's half), little-endian reads, a scratch directory per process, and child processes (Python,
// node, glslangValidator, the compiler) run with their output captured.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "pbrfit/core/bytes.hpp"
#include "pbrfit/texture/texture.hpp"

namespace pbrfit::texture::testing {

enum class Values {
  awkward,   // zeros of both signs, half ties, half subnormals and overflows, float subnormals, wide exponents
  moderate,  // finite in half precision: |v| < 60000, signs, wide exponents
  positive,  // >= 0 and finite (Radiance HDR), zeros and tiny values included
};

// A texture with channels R, G, B, A (the first `channels`), sizes as given, values by kind, seeded.
Texture sample(std::size_t width, std::size_t height, std::size_t channels, Values kind = Values::awkward,
               std::size_t depth = 1, std::size_t layers = 1, std::size_t levels = 1, unsigned seed = 1);

std::uint32_t f32_bits(double v);  // bit_cast of static_cast<float>(v)
std::uint16_t f16_bits(double v);  // Imath::half(static_cast<float>(v)).bits()
float f16_value(double v);         // the float equal to that half

std::uint16_t u16(const Bytes& b, std::size_t at);
std::uint32_t u32(const Bytes& b, std::size_t at);
std::uint64_t u64(const Bytes& b, std::size_t at);
std::string text(const Bytes& b, std::size_t at, std::size_t length);

// pbrfit-texture-tests-PID under the temporary directory, removed when the process ends.
std::filesystem::path scratch(const std::string& name);
void write_file(const std::filesystem::path& path, const Bytes& bytes);
void write_file(const std::filesystem::path& path, const std::string& text);
bool tool_available(const std::string& tool);

struct RunResult {
  int status = -1;     // the exit status, -1 when it did not exit normally
  std::string output;  // stdout
  std::string errors;  // stderr
};
RunResult run(const std::string& command);
std::string shell_quoted(const std::string& text);

}  // namespace pbrfit::texture::testing
