// The fan integrand's points compiled for AVX2 with FMA (core/kernel_set.hpp);
// cmake/layers.cmake gives files named *_isa_<set>.cpp their flags, contraction into FMA off.
#if defined(PBRFIT_X86_KERNELS)
#define PBRFIT_KERNEL_ISA avx2
#include "fan_points_kernels.hpp"
#endif
