#include "pbrfit/jobs/lut/lut_kind.hpp"

#include "pbrfit/jobs/lut/dfg_table.hpp"
#include "pbrfit/jobs/lut/disney_diffuse_table.hpp"

namespace pbrfit::jobs::lut {

namespace {

spec::Schema lut_schema() {
  spec::Schema s("lut");
  s.choice("function", {"dfg", "disney_diffuse"},
           "the table to compute: dfg = split-sum environment BRDF of GGX; disney_diffuse = SH, beta and ZH of the "
           "Disney diffuse environment lobe")
      .require();
  s.choice("visibility", {"height_correlated", "separable", "separable_schlick"},
           "Smith masking-shadowing: height_correlated (Filament), separable (exact Smith G1 G1), "
           "separable_schlick (UE4 / Karis, k = alpha / 2)")
      .defaults_to(std::string("height_correlated"));
  s.boolean("multiple_scattering", "also tabulate E(n.v) and the Kulla-Conty average albedo per roughness")
      .defaults_to(false);
  s.boolean("cloth", "also tabulate the cloth channel: the albedo of Charlie sheen with Neubelt's visibility, as "
                     "Filament's cmgen computes it, alpha from the same roughness axis")
      .defaults_to(false);
  s.choice("roughness", {"perceptual", "linear", "gloss"},
           "roughness axis: perceptual (alpha = r^2), linear (alpha = r), gloss (alpha = (1 - g)^4, Narkowicz)")
      .defaults_to(std::string("perceptual"));
  s.integer_list("resolution", 2, 2, "entries along [n_dot_v, roughness]")
      .range(1, 8192)
      .defaults_to(std::vector<std::int64_t>{128, 128});
  s.choice("samples", {"centres", "edges"}, "axis samples at cell centres (i + 0.5) / n or edges i / (n - 1)")
      .defaults_to(std::string("centres"));
  s.number("tolerance", "absolute error allowed per entry").range(1e-12, 1e-2).defaults_to(1e-6);
  s.integer("max_evaluations", "integrand evaluations allowed per entry before giving up on the tolerance")
      .range(1000, 1'000'000'000)
      .defaults_to(std::int64_t{20'000'000});
  return s;
}

brdf::SmithVisibility visibility_from(const std::string& name) {
  if (name == "separable") return brdf::SmithVisibility::separable;
  if (name == "separable_schlick") return brdf::SmithVisibility::separable_schlick;
  return brdf::SmithVisibility::height_correlated;
}

brdf::RoughnessParametrization roughness_from(const std::string& name) {
  if (name == "linear") return brdf::RoughnessParametrization::linear;
  if (name == "gloss") return brdf::RoughnessParametrization::gloss;
  return brdf::RoughnessParametrization::perceptual;
}

DfgSettings dfg_settings(const spec::Section& lut) {
  DfgSettings s;
  s.visibility = visibility_from(lut.get_string("visibility"));
  s.roughness = roughness_from(lut.get_string("roughness"));
  s.multiple_scattering = lut.get_bool("multiple_scattering");
  s.cloth = lut.get_bool("cloth");
  const auto& resolution = lut.get_int_list("resolution");
  s.n_dot_v_count = std::size_t(resolution[0]);
  s.roughness_count = std::size_t(resolution[1]);
  s.placement = placement_from(lut.get_string("samples"));
  if (s.placement == Placement::edges && (s.n_dot_v_count < 2 || s.roughness_count < 2))
    lut.reject("resolution", "needs at least 2 entries per axis when samples is 'edges'");
  s.integration.abs_tolerance = lut.get_number("tolerance");
  s.integration.max_evaluations = std::size_t(lut.get_int("max_evaluations"));
  return s;
}

// disney_diffuse: the DFG-only keys are refused, so a key never silently does nothing.
DisneyDiffuseSettings disney_settings(const spec::Section& lut) {
  for (const char* key : {"visibility", "multiple_scattering", "roughness", "cloth"})
    if (lut.given(key)) lut.reject(key, "applies to function 'dfg' only");
  const DfgSettings common = dfg_settings(lut);
  DisneyDiffuseSettings s;
  s.n_dot_v_count = common.n_dot_v_count;
  s.roughness_count = common.roughness_count;
  s.placement = common.placement;
  s.integration = common.integration;
  return s;
}

std::unique_ptr<runtime::Workload> make_lut(const spec::JobSpec& job) {
  if (job.kind_section.get_string("function") == "disney_diffuse")
    return std::make_unique<DisneyDiffuseTable>(disney_settings(job.kind_section));
  return std::make_unique<DfgTable>(dfg_settings(job.kind_section));
}

}  // namespace

JobKind lut_kind() {
  return {"lut", "reference tables by deterministic adaptive integration (function: dfg, disney_diffuse)", lut_schema(),
          make_lut};
}

}  // namespace pbrfit::jobs::lut
