// Must NOT compile: the engines form an order (docs/ARCHITECTURE.md), and brdf sits below ltc, so a brdf source
// that includes ltc would close a cycle. The test "layers: brdf cannot include ltc (no engine cycle)" builds
// this file with brdf's flags and expects the build to fail.
#include "pbrfit/brdf/ggx_lobe.hpp"
#include "pbrfit/ltc/lobe_moments.hpp"

int brdf_reaching_up_into_ltc() { return 0; }
