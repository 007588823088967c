#pragma once
// Text made of pieces in order: joined({"(", text, ")"}). Where GCC 12 warns falsely about
// `"literal" + std::string`, this says the same without the warning.
#include <initializer_list>
#include <string>
#include <string_view>

namespace pbrfit {

inline std::string joined(std::initializer_list<std::string_view> parts) {
  std::string text;
  for (std::string_view part : parts) text.append(part);
  return text;
}

}  // namespace pbrfit
