#include "relay_tree.hpp"

namespace pbrfit::runtime {

std::vector<int> relay_children(int rank, int size) {
  std::vector<int> children;
  int step = 1;
  while (step <= rank) step <<= 1;
  for (; rank + step < size; step <<= 1) children.push_back(rank + step);
  return children;
}

int relay_parent(int rank) {
  if (rank == 0) return -1;
  int high = 1;
  while (high * 2 <= rank) high <<= 1;
  return rank - high;
}

}  // namespace pbrfit::runtime
