#pragma once
// Shared by the tests of multi-versioned kernels (core/kernel_set.hpp): a kernel set for a scope.
#include "pbrfit/core/kernel_set.hpp"

namespace kernel_test {

// Uses a kernel set for its lifetime, then the one before.
class KernelSetScope {
 public:
  explicit KernelSetScope(pbrfit::KernelSet set) : saved_(pbrfit::active_kernel_set()) { pbrfit::use_kernel_set(set); }
  ~KernelSetScope() { pbrfit::use_kernel_set(saved_); }
  KernelSetScope(const KernelSetScope&) = delete;
  KernelSetScope& operator=(const KernelSetScope&) = delete;

 private:
  pbrfit::KernelSet saved_;
};

}  // namespace kernel_test
