#include "pbrfit/core/kernel_set.hpp"

#include <catch2/catch_test_macros.hpp>
#include <stdexcept>
#include <string>

using pbrfit::KernelSet;

TEST_CASE("kernel sets: names round-trip, and only available sets can be used", "[core]") {
  for (auto set : {KernelSet::generic, KernelSet::avx2, KernelSet::avx512})
    CHECK(pbrfit::parse_kernel_set(pbrfit::kernel_set_name(set)) == set);
  CHECK_FALSE(pbrfit::parse_kernel_set("AVX2").has_value());
  CHECK_FALSE(pbrfit::parse_kernel_set("sse2").has_value());

  CHECK(pbrfit::kernel_set_available(KernelSet::generic));
  const KernelSet best = pbrfit::best_kernel_set();
  CHECK(pbrfit::kernel_set_available(best));
  CHECK(pbrfit::active_kernel_set() == best);  // a process starts with its best set
  const std::string listed = pbrfit::available_kernel_sets();
  CHECK(listed.starts_with("generic"));
  CHECK(listed.ends_with(std::string(pbrfit::kernel_set_name(best))));
  // avx512 implies avx2 here (its kernels are compiled with both).
  if (pbrfit::kernel_set_available(KernelSet::avx512)) CHECK(pbrfit::kernel_set_available(KernelSet::avx2));

  pbrfit::use_kernel_set(KernelSet::generic);
  CHECK(pbrfit::active_kernel_set() == KernelSet::generic);
  CHECK_THROWS_AS(pbrfit::use_kernel_set(static_cast<KernelSet>(7)), std::invalid_argument);
  CHECK(pbrfit::active_kernel_set() == KernelSet::generic);
  pbrfit::use_kernel_set(best);
}
