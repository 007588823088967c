#include "pbrfit/store/result_layout.hpp"

#include <stdexcept>

namespace pbrfit::store {

const Axis& Group::axis(const std::string& axis_name) const {
  for (const auto& a : axes)
    if (a.name == axis_name) return a;
  throw std::logic_error("group '" + name + "' has no axis '" + axis_name + "'");
}

}  // namespace pbrfit::store
