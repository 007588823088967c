#include "pbrfit/jobs/ebrdf/ebrdf_settings.hpp"

namespace pbrfit::jobs::ebrdf {

const char* component_name(pbrfit::ebrdf::Component c) {
  return c == pbrfit::ebrdf::Component::specular ? "specular" : "diffuse";
}

const char* fit_method_name(pbrfit::ebrdf::FitMethod m) {
  switch (m) {
    case pbrfit::ebrdf::FitMethod::descent: return "descent";
    case pbrfit::ebrdf::FitMethod::nelder_mead: return "nelder_mead";
    case pbrfit::ebrdf::FitMethod::sgd: return "sgd";
  }
  return "?";
}

}  // namespace pbrfit::jobs::ebrdf
