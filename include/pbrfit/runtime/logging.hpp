#pragma once
// Log lines carry the elapsed time and the rank: "[   12.3s r0] info: message".
// Rank 0 logs at the chosen verbosity; other ranks log warnings and errors only (debug when verbose).
namespace pbrfit::runtime {

enum class Verbosity { quiet, normal, verbose };

void setup_logging(int rank, Verbosity verbosity);

}  // namespace pbrfit::runtime
