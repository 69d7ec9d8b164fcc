// Union-find over body indices: the islands of bodies joined by contacts, which the world puts to
// sleep together and the reference solves as one system each.
#pragma once

#include <numeric>
#include <vector>

namespace impulse2d {

/// Disjoint sets of the indices 0…n−1, joined pair by pair; path halving keeps the trees flat.
class UnionFind {
 public:
  /// n singletons.
  void reset(int count) {
    parent_.resize(count);
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  /// The representative of i's set.
  int root(int i) {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];
      i = parent_[i];
    }
    return i;
  }
  /// Joins a's set to b's.
  void join(int a, int b) {
    const int rootOfB = root(b);
    parent_[root(a)] = rootOfB;
  }
  /// n
  int size() const { return static_cast<int>(parent_.size()); }

 private:
  std::vector<int> parent_;
};

}  // namespace impulse2d
