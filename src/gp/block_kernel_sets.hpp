#pragma once
// The batch interpreter's block loop (a schedule run over every block of rows, block_kernels.hpp for each
// operator) in each kernel set (core/kernel_set.hpp), and the one of the set a process uses. Each set's
// loop is compiled in a file of its own for its instruction set (block_kernels_isa_<set>.cpp), with the
// operators inlined into it: the choice costs one indirect call per evaluation, not one per operator.
#include <cstddef>

#include "block_schedule.hpp"
#include "pbrfit/core/kernel_set.hpp"

namespace pbrfit::gp::detail {

// Receives each block's output values, rows [first, first + n).
template <class T>
struct BlockSink {
  void (*take)(void* context, std::size_t first, std::size_t n, const T* values);
  void* context;
};

// Runs the schedule over rows [0, rows) in blocks of block_rows, giving each block's output to the sink.
template <class T>
using ScheduleRunner = void (*)(const BlockSchedule<T>& schedule, std::size_t rows, std::size_t block_rows,
                                BlockSink<T> sink);

#define PBRFIT_DECLARE_SCHEDULE_RUNNERS(set)                                                                  \
  namespace set {                                                                                             \
  void run_schedule_f32(const BlockSchedule<float>& schedule, std::size_t rows, std::size_t block_rows,      \
                        BlockSink<float> sink);                                                               \
  void run_schedule_f64(const BlockSchedule<double>& schedule, std::size_t rows, std::size_t block_rows,     \
                        BlockSink<double> sink);                                                              \
  }
PBRFIT_DECLARE_SCHEDULE_RUNNERS(generic)
PBRFIT_DECLARE_SCHEDULE_RUNNERS(avx2)
PBRFIT_DECLARE_SCHEDULE_RUNNERS(avx512)
#undef PBRFIT_DECLARE_SCHEDULE_RUNNERS

template <class T>
ScheduleRunner<T> schedule_runner(KernelSet set) {
  constexpr bool f32 = sizeof(T) == sizeof(float);
  switch (set) {
#if defined(PBRFIT_X86_KERNELS)
    case KernelSet::avx512:
      if constexpr (f32) return avx512::run_schedule_f32; else return avx512::run_schedule_f64;
    case KernelSet::avx2:
      if constexpr (f32) return avx2::run_schedule_f32; else return avx2::run_schedule_f64;
#endif
    default:
      if constexpr (f32) return generic::run_schedule_f32; else return generic::run_schedule_f64;
  }
}

}  // namespace pbrfit::gp::detail
