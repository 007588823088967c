#pragma once
// The binomial tree over ranks 0..size-1 that stage contexts travel along: rank r receives from r with
// its highest set bit cleared and passes on to r + 2^k for every 2^k > r below size. No rank sends a
// context more than log2(size) times, and it reaches every rank after at most log2(size) hops.
#include <vector>

namespace pbrfit::runtime {

std::vector<int> relay_children(int rank, int size);
int relay_parent(int rank);  // -1 for rank 0

}  // namespace pbrfit::runtime
