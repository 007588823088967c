// Result files given to `status` and `export`: pbrfit's reading of their attributes and tables, with HDF5
// underneath (the report reads them with h5py, in Python).
#include "fuzz_support.hpp"
#include "pbrfit/jobs/table_export.hpp"
#include "pbrfit/store/result_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& path = pbrfit::fuzz::scratch_file(data, size, ".h5");
  pbrfit::fuzz::expect_result_or_input_error([&] {
    const auto summary = pbrfit::store::read_result_summary(path);
    if (summary.job_kind != "lut" && summary.job_kind != "sweep" && summary.job_kind != "ebrdf") return;
    for (const auto& table : pbrfit::jobs::exportable_tables(path, summary)) {
      pbrfit::jobs::TableRequest request;
      request.table = table;
      (void)pbrfit::jobs::table_texture(path, summary, request);
    }
  });
  return 0;
}
