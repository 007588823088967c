// PNG and TGA normal maps: stb_image as pbrfit calls it, with its size limits.
#include "fuzz_support.hpp"
#include "pbrfit/store/image_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& path = pbrfit::fuzz::scratch_file(data, size, ".png");
  pbrfit::fuzz::expect_result_or_input_error([&] { (void)pbrfit::store::read_rgb8_image(path); });
  return 0;
}
