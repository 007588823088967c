#include <catch2/catch_test_macros.hpp>

#include <filesystem>
#include <fstream>

#include "pbrfit/core/error.hpp"
#include "pbrfit/jobs/job_kinds.hpp"
#include "pbrfit/jobs/ebrdf/ebrdf_workload.hpp"
#include "pbrfit/store/png_file.hpp"

using namespace pbrfit;

namespace {

std::unique_ptr<runtime::Workload> workload(const std::string& section) {
  const std::string text = "name: t\nkind: ebrdf\nebrdf:\n" + section;
  return jobs::make_workload(spec::parse_job_text(text, "t.yaml", jobs::kind_catalogue()));
}

std::string refusal(const std::string& section) {
  try {
    workload(section);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

struct TempDir {
  std::filesystem::path path = std::filesystem::temp_directory_path() / ("pbrfit-ebrdf-" + std::to_string(::getpid()));
  TempDir() { std::filesystem::create_directories(path); }
  ~TempDir() { std::filesystem::remove_all(path); }
  std::string file(const std::string& name) const { return (path / name).string(); }
};

void write_bytes(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

}  // namespace

TEST_CASE("an ebrdf job has the normal-map item, then tiles by component and level") {
  const auto w = workload("  normal_map: stone\n  size: 16\n  tile: 4\n");
  CHECK(w->item_count(0) == 1 + 2 * (4 + 1 + 1 + 1));
  const auto one = workload("  normal_map: stone\n  size: 16\n  tile: 4\n  components: [diffuse]\n  max_level: 2\n");
  CHECK(one->item_count(0) == 1 + 4 + 1);
  const auto layout = one->layout();
  REQUIRE(layout.groups.size() == 3);
  CHECK(layout.groups[0].name == "ebrdf/normal_map");
  CHECK(layout.groups[2].name == "ebrdf/diffuse/mip2");
  CHECK(layout.groups[2].tables[0].chunk == std::vector<std::uint64_t>{4, 4, 2, 4, 9});
}

TEST_CASE("a tile's fits land at the tile's texels, one per view, and are deterministic") {
  const auto w = workload("  normal_map: glitter\n  size: 8\n  tile: 2\n  components: [diffuse]\n  iterations: 5\n");
  const Bytes nothing;
  const runtime::ItemTask task{{0, 2}, nothing, nothing, 11};  // level 1 (side 4), the second tile
  const Bytes result = w->compute(task);
  CHECK(result == w->compute(task));
  const auto blocks = w->blocks({0, 2}, result);
  REQUIRE(blocks.size() == 3);
  CHECK(blocks[0].group == "ebrdf/diffuse/mip1");
  CHECK(blocks[0].offset == std::vector<std::uint64_t>{0, 2, 0, 0, 0});
  CHECK(blocks[0].count == std::vector<std::uint64_t>{2, 2, 2, 4, 9});
  CHECK(blocks[1].values == store::reals(std::vector<double>(2 * 2 * 8, 1.0)));  // Lambert: amplitude 1
  const auto normals = w->blocks({0, 0}, w->compute({{0, 0}, nothing, nothing, 11}));
  REQUIRE(normals.size() == 1);
  CHECK(normals[0].count == std::vector<std::uint64_t>{8, 8, 3});
}

TEST_CASE("normal maps are read from PNG and TGA files, and bad pictures are refused naming the file") {
  const TempDir dir;
  RgbImage flat(4, 4, {0.5f, 0.5f, 1.0f});
  store::write_png_file(dir.file("flat.png"), flat);
  CHECK(workload("  normal_map: " + dir.file("flat.png") + "\n")->item_count(0) == 1 + 2 * 2);
  std::string tga = {0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 2, 0, 24, 0x20};
  for (int i = 0; i < 4; ++i) tga += std::string{char(255), char(128), char(128)};  // B G R
  write_bytes(dir.file("flat.tga"), tga);
  CHECK(workload("  normal_map: " + dir.file("flat.tga") + "\n")->item_count(0) == 1 + 2 * 1);

  write_bytes(dir.file("text.png"), "not a picture at all");
  CHECK(refusal("  normal_map: " + dir.file("text.png") + "\n") ==
        "t.yaml:4:15: error: 'normal_map' names " + dir.file("text.png") + ": not a PNG or TGA picture (unknown image type)");
  store::write_png_file(dir.file("six.png"), RgbImage(6, 6));
  CHECK(refusal("  normal_map: " + dir.file("six.png") + "\n").ends_with(
      "a normal map must be square with a power-of-two side of at most 512 pixels; this one is 6 x 6"));
  store::write_png_file(dir.file("big.png"), RgbImage(1024, 1024));
  CHECK(refusal("  normal_map: " + dir.file("big.png") + "\n").ends_with("this one is 1024 x 1024"));
  const std::string png = [&] {
    std::ifstream in(dir.file("flat.png"), std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  write_bytes(dir.file("cut.png"), png.substr(0, png.size() / 2));
  CHECK(refusal("  normal_map: " + dir.file("cut.png") + "\n").find("cannot decode the picture") != std::string::npos);
}
