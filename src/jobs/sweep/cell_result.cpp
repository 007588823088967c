#include "pbrfit/jobs/sweep/cell_result.hpp"

#include "pbrfit/core/error.hpp"

namespace pbrfit::jobs::sweep {

Bytes encode_cell(const std::vector<ModelFit>& fits) {
  ByteWriter out;
  out.put_varint(fits.size());
  for (const auto& fit : fits) {
    out.put_array(std::span<const double>(fit.parameters));
    out.put(fit.error);
    out.put_varint(fit.evaluations);
    out.put(static_cast<std::uint8_t>(fit.start));
    out.put(static_cast<std::uint8_t>(fit.global_ran));
    out.put_array(std::span<const double>(fit.outputs));
  }
  return out.take();
}

std::vector<ModelFit> decode_cell(const Bytes& bytes, const std::vector<FitShape>& shapes) {
  try {
    ByteReader in(bytes);
    if (in.get_varint() != shapes.size()) throw RunError("a sweep cell result holds another number of models");
    std::vector<ModelFit> fits(shapes.size());
    for (std::size_t m = 0; m < shapes.size(); ++m) {
      ModelFit& fit = fits[m];
      fit.parameters = in.get_array<double>();
      fit.error = in.get<double>();
      fit.evaluations = in.get_varint();
      const auto start = in.get<std::uint8_t>();
      fit.global_ran = in.get<std::uint8_t>() != 0;
      fit.outputs = in.get_array<double>();
      if (start > 3 || fit.parameters.size() != shapes[m].parameters || fit.outputs.size() != shapes[m].outputs)
        throw RunError("a sweep cell result does not match the job's models");
      fit.start = static_cast<StartCode>(start);
    }
    if (in.remaining() != 0) throw RunError("a sweep cell result has trailing bytes");
    return fits;
  } catch (const ByteFormatError& e) {
    throw RunError(std::string("a sweep cell result is truncated: ") + e.what());
  }
}

}  // namespace pbrfit::jobs::sweep
