// The batch interpreter's block loop compiled for AVX2 with FMA (core/kernel_set.hpp);
// cmake/layers.cmake gives files named *_isa_<set>.cpp their flags, contraction into FMA off.
#if defined(PBRFIT_X86_KERNELS)
#define PBRFIT_KERNEL_ISA avx2
#define PBRFIT_KERNEL_LIBMVEC 256  // tan, asin, acos and atan by glibc's libmvec
#include "block_kernels.hpp"
#endif
