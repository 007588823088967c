// PNG and TGA normal maps, as an ebrdf job reads them: stb_image with pbrfit's limits (the picture's side
// and the normal map's shape checked from the header, before any pixel is decoded), then the decoding of
// the pixels into normals.
#include "fuzz_support.hpp"
#include "pbrfit/jobs/ebrdf/normal_map_source.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& path = pbrfit::fuzz::scratch_file(data, size, ".png");
  pbrfit::fuzz::expect_result_or_input_error([&] { (void)pbrfit::jobs::ebrdf::normal_map_file(path); });
  return 0;
}
