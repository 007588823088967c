// Must NOT compile: an engine may not see the store's headers (docs/ARCHITECTURE.md). The test
// "layers: an engine cannot include the store" builds this file and expects the build to fail.
#include "pbrfit/integrate/box.hpp"
#include "pbrfit/store/result_file.hpp"

int engine_reaching_into_the_store() { return int(pbrfit::store::host_name().size()); }
