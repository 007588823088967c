// 16-bit PNG read back by pypng (Debian's python3-png) in a child Python: its header (bit depth, planes,
// colour type), its tEXt/iTXt chunks (ranges, name, channels, metadata), and every sample within the
// documented quantization: |min + q / 65535 (max - min) - v| <= (max - min) / 131070.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <cmath>
#include <map>
#include <sstream>

#include "pbrfit/texture/png16.hpp"
#include "texture_test_support.hpp"

using namespace pbrfit;
using namespace pbrfit::texture;
using Catch::Matchers::Equals;

namespace {

constexpr const char* reader = R"(import sys, zlib, png
for path in sys.argv[1:]:
    chunks = list(png.Reader(filename=path).chunks())
    kinds = [kind for kind, _ in chunks]
    print('chunks', ' '.join(k.decode() for k in kinds))
    for kind, data in chunks:
        if kind == b'tEXt':
            key, value = data.split(b'\0', 1)
            print('text', key.decode('latin-1'), value.hex())
        elif kind == b'iTXt':
            key, rest = data.split(b'\0', 1)
            compressed, rest = rest[0], rest[2:]
            language, translated, value = rest.split(b'\0', 2)
            print('itxt', key.decode('latin-1'), (zlib.decompress(value) if compressed else value).hex())
    width, height, rows, info = png.Reader(filename=path).read()
    print('info', width, height, info['bitdepth'], info['planes'], int(info['greyscale']), int(info['alpha']))
    for row in rows:
        print('row', ' '.join(str(q) for q in row))
)";

struct Read {
  std::size_t width = 0, height = 0, bitdepth = 0, planes = 0, greyscale = 0, alpha = 0;
  std::string chunks;
  std::map<std::string, std::string> text;   // tEXt and iTXt, by key
  std::map<std::string, std::string> kinds;  // key -> "text" or "itxt"
  std::vector<std::uint32_t> samples;
};

std::string unhex(const std::string& hex) {
  std::string out;
  for (std::size_t k = 0; k + 1 < hex.size(); k += 2) out += char(std::stoi(hex.substr(k, 2), nullptr, 16));
  return out;
}

std::vector<Read> read_with_pypng(const std::vector<Bytes>& files) {
  std::string command = "/usr/bin/python3 " + testing::shell_quoted(testing::scratch("read_png.py").string());
  testing::write_file(testing::scratch("read_png.py"), std::string(reader));
  for (std::size_t k = 0; k < files.size(); ++k) {
    const auto path = testing::scratch("t" + std::to_string(k) + ".png");
    testing::write_file(path, files[k]);
    command += " " + testing::shell_quoted(path.string());
  }
  const auto result = testing::run(command);
  INFO(result.errors);
  REQUIRE(result.status == 0);
  std::vector<Read> reads;
  std::istringstream lines(result.output);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "chunks") {
      reads.emplace_back();
      reads.back().chunks = line.substr(7);
    } else if (tag == "text" || tag == "itxt") {
      std::string key, hex;
      words >> key >> hex;
      reads.back().text[key] = unhex(hex);
      reads.back().kinds[key] = tag;
    } else if (tag == "info") {
      Read& r = reads.back();
      words >> r.width >> r.height >> r.bitdepth >> r.planes >> r.greyscale >> r.alpha;
    } else if (tag == "row") {
      for (std::uint32_t q; words >> q;) reads.back().samples.push_back(q);
    }
  }
  return reads;
}

void check_read(const Texture& t, const Read& r) {
  const std::size_t channels = t.channels.size();
  CHECK(r.width == t.width);
  CHECK(r.height == t.height);
  CHECK(r.bitdepth == 16);
  CHECK(r.planes == channels);
  CHECK(r.greyscale == (channels <= 2));
  CHECK(r.alpha == (channels == 2 || channels == 4));
  CHECK(r.chunks.find("tEXt") < r.chunks.find("IDAT"));
  CHECK(r.text.at("pbrfit:name") == t.name);
  std::string names;
  for (const std::string& c : t.channels) names += (names.empty() ? "" : ",") + c;
  CHECK(r.text.at("pbrfit:channels") == names);
  for (const auto& [key, value] : t.metadata) CHECK(r.text.at("pbrfit:" + key) == value);
  REQUIRE(r.samples.size() == t.values.size());
  std::vector<double> low(channels), high(channels);
  for (std::size_t c = 0; c < channels; ++c) {
    std::istringstream range(r.text.at("pbrfit:range:" + t.channels[c]));
    range >> low[c] >> high[c];
    CHECK(r.kinds.at("pbrfit:range:" + t.channels[c]) == "text");
  }
  const auto ranges = png16_ranges(t);
  std::size_t outside = 0, ends = 0;
  for (std::size_t c = 0; c < channels; ++c) {
    CHECK(low[c] == ranges[c].min);  // 17 digits: the same doubles
    CHECK(high[c] == ranges[c].max);
  }
  for (std::size_t i = 0; i < t.values.size(); ++i) {
    const std::size_t c = i % channels;
    const double span = high[c] - low[c], v = t.values[i];
    const double decoded = low[c] + double(r.samples[i]) / 65535.0 * span;
    outside += !(std::abs(decoded - v) <= span / 131070.0 * (1 + 1e-9));
    if (v == low[c]) ends += r.samples[i] != 0;
    if (v == high[c] && span > 0) ends += r.samples[i] != 65535;
  }
  CHECK(outside == 0);
  CHECK(ends == 0);
}

}  // namespace

TEST_CASE("PNG: pypng reads gray, gray + alpha, RGB and RGBA at 16 bits, ranges and text") {
  std::vector<Texture> textures;
  for (std::size_t channels = 1; channels <= 4; ++channels) {
    textures.push_back(
        testing::sample(7 + channels, 5, channels, testing::Values::moderate, 1, 1, 1, unsigned(channels)));
    textures.back().metadata = {{"source", "jobs/ltc-ggx.yaml"}, {"unit", "sr\u207b\u00b9"}};
  }
  Texture constant = testing::sample(3, 3, 2, testing::Values::moderate);
  for (std::size_t i = 0; i < constant.values.size(); i += 2) constant.values[i] = 0.25;  // R is constant
  textures.push_back(constant);
  std::vector<Bytes> files;
  for (const Texture& t : textures) files.push_back(encode_png16(t));
  const auto reads = read_with_pypng(files);
  REQUIRE(reads.size() == textures.size());
  for (std::size_t k = 0; k < textures.size(); ++k) check_read(textures[k], reads[k]);
  CHECK(reads[0].kinds.at("pbrfit:unit") == "itxt");  // not ASCII: UTF-8 in iTXt
  CHECK(reads[0].kinds.at("pbrfit:source") == "text");
  CHECK(reads[4].text.at("pbrfit:range:R") == "0.25 0.25");
  CHECK(reads[4].samples[0] == 0);
}

TEST_CASE("PNG: ranges have 17 significant digits") {
  Texture t;
  t.width = 2;
  t.channels = {"x"};
  t.values = {0.1, 1.0 / 3.0};
  const auto reads = read_with_pypng({encode_png16(t)});
  CHECK(reads.at(0).text.at("pbrfit:range:x") == "0.10000000000000001 0.33333333333333331");
  CHECK(reads.at(0).samples == std::vector<std::uint32_t>{0, 65535});
}

TEST_CASE("PNG: refusals") {
  CHECK_THROWS_WITH(encode_png16(testing::sample(4, 4, 3, testing::Values::moderate, 1, 1, 3)),
                    Equals("png: holds one 2D image, not 3 mip levels"));
  CHECK_THROWS_WITH(encode_png16(testing::sample(4, 4, 3, testing::Values::moderate, 1, 6)),
                    Equals("png: holds one 2D image, not 6 array layers"));
  CHECK_THROWS_WITH(encode_png16(testing::sample(4, 4, 3, testing::Values::moderate, 4)),
                    Equals("png: holds one 2D image, not a volume of depth 4"));
  Texture t = testing::sample(4, 4, 1, testing::Values::moderate);
  t.values[6] = NAN;
  CHECK_THROWS_WITH(encode_png16(t), Equals("png: value nan at level 0, texel (2, 1), channel R is not finite"));
}
