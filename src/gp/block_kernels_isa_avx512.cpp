// The batch interpreter's block loop compiled for AVX-512 F, BW, DQ and VL (core/kernel_set.hpp);
// cmake/layers.cmake gives files named *_isa_<set>.cpp their flags, contraction into FMA off.
#if defined(PBRFIT_X86_KERNELS)
#define PBRFIT_KERNEL_ISA avx512
#define PBRFIT_KERNEL_LIBMVEC 512  // tan, asin, acos and atan by glibc's libmvec
#include "block_kernels.hpp"
#endif
