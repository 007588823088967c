#include "texture_test_support.hpp"

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include <Imath/half.h>

#include "scratch_directory.hpp"

namespace pbrfit::texture::testing {
namespace {

// splitmix64: a deterministic stream of 64-bit numbers.
struct Stream {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double unit() { return double(next() >> 11) * 0x1p-53; }
};

const double awkward_values[] = {0.0,
                                 -0.0,
                                 1.0,
                                 -1.0,
                                 0.1,
                                 1.0 / 3.0,
                                 65504.0,
                                 65519.0,
                                 65520.0,
                                 1e30,
                                 -1e30,
                                 1e-8,
                                 6e-8,
                                 2.9e-8,
                                 5.96e-8,
                                 6.103515625e-05,
                                 1.0 + 0x1p-11,
                                 1.0 + 3 * 0x1p-11,
                                 -(2.0 + 0x1p-10),
                                 1e-40,
                                 1e-45,
                                 3.4028234663852886e38,
                                 0.5 + 0x1p-25,
                                 0.5 + 0x1p-26,
                                 1.0 + 0x1p-24,
                                 1.0 + 0x1p-24 + 0x1p-50,
                                 123456.789,
                                 -0.000244140625};
const double moderate_values[] = {0.0,
                                  -0.0,
                                  1.0,
                                  -1.0,
                                  0.1,
                                  1.0 / 3.0,
                                  65504.0,
                                  6e-8,
                                  1.0 + 0x1p-11,
                                  1.0 + 3 * 0x1p-11,
                                  -(2.0 + 0x1p-10),
                                  1e-40,
                                  0.5 + 0x1p-25,
                                  3.14159265358979};
const double positive_values[] = {0.0, 1.0, 0.1, 1.0 / 3.0, 65504.0, 1e-30, 1e-33, 1e30, 0.75, 255.5, 256.0};

template <std::size_t N>
double pick(Stream& s, const double (&fixed)[N], double low_exponent, double high_exponent, bool negative) {
  if (s.next() % 3 == 0) return fixed[s.next() % N];
  const double exponent = low_exponent + (high_exponent - low_exponent) * s.unit();
  const double v = (1.0 + s.unit()) * std::exp2(std::floor(exponent));
  return negative && s.next() % 2 ? -v : v;
}

}  // namespace

Texture sample(std::size_t width, std::size_t height, std::size_t channels, Values kind, std::size_t depth,
               std::size_t layers, std::size_t levels, unsigned seed) {
  Texture t;
  t.name = "sample " + std::to_string(width) + "x" + std::to_string(height);
  t.width = width, t.height = height, t.depth = depth, t.layers = layers, t.levels = levels;
  const char* names[] = {"R", "G", "B", "A"};
  t.channels.assign(names, names + channels);
  t.values.resize(level_offset(t, levels, 0));
  Stream s{seed};
  for (double& v : t.values) {
    switch (kind) {
      case Values::awkward: v = pick(s, awkward_values, -40, 40, true); break;
      case Values::moderate: v = pick(s, moderate_values, -20, 15, true); break;
      case Values::positive: v = pick(s, positive_values, -40, 40, false); break;
    }
  }
  return t;
}

std::uint32_t f32_bits(double v) { return std::bit_cast<std::uint32_t>(static_cast<float>(v)); }
std::uint16_t f16_bits(double v) { return Imath::half(static_cast<float>(v)).bits(); }
float f16_value(double v) { return float(Imath::half(static_cast<float>(v))); }

std::uint16_t u16(const Bytes& b, std::size_t at) {
  return std::uint16_t(std::uint16_t(b.at(at)) | std::uint16_t(b.at(at + 1)) << 8);
}
std::uint32_t u32(const Bytes& b, std::size_t at) {
  return std::uint32_t(u16(b, at)) | std::uint32_t(u16(b, at + 2)) << 16;
}
std::uint64_t u64(const Bytes& b, std::size_t at) {
  return std::uint64_t(u32(b, at)) | std::uint64_t(u32(b, at + 4)) << 32;
}
std::string text(const Bytes& b, std::size_t at, std::size_t length) {
  std::string out;
  for (std::size_t k = 0; k < length; ++k) out += char(b.at(at + k));
  return out;
}

namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

std::filesystem::path scratch(const std::string& name) {
  static const ScratchDirectory directory("pbrfit-texture-tests");
  return directory.path() / name;
}

void write_file(const std::filesystem::path& path, const Bytes& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

bool tool_available(const std::string& tool) {
  return std::system(("command -v " + tool + " > /dev/null 2>&1").c_str()) == 0;
}

std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

RunResult run(const std::string& command) {
  static int count = 0;
  const auto out = scratch("run-" + std::to_string(++count) + ".out"),
             err = scratch("run-" + std::to_string(count) + ".err");
  const int raw =
      std::system((command + " > " + shell_quoted(out.string()) + " 2> " + shell_quoted(err.string())).c_str());
  RunResult result;
  result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  result.output = read_text(out);
  result.errors = read_text(err);
  return result;
}

}  // namespace pbrfit::texture::testing
