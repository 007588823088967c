// Radiance `.hdr` environment maps (RGBE, flat or run-length encoded scanlines).
#include <span>

#include "fuzz_support.hpp"
#include "pbrfit/render/radiance_hdr.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  pbrfit::fuzz::expect_result_or_input_error([&] { (void)pbrfit::render::decode_radiance_hdr(bytes, "fuzz.hdr"); });
  return 0;
}
