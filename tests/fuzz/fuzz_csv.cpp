// CSV datasets of symbolic-regression jobs.
#include "fuzz_support.hpp"
#include "pbrfit/jobs/symreg/csv_table.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  pbrfit::fuzz::expect_result_or_input_error(
      [&] { (void)pbrfit::jobs::symreg::parse_csv(pbrfit::fuzz::text_of(data, size), "fuzz.csv"); });
  return 0;
}
