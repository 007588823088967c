#include "pbrfit/runtime/mpi_session.hpp"

#include <mpi.h>

#include <cstdlib>
#include <string>

#include "pbrfit/core/error.hpp"

namespace pbrfit::runtime {

MpiSession::MpiSession() {
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
    throw RunError("MPI initialization failed");
  if (provided < MPI_THREAD_FUNNELED) throw RunError("the MPI library lacks MPI_THREAD_FUNNELED support");
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  MPI_Comm_size(node, &local_size_);
  MPI_Comm_free(&node);
}

MpiSession::~MpiSession() {
  if (finalize_) MPI_Finalize();
}

int MpiSession::broadcast_from_coordinator(int value) const {
  MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value;
}

int MpiSession::minimum_over_ranks(int value) const {
  int least = value;
  MPI_Allreduce(&value, &least, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return least;
}

std::vector<int> MpiSession::gather_to_coordinator(int value) const {
  std::vector<int> values(coordinator() ? std::size_t(size_) : 0);
  MPI_Gather(&value, 1, MPI_INT, values.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  return values;
}

int launcher_rank() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK", "SLURM_PROCID"}) {
    if (const char* value = std::getenv(name)) return std::atoi(value);
  }
  return 0;
}

}  // namespace pbrfit::runtime
