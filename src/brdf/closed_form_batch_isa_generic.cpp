// The closed-form lobes' batch kernels compiled for the build's own target (no instruction-set flags) (core/kernel_set.hpp);
// cmake/layers.cmake gives files named *_isa_<set>.cpp their flags, contraction into FMA off.
#define PBRFIT_KERNEL_ISA generic
#include "closed_form_batch_kernels.hpp"
