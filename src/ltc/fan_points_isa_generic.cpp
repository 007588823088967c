// The fan integrand's points compiled for the build's own target (no instruction-set flags)
// (core/kernel_set.hpp); cmake/layers.cmake gives files named *_isa_<set>.cpp their flags, contraction into FMA off.
#define PBRFIT_KERNEL_ISA generic
#include "fan_points_kernels.hpp"
