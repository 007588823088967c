#include "pbrfit/jobs/symreg/island_epoch.hpp"

#include "pbrfit/gp/program_bytes.hpp"

namespace pbrfit::jobs::symreg {

EncodedState encode_state(const IslandState& state) {
  return {gp::population_to_bytes(state.population), gp::archive_to_bytes(state.front), state.reached_target};
}

IslandState decode_state(const EncodedState& state, std::size_t inputs) {
  return {gp::population_from_bytes(state.population, inputs), gp::archive_from_bytes(state.front, inputs),
          state.reached_target};
}

EpochRecord epoch_record(const EpochResult& epoch, std::size_t inputs) {
  return {epoch.generation, gp::archive_from_bytes(epoch.state.front, inputs),
          gp::archive_from_bytes(epoch.additions, inputs), epoch.evaluations, epoch.best_error};
}

}  // namespace pbrfit::jobs::symreg
