#include "pbrfit/gp/batch_interpreter.hpp"

#include <algorithm>
#include <stdexcept>

#include "block_kernel_sets.hpp"
#include "error_sums.hpp"

namespace pbrfit::gp {

// ErrorSums interleaves its partial sums by row index modulo 4 within a block: blocks starting at multiples
// of 4 make the sum's order, and so the error, independent of the block size.
static_assert(block_rows % 4 == 0);

template <class T>
BatchInterpreter<T>::BatchInterpreter(const Dataset& dataset, const ErrorOptions& error_options)
    : columns_(dataset.inputs.template cast<T>()),
      target_(dataset.target),
      error_options_(error_options),
      slots_(max_program_length * block_rows),
      constant_blocks_(max_program_length * max_operands * block_rows) {
  validate(dataset);
  const Eigen::Index n = dataset.inputs.rows();
  weights_ = dataset.weights.size() == 0 ? Eigen::ArrayXd::Ones(n) : dataset.weights;
  weight_sum_ = weights_.sum();
  error_scale_ = Eigen::ArrayXd::Ones(n);
  if (error_options.measure == ErrorMeasure::relative) {
    error_scale_ = 1.0 / target_.abs().max(error_options.relative_floor);
  }
}

template <class T>
template <class Sink>
void BatchInterpreter<T>::run(const Program& program, Sink& sink) {
  const auto schedule = detail::schedule_blocks<T>(program, columns_, slots_, constant_blocks_, block_rows);
  const detail::BlockSink<T> block_sink{
      [](void* context, std::size_t first, std::size_t n, const T* values) {
        (*static_cast<Sink*>(context))(first, n, values);
      },
      &sink};
  detail::schedule_runner<T>(active_kernel_set())(schedule, rows(), block_rows, block_sink);
}

template <class T>
void BatchInterpreter<T>::evaluate(const Program& program, std::span<T> out) {
  if (out.size() != rows()) throw std::invalid_argument("evaluate: the output span must have one value per row");
  auto copy = [&](std::size_t first, std::size_t n, const T* values) { std::copy_n(values, n, out.data() + first); };
  run(program, copy);
}

template <class T>
double BatchInterpreter<T>::error(const Program& program) {
  detail::ErrorSums sums;
  auto accumulate = [&](std::size_t first, std::size_t n, const T* values) {
    sums.add_block(values, target_.data() + first, weights_.data() + first, error_scale_.data() + first, n);
  };
  run(program, accumulate);
  return sums.error(error_options_.measure, weight_sum_);
}

template class BatchInterpreter<float>;
template class BatchInterpreter<double>;

}  // namespace pbrfit::gp
