#pragma once
// Durations for log lines: "12.3s", "4m05s", "2h17m". Private to the runtime.
#include <string>

namespace pbrfit::runtime {

std::string duration_text(double seconds);

}  // namespace pbrfit::runtime
