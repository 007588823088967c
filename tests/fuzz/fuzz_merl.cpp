// MERL `.binary` measured materials, read from a file as jobs name them.
#include "fuzz_support.hpp"
#include "pbrfit/store/merl_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& path = pbrfit::fuzz::scratch_file(data, size, ".binary");
  pbrfit::fuzz::expect_result_or_input_error([&] { (void)pbrfit::store::read_merl_file(path); });
  return 0;
}
