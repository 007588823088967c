// The Texture value: its layout (level, layer, z, y, x, channel), level sizes and offsets, and validate()'s
// one-line refusals; the format table of format.hpp.
#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <stdexcept>

#include "pbrfit/texture/format.hpp"
#include "pbrfit/texture/texture.hpp"
#include "texture_test_support.hpp"

using namespace pbrfit::texture;
using Catch::Matchers::Equals;
using Catch::Matchers::StartsWith;

namespace {

std::string refusal(const Texture& t) {
  try {
    validate(t);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace

TEST_CASE("levels halve each size down to 1 and come one after the other, each with all its layers") {
  Texture t = testing::sample(8, 3, 2, testing::Values::moderate, 1, 3, 4);
  CHECK(level_width(t, 0) == 8);
  CHECK(level_height(t, 1) == 1);
  CHECK(level_width(t, 3) == 1);
  CHECK(level_depth(t, 2) == 1);
  CHECK(layer_value_count(t, 0) == 8 * 3 * 2);
  CHECK(layer_value_count(t, 1) == 4 * 1 * 2);
  CHECK(level_offset(t, 0, 0) == 0);
  CHECK(level_offset(t, 0, 2) == 2 * 48);
  CHECK(level_offset(t, 1, 0) == 3 * 48);
  CHECK(level_offset(t, 1, 1) == 3 * 48 + 8);
  CHECK(level_offset(t, 2, 0) == 3 * 48 + 3 * 8);
  CHECK(level_offset(t, 4, 0) == 3 * (48 + 8 + 4 + 2));
  CHECK(t.values.size() == level_offset(t, 4, 0));
  CHECK_NOTHROW(validate(t));
  CHECK_THROWS_AS(level_offset(t, 0, 3), std::out_of_range);
  CHECK_THROWS_AS(level_offset(t, 5, 0), std::out_of_range);
  CHECK_THROWS_AS(level_width(t, 4), std::out_of_range);

  Texture volume = testing::sample(4, 4, 1, testing::Values::moderate, 8, 1, 4);
  CHECK(level_depth(volume, 2) == 2);
  CHECK(level_offset(volume, 1, 0) == 4 * 4 * 8);
  CHECK(level_offset(volume, 2, 0) == 128 + 2 * 2 * 4);
}

TEST_CASE("validate names what is wrong in one line") {
  const Texture good = testing::sample(4, 2, 3);
  CHECK(refusal(good) == "accepted");
  Texture t = good;
  t.width = 0;
  CHECK_THAT(refusal(t), Equals("texture \"sample 4x2\": width is 0; it must be at least 1"));
  t = good, t.layers = 2, t.depth = 2;
  CHECK_THAT(refusal(t), Equals("texture \"sample 4x2\": a volume (depth 2) cannot have array layers (2)"));
  t = good, t.levels = 4;
  CHECK_THAT(refusal(t), Equals("texture \"sample 4x2\": 4 mip levels for 4 x 2 x 1 texels; the full chain has 3"));
  t = good, t.height = std::size_t(1) << 31;
  CHECK_THAT(refusal(t), Equals("texture \"sample 4x2\": height 2147483648 is not below 2^31"));
  t = good, t.channels = {"R", "G", "B", "A", "E"};
  CHECK_THAT(refusal(t), Equals("texture \"sample 4x2\": 5 channels; a texture has 1 to 4"));
  t = good, t.channels.clear();
  CHECK_THAT(refusal(t), Equals("texture \"sample 4x2\": 0 channels; a texture has 1 to 4"));
  t = good, t.channels = {"R", "R", "B"};
  CHECK_THAT(refusal(t), Equals("texture \"sample 4x2\": channel name \"R\" appears twice"));
  t = good, t.channels = {"R", "a b", "B"};
  CHECK_THAT(refusal(t), Equals("texture \"sample 4x2\": channel name \"a b\" is not 1 to 64 printable ASCII "
                                "characters without spaces or commas"));
  t = good, t.values.pop_back();
  CHECK_THAT(refusal(t), Equals("texture \"sample 4x2\": values holds 23 numbers; 4 x 2 x 1 texels, 1 layers, 1 "
                                "levels and 3 channels need 24"));
  t = good, t.metadata = {{"name", "x"}};
  CHECK_THAT(refusal(t), Equals("texture \"sample 4x2\": metadata key \"name\" is reserved for the texture's own "
                                "name, channels or ranges"));
  t = good, t.metadata = {{"range:R", "x"}};
  CHECK_THAT(refusal(t), StartsWith("texture \"sample 4x2\": metadata key \"range:R\" is reserved"));
  t = good, t.metadata = {{"a", "1"}, {"a", "2"}};
  CHECK_THAT(refusal(t), Equals("texture \"sample 4x2\": metadata key \"a\" appears twice"));
  t = good, t.metadata = {{"a key", "1"}};
  CHECK_THAT(refusal(t), Equals("texture \"sample 4x2\": metadata key \"a key\" is not 1 to 64 printable ASCII "
                                "characters without spaces"));
  t = good, t.metadata = {{"a", std::string("x\0y", 3)}};
  CHECK_THAT(refusal(t), Equals("texture \"sample 4x2\": metadata value of \"a\" holds a NUL character"));
  t = good, t.name = std::string("x\0y", 3);
  CHECK_THAT(refusal(t), Equals("texture \"x\\x00y\": the name holds a NUL character"));
  t = good, t.name = "two\nlines", t.channels = {"R", "G", "B\n"};
  CHECK_THAT(refusal(t), Equals("texture \"two\\nlines\": channel name \"B\\n\" is not 1 to 64 printable ASCII "
                                "characters without spaces or commas"));
}

TEST_CASE("formats by name, with their extensions; encode() refusals start with the format's name") {
  CHECK(all_formats().size() == 10);
  for (const Format f : all_formats()) {
    REQUIRE(format_named(format_name(f)) == f);
    CHECK(file_extension(f).starts_with("."));
  }
  CHECK(file_extension(Format::cpp) == ".hpp");
  CHECK(format_named("tga") == std::nullopt);
  Texture bad = testing::sample(4, 2, 3);
  bad.values.clear();
  for (const Format f : all_formats()) {
    try {
      encode(bad, f, {Precision::f16, "T_"});
      FAIL("accepted");
    } catch (const std::invalid_argument& e) {
      CHECK_THAT(e.what(), StartsWith(std::string(format_name(f)) + ": texture \"sample 4x2\": values holds 0"));
    }
  }
}
