#include "pbrfit/jobs/lut/dfg_table.hpp"

#include <algorithm>
#include <cstdio>

#include "pbrfit/brdf/cloth_albedo.hpp"
#include "pbrfit/brdf/split_sum_dfg.hpp"
#include "pbrfit/core/error.hpp"

namespace pbrfit::jobs::lut {

namespace {

const char* visibility_description(brdf::SmithVisibility v) {
  switch (v) {
    case brdf::SmithVisibility::separable: return "separable Smith GGX, G = G1(v) G1(l)";
    case brdf::SmithVisibility::separable_schlick:
      return "separable Schlick-GGX, G1(x) = x / (x (1 - k) + k), k = alpha / 2 (UE4 / Karis)";
    default: return "height-correlated Smith GGX, G = 1 / (1 + Lambda(v) + Lambda(l)) (Heitz 2014 / Filament)";
  }
}

std::string roughness_axis_name(brdf::RoughnessParametrization p) {
  return p == brdf::RoughnessParametrization::gloss ? "gloss" : "roughness";
}

std::string format_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

}  // namespace

DfgTable::DfgTable(const DfgSettings& settings)
    : settings_(settings),
      n_dot_v_(unit_axis(settings.n_dot_v_count, settings.placement)),
      roughness_(unit_axis(settings.roughness_count, settings.placement)) {
  add_stage(runtime::stage<Nothing, Nothing, Row>("rows", 1, this)
                .items(&DfgTable::row_count)
                .compute(&DfgTable::compute_row)
                .check(&DfgTable::check_row)
                .blocks(&DfgTable::row_blocks)
                .fold(&DfgTable::fold_row));
}

double DfgTable::alpha(std::uint64_t row) const { return brdf::alpha_from(settings_.roughness, roughness_[row]); }

store::ResultLayout DfgTable::layout() const {
  const std::string r = roughness_axis_name(settings_.roughness);
  const std::string placement = settings_.placement == Placement::centres ? "cell centres (i + 0.5) / n"
                                                                          : "cell edges i / (n - 1)";
  store::Group group;
  group.name = "dfg";
  group.description =
      "Split-sum environment BRDF of GGX specular: specular = f0 * scale + bias (Schlick Fresnel), "
      "scale = integral of (f/F)(1 - (1 - v.h)^5)(n.l) dl, bias = integral of (f/F)(1 - v.h)^5 (n.l) dl";
  group.attributes = {{"function", "dfg"},
                      {"visibility", visibility_description(settings_.visibility)},
                      {"roughness_parametrization", brdf::formula(settings_.roughness)},
                      {"samples", placement},
                      {"tolerance", format_number(settings_.integration.abs_tolerance)},
                      {"integrator", "globally adaptive tensor-product Gauss-Kronrod 7-15 over the half-vector "
                                     "hemisphere above the horizon"},
                      {"multiple_scattering", settings_.multiple_scattering ? "true" : "false"},
                      {"cloth", settings_.cloth ? "true" : "false"}};
  group.axes = {{r, roughness_, r + " (" + brdf::formula(settings_.roughness) + "), " + placement},
                {"n_dot_v", n_dot_v_, "cosine between normal and view direction, " + placement}};
  const std::vector<std::string> grid = {r, "n_dot_v"};
  group.tables = {{"scale", grid, "factor of f0"},
                  {"bias", grid, "term added after the f0 factor"},
                  {"error_estimate", grid, "absolute error estimate of the integrator (max of scale and bias)"},
                  {"evaluations", grid, "integrand evaluations spent on the entry"},
                  {"alpha", {r}, "GGX alpha of the row"}};
  if (settings_.multiple_scattering) {
    group.tables.push_back({"energy", grid,
                            "directional albedo E(n.v) = scale + bias of the single-scattering lobe with F = 1; "
                            "Filament's energy compensation is 1 + f0 (1 / E - 1)"});
    group.tables.push_back({"average_energy", {r},
                            "Kulla-Conty average albedo E_avg = 2 * integral of E(mu) mu dmu; multiple-scattering "
                            "lobe f_ms = (1 - E(mu_o))(1 - E(mu_i)) / (pi (1 - E_avg))"});
  }
  if (settings_.cloth) {
    group.attributes["cloth_lobe"] =
        "Charlie sheen D (Estevez & Kulla 2017) with V = 1 / (4 (n.l + n.v - n.l n.v)) (Neubelt & Pettineo 2013), "
        "F = 1, alpha as the row's: Filament cmgen's DFV_Charlie_Uniform";
    group.tables.push_back({"cloth", grid,
                            "directional albedo of the cloth (sheen) lobe: integral of D_Charlie V_Neubelt (n.l) dl; "
                            "Filament's DFG LUT holds it in its blue channel"});
    group.tables.push_back({"cloth_error_estimate", grid, "absolute error estimate of the cloth integral"});
    group.tables.push_back({"cloth_evaluations", grid, "integrand evaluations spent on the cloth entry"});
  }
  return {{group}};
}

void DfgTable::require_converged(bool converged, double error, std::size_t evaluations, const std::string& what) const {
  if (converged) return;
  char text[300];
  std::snprintf(text, sizeof text,
                "%s did not reach the tolerance %.3g within %zu evaluations (error estimate %.3g); raise "
                "max_evaluations or the tolerance",
                what.c_str(), settings_.integration.abs_tolerance, evaluations, error);
  throw RunError(text);
}

DfgTable::Row DfgTable::compute_row(const Task& task) const {
  const std::uint64_t item = task.item();
  const double a = alpha(item);
  const std::string r = roughness_axis_name(settings_.roughness) + " " + format_number(roughness_[item]);
  Row row;
  for (double mu : n_dot_v_) {
    const auto entry = brdf::integrate_dfg(mu, a, settings_.visibility, settings_.integration);
    require_converged(entry.converged, entry.error_estimate, entry.evaluations,
                      "entry (n_dot_v " + format_number(mu) + ", " + r + ")");
    row.scale.push_back(entry.scale);
    row.bias.push_back(entry.bias);
    row.error_estimate.push_back(entry.error_estimate);
    row.evaluations.push_back(double(entry.evaluations));
    if (settings_.cloth) {
      const auto cloth = brdf::integrate_cloth_albedo(mu, a, settings_.integration);
      require_converged(cloth.converged, cloth.error_estimate, cloth.evaluations,
                        "cloth entry (n_dot_v " + format_number(mu) + ", " + r + ")");
      row.cloth.push_back(cloth.value);
      row.cloth_error.push_back(cloth.error_estimate);
      row.cloth_evaluations.push_back(double(cloth.evaluations));
    }
  }
  if (settings_.multiple_scattering) {
    const auto average = brdf::integrate_average_albedo(a, settings_.visibility, settings_.integration);
    require_converged(average.converged, average.error_estimate, average.evaluations, "average albedo at " + r);
    row.average_energy = average.value;
    row.average_energy_error = average.error_estimate;
  }
  return row;
}

void DfgTable::check_row(const runtime::StageItem&, const Row& row) const {
  const std::size_t cloth_length = settings_.cloth ? n_dot_v_.size() : 0;
  for (const auto* v : {&row.scale, &row.bias, &row.error_estimate, &row.evaluations})
    if (v->size() != n_dot_v_.size()) throw RunError("DFG row result has the wrong length");
  for (const auto* v : {&row.cloth, &row.cloth_error, &row.cloth_evaluations})
    if (v->size() != cloth_length) throw RunError("DFG row result has the wrong length");
}

std::vector<store::Block> DfgTable::row_blocks(const runtime::StageItem& at, const Row& row) const {
  const WorkItemId id = at.id;
  const std::uint64_t n = n_dot_v_.size();
  auto row_block = [&](const char* table, const std::vector<double>& values) {
    return store::Block{"dfg", table, {id.item, 0}, {1, n}, store::reals(values)};
  };
  auto cell_block = [&](const char* table, double value) {
    return store::Block{"dfg", table, {id.item}, {1}, {value}};
  };
  std::vector<store::Block> out = {row_block("scale", row.scale), row_block("bias", row.bias),
                                   row_block("error_estimate", row.error_estimate),
                                   row_block("evaluations", row.evaluations), cell_block("alpha", alpha(id.item))};
  if (settings_.multiple_scattering) {
    std::vector<double> energy(n);
    for (std::size_t i = 0; i < n; ++i) energy[i] = row.scale[i] + row.bias[i];
    out.push_back(row_block("energy", std::move(energy)));
    out.push_back(cell_block("average_energy", row.average_energy));
  }
  if (settings_.cloth) {
    out.push_back(row_block("cloth", row.cloth));
    out.push_back(row_block("cloth_error_estimate", row.cloth_error));
    out.push_back(row_block("cloth_evaluations", row.cloth_evaluations));
  }
  return out;
}

void DfgTable::fold_row(Summary& sum, const runtime::StageItem&, const Row& row) const {
  for (std::size_t i = 0; i < row.scale.size(); ++i) {
    sum.worst_error = std::max(sum.worst_error, row.error_estimate[i]);
    sum.above_tolerance += row.error_estimate[i] > settings_.integration.abs_tolerance;
    sum.evaluations += row.evaluations[i];
    ++sum.entries;
    if (settings_.cloth) {
      sum.worst_error = std::max(sum.worst_error, row.cloth_error[i]);
      sum.above_tolerance += row.cloth_error[i] > settings_.integration.abs_tolerance;
    }
  }
}

std::string DfgTable::headline_of(const Summary& sum) const {
  if (sum.entries == 0) return "no entries yet";
  char text[200];
  std::snprintf(text, sizeof text, "%llu entries, max error estimate %.2g (tolerance %.2g%s), %.0f evaluations/entry",
                static_cast<unsigned long long>(sum.entries), sum.worst_error, settings_.integration.abs_tolerance,
                sum.above_tolerance ? (", " + std::to_string(sum.above_tolerance) + " above it").c_str() : "",
                sum.evaluations / double(sum.entries));
  return text;
}

}  // namespace pbrfit::jobs::lut
