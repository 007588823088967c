#pragma once
// The instruction sets pbrfit's hot kernels are compiled for, and the one a process uses.
//
// Contract:
//  - generic: the build's own target (x86-64 baseline, SSE2); avx2: AVX2 with FMA; avx512: AVX-512 F, BW,
//    DQ and VL. A build has the avx2 and avx512 kernels on x86-64 with GCC or clang (PBRFIT_X86_KERNELS).
//  - A process starts with the best set both its CPU and its build have; use_kernel_set() changes it (a
//    job's ranks agree on the best set all of them have, runtime/mpi_session.hpp), before any kernel runs.
//  - What may differ between sets, and only that: results of the kernels' transcendental functions (the
//    vector exp, log, sin, cos, ... of Eigen, whose polynomials use FMA and whose lane counts differ, and in
//    the avx2 and avx512 sets glibc's vector tan, asin, acos and atan, whose code differs per set).
//    Arithmetic (+ - * /, min, max, abs, comparisons) and sqrt are compiled without contraction into FMA, so
//    they are bitwise the same in every set. On one machine every rank and thread uses the same set: results stay
//    identical across ranks, threads and resumptions there.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pbrfit {

enum class KernelSet : int { generic = 0, avx2 = 1, avx512 = 2 };

std::string_view kernel_set_name(KernelSet set);
// "generic", "avx2" or "avx512"; nothing for anything else.
std::optional<KernelSet> parse_kernel_set(std::string_view name);

// Whether this CPU can run the set and this build has it.
bool kernel_set_available(KernelSet set);
// The best available set.
KernelSet best_kernel_set();
// Every available set, generic first, best last.
std::vector<KernelSet> kernel_sets_available();
// The names of every available set, best last ("generic, avx2, avx512").
std::string available_kernel_sets();

KernelSet active_kernel_set();
// Throws std::invalid_argument naming the set when it is not available.
void use_kernel_set(KernelSet set);

}  // namespace pbrfit
