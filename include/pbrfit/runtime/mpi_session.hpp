#pragma once
// The MPI environment of one process: initialized once (MPI_THREAD_FUNNELED: only the main thread calls
// MPI; compute threads never do), finalized on destruction. MPI errors are returned, not fatal, so a
// dead peer is an error pbrfit reports, not an abort that skips the checkpoint.
#include <vector>

namespace pbrfit::runtime {

class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  int ranks_on_this_node() const { return local_size_; }
  bool coordinator() const { return rank_ == 0; }

  // After a rank was lost: the process ends without MPI_Finalize (which would wait for the lost rank);
  // the launcher then ends the others.
  void leave_without_finalize() { finalize_ = false; }

  // Collective. Every rank returns rank 0's value.
  int broadcast_from_coordinator(int value) const;
  // Collective. Every rank returns the least of the ranks' values.
  int minimum_over_ranks(int value) const;
  // Collective. Rank 0 gets every rank's value (by rank); the others get an empty vector.
  std::vector<int> gather_to_coordinator(int value) const;

 private:
  int rank_ = 0;
  int size_ = 1;
  int local_size_ = 1;
  bool finalize_ = true;
};

// The rank this process will have, read from the launcher's environment before MPI starts
// (OpenMPI, PMIx, Slurm); 0 when launched alone. Lets only one rank report input errors.
int launcher_rank();

}  // namespace pbrfit::runtime
