#include "search_records.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "pbrfit/core/decoded_record.hpp"
#include "pbrfit/jobs/brdf/brdf_inputs.hpp"

namespace pbrfit::jobs::brdf {

namespace {

void write_statistics(ByteWriter& out, const IslandStatistics& s) {
  out.put(s.best_error);
  out.put(s.median_error);
  out.put(s.median_size);
  out.put(s.infeasible);
  out.put(s.abandoned);
}

IslandStatistics read_statistics(ByteReader& in) {
  IslandStatistics s;
  s.best_error = in.get<double>();
  s.median_error = in.get<double>();
  s.median_size = in.get<double>();
  s.infeasible = in.get<std::uint32_t>();
  s.abandoned = in.get<std::uint32_t>();
  return s;
}

double median(std::span<const double> values) {
  if (values.empty()) return 0.0;
  std::vector<double> sorted(values.begin(), values.end());
  std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
  return sorted[sorted.size() / 2];
}

}  // namespace

const Bytes& kept_result(const ItemResults& kept, WorkItemId id) {
  const auto found = kept.find(id);
  if (found == kept.end()) throw std::logic_error("brdf search: a result of the generation before was not kept");
  return found->second;
}

Bytes encode(const BreedRecord& r) {
  ByteWriter out;
  out.put_varint(r.genomes.size());
  for (const auto& g : r.genomes) write_genome(out, g);
  for (const auto& t : r.trees) write_tree(out, t);
  out.put_varint(r.generation);
  write_statistics(out, r.statistics);
  out.put(r.migrants_in);
  return out.take();
}

BreedRecord decode_breed(const Bytes& bytes) {
  return decoded_record(bytes, "BRDF search breeding record", [](ByteReader& in) {
    BreedRecord r;
    const auto n = in.get_varint();
    if (n > in.remaining()) throw ByteFormatError(in.offset(), "more genomes than bytes");
    for (std::uint64_t k = 0; k < n; ++k) r.genomes.push_back(read_genome(in));
    for (std::uint64_t k = 0; k < n; ++k) r.trees.push_back(read_tree(in, brdf_input_count, brdf_parameter_count));
    r.generation = in.get_varint();
    r.statistics = read_statistics(in);
    r.migrants_in = in.get<std::uint32_t>();
    return r;
  });
}

Bytes encode(const EvaluationRecord& r) {
  ByteWriter out;
  out.put_array(std::span<const double>(r.errors));
  out.put_array(std::span<const double>(r.sizes));
  for (const auto& m : r.material_errors) out.put_array(std::span<const double>(m));
  out.put_array(std::span<const std::uint8_t>(r.abandoned));
  return out.take();
}

EvaluationRecord decode_evaluation(const Bytes& bytes) {
  return decoded_record(bytes, "BRDF search evaluation record", [](ByteReader& in) {
    EvaluationRecord r;
    r.errors = in.get_array<double>();
    r.sizes = in.get_array<double>();
    if (r.sizes.size() != r.errors.size()) throw ByteFormatError(in.offset(), "errors and sizes differ in number");
    for (std::size_t k = 0; k < r.errors.size(); ++k) r.material_errors.push_back(in.get_array<double>());
    r.abandoned = in.get_array<std::uint8_t>();
    if (r.abandoned.size() != r.errors.size()) throw ByteFormatError(in.offset(), "errors and abandoned flags differ in number");
    return r;
  });
}

IslandStatistics island_statistics(std::span<const double> errors, std::span<const double> sizes,
                                   std::span<const std::uint8_t> abandoned) {
  IslandStatistics out;
  for (std::size_t k = 0; k < errors.size(); ++k) {
    if (!std::isfinite(errors[k])) ++out.infeasible;
    else if (abandoned[k]) ++out.abandoned;
    else out.best_error = std::min(out.best_error, errors[k]);
  }
  out.median_error = errors.empty() ? gp::worst_error : median(errors);
  out.median_size = median(sizes);
  return out;
}

Bytes encode(const FrontRecord& r) {
  ByteWriter out;
  write_scored(out, r.front);
  write_scored(out, r.additions);
  write_scored(out, r.simplified);
  out.put_varint(r.last_generation.size());
  for (const auto& s : r.last_generation) write_statistics(out, s);
  return out.take();
}

FrontRecord decode_front(const Bytes& bytes, std::size_t inputs, std::size_t parameters) {
  return decoded_record(bytes, "BRDF search front record", [&](ByteReader& in) {
    FrontRecord r;
    r.front = read_scored(in, inputs, parameters);
    r.additions = read_scored(in, inputs, parameters);
    r.simplified = read_scored(in, inputs, parameters);
    const auto islands = in.get_varint();
    if (islands > in.remaining()) throw ByteFormatError(in.offset(), "more islands than bytes");
    for (std::uint64_t k = 0; k < islands; ++k) r.last_generation.push_back(read_statistics(in));
    return r;
  });
}

Bytes encode(const MaterialEvaluation& r) {
  ByteWriter out;
  out.put_varint(r.models.size());
  for (const auto& m : r.models) {
    out.put(m.metric_error);
    out.put(m.image_l2);
    out.put(m.one_minus_ssim);
    out.put_array(std::span<const double>(m.parameters));
  }
  out.put_array(std::span<const std::uint8_t>(r.renders));
  return out.take();
}

MaterialEvaluation decode_material(const Bytes& bytes) {
  return decoded_record(bytes, "BRDF search material evaluation", [](ByteReader& in) {
    MaterialEvaluation r;
    const auto n = in.get_varint();
    if (n > in.remaining() / 24) throw ByteFormatError(in.offset(), "more models than bytes");
    for (std::uint64_t k = 0; k < n; ++k) {
      ModelEvaluation m;
      m.metric_error = in.get<double>();
      m.image_l2 = in.get<double>();
      m.one_minus_ssim = in.get<double>();
      m.parameters = in.get_array<double>();
      r.models.push_back(std::move(m));
    }
    r.renders = in.get_array<std::uint8_t>();
    return r;
  });
}

Bytes encode(const std::vector<AverageRow>& rows) {
  ByteWriter out;
  out.put_varint(rows.size());
  for (const auto& row : rows) {
    out.put_string(row.set);
    out.put_string(row.model);
    for (const double v : {row.metric_error, row.image_l2, row.one_minus_ssim, row.l2_reduction, row.ssim_reduction})
      out.put(v);
  }
  return out.take();
}

std::vector<AverageRow> decode_averages(const Bytes& bytes) {
  return decoded_record(bytes, "BRDF search average", [](ByteReader& in) {
    std::vector<AverageRow> rows;
    const auto n = in.get_varint();
    if (n > in.remaining() / 40) throw ByteFormatError(in.offset(), "more rows than bytes");
    for (std::uint64_t k = 0; k < n; ++k) {
      AverageRow row{in.get_string(), in.get_string()};
      row.metric_error = in.get<double>();
      row.image_l2 = in.get<double>();
      row.one_minus_ssim = in.get<double>();
      row.l2_reduction = in.get<double>();
      row.ssim_reduction = in.get<double>();
      rows.push_back(std::move(row));
    }
    return rows;
  });
}

}  // namespace pbrfit::jobs::brdf
