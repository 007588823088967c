// The closed-form lobes' batch kernels compiled for AVX2 with FMA (core/kernel_set.hpp);
// cmake/layers.cmake gives files named *_isa_<set>.cpp their flags, contraction into FMA off.
#if defined(PBRFIT_X86_KERNELS)
#define PBRFIT_KERNEL_ISA avx2
#include "closed_form_batch_kernels.hpp"
#endif
