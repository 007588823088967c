// KTX2 byte by byte against the KTX 2.0 specification (header, index, level index with its offsets, lengths,
// alignment and order, the Data Format Descriptor, the key/value data), and read back by ktx-parse (npm) in
// node when it is installed in the build directory.
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <numeric>
#include <sstream>

#include "pbrfit/texture/ktx2.hpp"
#include "texture_test_support.hpp"

using namespace pbrfit;
using namespace pbrfit::texture;
using testing::u32;
using testing::u64;

namespace {

std::size_t component_bytes(Precision p) { return p == Precision::f32 ? 4 : 2; }

std::uint32_t expected_vk_format(std::size_t channels, Precision p) {
  // VK_FORMAT_R16_SFLOAT 76, R16G16 83, R16G16B16 90, R16G16B16A16 97, R32 100, R32G32 103, R32G32B32 106,
  // R32G32B32A32 109 (vulkan_core.h).
  const std::uint32_t half[] = {76, 83, 90, 97}, single[] = {100, 103, 106, 109};
  return (p == Precision::f32 ? single : half)[channels - 1];
}

std::map<std::string, std::string> key_values(const Bytes& b) {
  const std::size_t offset = u32(b, 56), length = u32(b, 60);
  std::map<std::string, std::string> entries;
  std::vector<std::string> order;
  for (std::size_t at = offset; at < offset + length;) {
    const std::size_t size = u32(b, at);
    const std::string entry = testing::text(b, at + 4, size);
    const std::size_t nul = entry.find('\0');
    REQUIRE(nul != std::string::npos);
    REQUIRE(entry.back() == '\0');  // string values are NUL-terminated
    order.push_back(entry.substr(0, nul));
    entries[entry.substr(0, nul)] = entry.substr(nul + 1, entry.size() - nul - 2);
    const std::size_t padding = (4 - size % 4) % 4;
    for (std::size_t k = 0; k < padding; ++k) CHECK(b.at(at + 4 + size + k) == std::byte(0));
    at += 4 + size + padding;
    CHECK(at <= offset + length);  // kvdByteLength counts every entry's padding
  }
  CHECK(std::is_sorted(order.begin(), order.end()));
  return entries;
}

void check_dfd(const Bytes& b, std::size_t channels, Precision p) {
  const std::size_t at = u32(b, 48), length = u32(b, 52);
  CHECK(at % 4 == 0);
  CHECK(length == 4 + 24 + 16 * channels);
  CHECK(u32(b, at) == length);                              // dfdTotalSize
  CHECK(u32(b, at + 4) == 0);                               // vendorId KHR 0, descriptorType basic 0
  CHECK(testing::u16(b, at + 8) == 2);                      // versionNumber KHR_DF_VERSIONNUMBER_1_3
  CHECK(testing::u16(b, at + 10) == 24 + 16 * channels);    // descriptorBlockSize
  CHECK(std::uint8_t(b[at + 12]) == 1);                     // colorModel KHR_DF_MODEL_RGBSDA
  CHECK(std::uint8_t(b[at + 13]) == 1);                     // colorPrimaries BT709
  CHECK(std::uint8_t(b[at + 14]) == 1);                     // transferFunction LINEAR (floats)
  CHECK(std::uint8_t(b[at + 15]) == 0);                     // flags ALPHA_STRAIGHT
  CHECK(u32(b, at + 16) == 0);                              // texelBlockDimension 1x1x1x1 (stored - 1)
  CHECK(u32(b, at + 20) == channels * component_bytes(p));  // bytesPlane0
  CHECK(u32(b, at + 24) == 0);                              // bytesPlane4..7
  const std::uint8_t ids[] = {0, 1, 2, 15};                 // KHR_DF_CHANNEL_RGBSDA_R, G, B, ALPHA
  for (std::size_t c = 0; c < channels; ++c) {
    const std::size_t s = at + 28 + 16 * c;
    const std::size_t bits = 8 * component_bytes(p);
    CHECK(testing::u16(b, s) == c * bits);                    // bitOffset
    CHECK(std::uint8_t(b[s + 2]) == bits - 1);                // bitLength
    CHECK(std::uint8_t(b[s + 3]) == (ids[c] | 0x40 | 0x80));  // channelType: id | SIGNED | FLOAT
    CHECK(u32(b, s + 4) == 0);                                // samplePosition
    CHECK(u32(b, s + 8) == 0xBF800000);                       // sampleLower -1.0f
    CHECK(u32(b, s + 12) == 0x3F800000);                      // sampleUpper 1.0f
  }
}

// Checks the whole file; returns the offset of each level's data.
std::vector<std::size_t> check_ktx2(const Bytes& b, const Texture& t, Precision p) {
  const std::uint8_t id[12] = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32, 0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
  for (std::size_t k = 0; k < 12; ++k) REQUIRE(std::uint8_t(b.at(k)) == id[k]);
  const std::size_t channels = t.channels.size();
  CHECK(u32(b, 12) == expected_vk_format(channels, p));
  CHECK(u32(b, 16) == component_bytes(p));  // typeSize
  CHECK(u32(b, 20) == t.width);
  CHECK(u32(b, 24) == (t.height == 1 && t.depth == 1 ? 0 : t.height));
  CHECK(u32(b, 28) == (t.depth > 1 ? t.depth : 0));
  CHECK(u32(b, 32) == (t.layers > 1 ? t.layers : 0));
  CHECK(u32(b, 36) == 1);  // faceCount
  CHECK(u32(b, 40) == t.levels);
  CHECK(u32(b, 44) == 0);                        // supercompressionScheme
  CHECK(u32(b, 48) == 80 + 24 * t.levels);       // the DFD follows the level index
  CHECK(u32(b, 56) == u32(b, 48) + u32(b, 52));  // the KVD follows the DFD
  CHECK(u64(b, 64) == 0);                        // sgdByteOffset
  CHECK(u64(b, 72) == 0);                        // sgdByteLength
  check_dfd(b, channels, p);
  const std::size_t alignment = std::lcm(channels * component_bytes(p), std::size_t(4));
  std::vector<std::size_t> offsets(t.levels);
  std::size_t expected_start = u32(b, 56) + u32(b, 60);
  for (std::size_t level = t.levels; level-- > 0;) {  // the data: smallest level first
    const std::size_t entry = 80 + 24 * level;
    const std::size_t offset = u64(b, entry), length = u64(b, entry + 8);
    CHECK(offset % alignment == 0);
    CHECK(offset >= expected_start);
    CHECK(offset - expected_start < alignment);
    for (std::size_t k = expected_start; k < offset; ++k) CHECK(b.at(k) == std::byte(0));
    CHECK(length == layer_value_count(t, level) * t.layers * component_bytes(p));
    CHECK(u64(b, entry + 16) == length);  // uncompressedByteLength
    offsets[level] = offset;
    expected_start = offset + length;
    // A level's data: all layers together, in the texture's order.
    std::size_t mismatches = 0;
    const std::size_t begin = level_offset(t, level, 0);
    for (std::size_t k = 0; k < length / component_bytes(p); ++k) {
      const double v = t.values[begin + k];
      if (p == Precision::f32) mismatches += u32(b, offset + 4 * k) != testing::f32_bits(v);
      else mismatches += testing::u16(b, offset + 2 * k) != testing::f16_bits(v);
    }
    CHECK(mismatches == 0);
  }
  CHECK(expected_start == b.size());
  return offsets;
}

}  // namespace

TEST_CASE("KTX2: 2D textures of every vkFormat, and the key/value data") {
  for (const Precision p : {Precision::f32, Precision::f16})
    for (std::size_t channels = 1; channels <= 4; ++channels) {
      Texture t = testing::sample(5, 3, channels, testing::Values::awkward, 1, 1, 1, unsigned(channels));
      t.metadata = {{"source", "jobs/ltc-ggx.yaml"}, {"Axis", "n_dot_v \"rows\"\n"}};
      const Bytes b = encode_ktx2(t, p);
      check_ktx2(b, t, p);
      const auto kv = key_values(b);
      CHECK(kv.size() == 6);
      CHECK(kv.at("KTXwriter") == "pbrfit");
      CHECK(kv.at("KTXorientation") == "rd");
      CHECK(kv.at("pbrfit:name") == "sample 5x3");
      CHECK(kv.at("pbrfit:channels") == std::string("R,G,B,A").substr(0, 2 * channels - 1));
      CHECK(kv.at("pbrfit:source") == "jobs/ltc-ggx.yaml");
      CHECK(kv.at("pbrfit:Axis") == "n_dot_v \"rows\"\n");
    }
}

TEST_CASE("KTX2: mips from the smallest level to the largest, each aligned to lcm(texel bytes, 4)") {
  // RGB16F: 6-byte texels, levels aligned to 12; RGB32F: 12; RG16F: 4.
  for (const auto& [channels, p] : {std::pair{3, Precision::f16}, std::pair{3, Precision::f32},
                                    std::pair{2, Precision::f16}, std::pair{1, Precision::f16}}) {
    const Texture t = testing::sample(7, 5, std::size_t(channels), testing::Values::awkward, 1, 1, 3);
    const auto offsets = check_ktx2(encode_ktx2(t, p), t, p);
    CHECK(offsets[2] < offsets[1]);
    CHECK(offsets[1] < offsets[0]);
  }
}

TEST_CASE("KTX2: an array with mips keeps all layers of a level together; a volume; a 1D texture") {
  const Texture array = testing::sample(4, 4, 4, testing::Values::awkward, 1, 3, 3);
  check_ktx2(encode_ktx2(array, Precision::f16), array, Precision::f16);
  const Texture volume = testing::sample(4, 2, 2, testing::Values::awkward, 8, 1, 4);
  const Bytes v = encode_ktx2(volume, Precision::f32);
  check_ktx2(v, volume, Precision::f32);
  CHECK(key_values(v).at("KTXorientation") == "rdi");
  const Texture line = testing::sample(8, 1, 1, testing::Values::awkward, 1, 1, 4);
  const Bytes l = encode_ktx2(line, Precision::f32);
  check_ktx2(l, line, Precision::f32);
  CHECK(u32(l, 24) == 0);  // pixelHeight 0: 1D
  CHECK(key_values(l).at("KTXorientation") == "r");
}

// ktx-parse comes with the web test packages that `make test` installs (tests/web/package.json).
TEST_CASE("KTX2: ktx-parse reads what pbrfit wrote") {
  const std::filesystem::path ktx_parse = PBRFIT_KTX_PARSE_DIR;
  INFO("install the web test packages: make web-deps (npm ci into BUILD/web)");
  REQUIRE(std::filesystem::exists(ktx_parse / "dist/index.mjs"));
  REQUIRE(testing::tool_available("node"));
  struct Case {
    Texture t;
    Precision p;
  };
  std::vector<Case> cases = {{testing::sample(8, 4, 4, testing::Values::awkward, 1, 2, 3), Precision::f16},
                             {testing::sample(3, 5, 3, testing::Values::awkward, 1, 1, 2), Precision::f32},
                             {testing::sample(4, 4, 2, testing::Values::awkward, 4, 1, 3), Precision::f32}};
  cases[0].t.metadata = {{"source", "jobs/ltc-ggx.yaml"}};
  std::string files;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const auto path = testing::scratch("parse-" + std::to_string(k) + ".ktx2");
    testing::write_file(path, encode_ktx2(cases[k].t, cases[k].p));
    files += (k ? ", " : "") + ("'" + path.string() + "'");
  }
  const std::string script = "import { read } from '" + (ktx_parse / "dist/index.mjs").string() + "';\n" +
                             "import { readFileSync } from 'node:fs';\n" + "for (const file of [" + files + "]) {\n" +
                             R"(  const c = read(new Uint8Array(readFileSync(file)));
  const d = c.dataFormatDescriptor[0];
  console.log(['file', c.vkFormat, c.typeSize, c.pixelWidth, c.pixelHeight, c.pixelDepth, c.layerCount,
               c.faceCount, c.levelCount, c.supercompressionScheme, d.colorModel, d.colorPrimaries,
               d.transferFunction, d.bytesPlane[0], d.samples.length].join(' '));
  for (const s of d.samples) console.log(['sample', s.bitOffset, s.bitLength, s.channelType, s.sampleLower,
                                          s.sampleUpper].join(' '));
  for (const [k, v] of Object.entries(c.keyValue))
    console.log(['kv', k, typeof v === 'string' ? v : new TextDecoder().decode(v.subarray(0, v.length - 1))].join(' '));
  for (const l of c.levels) {
    const data = l.levelData.slice().buffer;
    const words = c.typeSize === 4 ? new Uint32Array(data) : new Uint16Array(data);
    console.log(['level', l.uncompressedByteLength, ...words].join(' '));
  }
}
)";
  const auto script_path = testing::scratch("parse.mjs");
  testing::write_file(script_path, script);
  const auto result = testing::run("node " + testing::shell_quoted(script_path.string()));
  INFO(result.errors);
  REQUIRE(result.status == 0);
  std::istringstream lines(result.output);
  std::string line;
  for (const Case& c : cases) {
    const Texture& t = c.t;
    REQUIRE(std::getline(lines, line));
    std::ostringstream header;
    header << "file " << expected_vk_format(t.channels.size(), c.p) << ' ' << component_bytes(c.p) << ' ' << t.width
           << ' ' << (t.height == 1 && t.depth == 1 ? 0 : t.height) << ' ' << (t.depth > 1 ? t.depth : 0) << ' '
           << (t.layers > 1 ? t.layers : 0) << " 1 " << t.levels << " 0 1 1 1 "
           << t.channels.size() * component_bytes(c.p) << ' ' << t.channels.size();
    CHECK(line == header.str());
    const int ids[] = {0, 1, 2, 15};
    for (std::size_t s = 0; s < t.channels.size(); ++s) {
      REQUIRE(std::getline(lines, line));
      const std::size_t bits = 8 * component_bytes(c.p);
      CHECK(line == "sample " + std::to_string(s * bits) + " " + std::to_string(bits - 1) + " " +
                        std::to_string(ids[s] | 0xC0) + " -1082130432 1065353216");
    }
    std::map<std::string, std::string> kv;
    while (lines.peek() == 'k' && std::getline(lines, line)) {
      const std::size_t space = line.find(' ', 3);
      kv[line.substr(3, space - 3)] = line.substr(space + 1);
    }
    CHECK(kv["KTXwriter"] == "pbrfit");
    CHECK(kv["pbrfit:name"] == t.name);
    for (const auto& [key, value] : t.metadata) CHECK(kv["pbrfit:" + key] == value);
    for (std::size_t level = 0; level < t.levels; ++level) {
      REQUIRE(std::getline(lines, line));
      std::istringstream words(line);
      std::string tag;
      std::size_t length = 0;
      words >> tag >> length;
      CHECK(tag == "level");
      CHECK(length == layer_value_count(t, level) * t.layers * component_bytes(c.p));
      std::size_t count = 0, mismatches = 0;
      for (std::uint64_t w; words >> w; ++count) {
        const double v = t.values.at(level_offset(t, level, 0) + count);
        mismatches += w != (c.p == Precision::f32 ? testing::f32_bits(v) : testing::f16_bits(v));
      }
      CHECK(count == layer_value_count(t, level) * t.layers);
      CHECK(mismatches == 0);
    }
  }
}
