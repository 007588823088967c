#pragma once
// pbrfit's read-only files (the data directory, the report package, the Slurm batch template), found at
// run time rather than compiled in, so one binary works from its build tree, installed under a prefix, or
// copied to a cluster with the files beside it.
//
// share_directory(): $PBRFIT_SHARE_DIR when set; else the first `share/pbrfit` folder in the running
// program's directory or in one of its three parents (an installed `<prefix>/bin/pbrfit` finds
// `<prefix>/share/pbrfit`; a build tree has `share/pbrfit` made by CMake, linking to the sources).
// data_directory(): $PBRFIT_DATA_DIR when set, else share_directory() + "/data".
// Both throw RunError naming the places looked at when there is none.
#include <string>

namespace pbrfit::store {

std::string share_directory();
std::string data_directory();

}  // namespace pbrfit::store
