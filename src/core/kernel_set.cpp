#include "pbrfit/core/kernel_set.hpp"

#include <atomic>
#include <stdexcept>

namespace pbrfit {
namespace {

constexpr KernelSet all_sets[] = {KernelSet::generic, KernelSet::avx2, KernelSet::avx512};

bool cpu_has(KernelSet set) {
  switch (set) {
    case KernelSet::generic:
      return true;
#if defined(PBRFIT_X86_KERNELS)
    case KernelSet::avx2:
      return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    case KernelSet::avx512:
      return cpu_has(KernelSet::avx2) && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
             __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
#endif
    default:
      return false;
  }
}

std::atomic<int>& active() {
  static std::atomic<int> set{static_cast<int>(best_kernel_set())};
  return set;
}

}  // namespace

std::string_view kernel_set_name(KernelSet set) {
  switch (set) {
    case KernelSet::generic:
      return "generic";
    case KernelSet::avx2:
      return "avx2";
    case KernelSet::avx512:
      return "avx512";
  }
  return "unknown";
}

std::optional<KernelSet> parse_kernel_set(std::string_view name) {
  for (KernelSet set : all_sets)
    if (kernel_set_name(set) == name) return set;
  return std::nullopt;
}

bool kernel_set_available(KernelSet set) { return cpu_has(set); }

KernelSet best_kernel_set() { return kernel_sets_available().back(); }

std::vector<KernelSet> kernel_sets_available() {
  std::vector<KernelSet> sets;
  for (KernelSet set : all_sets)
    if (kernel_set_available(set)) sets.push_back(set);
  return sets;
}

std::string available_kernel_sets() {
  std::string names;
  for (KernelSet set : kernel_sets_available()) {
    if (!names.empty()) names += ", ";
    names += kernel_set_name(set);
  }
  return names;
}

KernelSet active_kernel_set() { return static_cast<KernelSet>(active().load(std::memory_order_relaxed)); }

void use_kernel_set(KernelSet set) {
  if (!kernel_set_available(set))
    throw std::invalid_argument("the kernel set " + std::string(kernel_set_name(set)) +
                                " is not available here (available: " + available_kernel_sets() + ")");
  active().store(static_cast<int>(set), std::memory_order_relaxed);
}

}  // namespace pbrfit
