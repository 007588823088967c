// The LTC batch kernels compiled for the build's own target (no instruction-set flags) (core/kernel_set.hpp);
// cmake/layers.cmake gives files named *_isa_<set>.cpp their flags, contraction into FMA off.
#define PBRFIT_KERNEL_ISA generic
#include "ltc_batch_kernels.hpp"
