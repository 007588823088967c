// OpenEXR read back by OpenEXR's own reading API (Imf::InputFile and a FrameBuffer): channels, pixel types,
// windows, attributes, and every value bitwise (FLOAT: the float cast; HALF: Imath's half).
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <bit>
#include <cstring>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include "pbrfit/texture/exr.hpp"
#include "texture_test_support.hpp"

using namespace pbrfit;
using namespace pbrfit::texture;

namespace {

void check_exr(const Texture& t, Precision p) {
  const auto path = testing::scratch("t-" + std::to_string(t.channels.size()) + ".exr");
  testing::write_file(path, encode_exr(t, p));
  Imf::InputFile file(path.c_str());
  const Imf::Header& header = file.header();
  const auto window = header.dataWindow();
  CHECK(window.min.x == 0);
  CHECK(window.min.y == 0);
  CHECK(window.max.x == int(t.width) - 1);
  CHECK(window.max.y == int(t.height) - 1);
  CHECK(header.lineOrder() == Imf::INCREASING_Y);
  const Imf::PixelType type = p == Precision::f32 ? Imf::FLOAT : Imf::HALF;
  const char* rgba[] = {"R", "G", "B", "A"};
  std::size_t channel_count = 0;
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
    ++channel_count;
    CHECK(it.channel().type == type);
  }
  CHECK(channel_count == t.channels.size());
  const auto attribute = [&](const std::string& name) {
    const auto* a = header.findTypedAttribute<Imf::StringAttribute>(name);
    return a ? a->value() : std::string("(missing)");
  };
  CHECK(attribute("pbrfit:name") == t.name);
  CHECK(attribute("pbrfit:channels") == std::string("R,G,B,A").substr(0, 2 * t.channels.size() - 1));
  for (const auto& [key, value] : t.metadata) CHECK(attribute("pbrfit:" + key) == value);

  const std::size_t channels = t.channels.size(), texels = t.width * t.height;
  std::vector<float> floats(texels * channels);
  std::vector<Imath::half> halves(texels * channels);
  Imf::FrameBuffer frame;
  for (std::size_t c = 0; c < channels; ++c) {
    const char* name = channels == 1 ? "Y" : rgba[c];
    REQUIRE(header.channels().findChannel(name) != nullptr);
    char* base =
        p == Precision::f32 ? reinterpret_cast<char*>(floats.data() + c) : reinterpret_cast<char*>(halves.data() + c);
    const std::size_t size = p == Precision::f32 ? sizeof(float) : sizeof(Imath::half);
    frame.insert(name, Imf::Slice(type, base, size * channels, size * channels * t.width));
  }
  file.setFrameBuffer(frame);
  file.readPixels(window.min.y, window.max.y);
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < t.values.size(); ++i) {
    if (p == Precision::f32) mismatches += std::bit_cast<std::uint32_t>(floats[i]) != testing::f32_bits(t.values[i]);
    else mismatches += halves[i].bits() != testing::f16_bits(t.values[i]);
  }
  CHECK(mismatches == 0);
}

}  // namespace

TEST_CASE("EXR: OpenEXR reads every value back, FLOAT and HALF, Y and R G B A") {
  for (const Precision p : {Precision::f32, Precision::f16})
    for (std::size_t channels = 1; channels <= 4; ++channels) {
      Texture t = testing::sample(9, 5, channels, testing::Values::awkward, 1, 1, 1, unsigned(channels + 7));
      t.metadata = {{"source", "jobs/ltc-ggx.yaml"}, {"note", "two\nlines"}};
      check_exr(t, p);
    }
}

TEST_CASE("EXR: one 2D image only") {
  using Catch::Matchers::Equals;
  CHECK_THROWS_WITH(encode_exr(testing::sample(4, 4, 2, testing::Values::awkward, 1, 1, 3), Precision::f32),
                    Equals("exr: holds one 2D image, not 3 mip levels"));
  CHECK_THROWS_WITH(encode_exr(testing::sample(4, 4, 2, testing::Values::awkward, 1, 6), Precision::f16),
                    Equals("exr: holds one 2D image, not 6 array layers"));
  CHECK_THROWS_WITH(encode_exr(testing::sample(4, 4, 2, testing::Values::awkward, 2), Precision::f16),
                    Equals("exr: holds one 2D image, not a volume of depth 2"));
}
