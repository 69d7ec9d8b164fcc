// An indexed max-heap: the worst-first choice of the micro-collision resolver without rescanning
// every contact at every iteration. Changing one item's key costs O(log n), so resolving a scene
// costs O(impulses · log contacts) rather than O(impulses · contacts).
#pragma once

#include <vector>

namespace impulse2d {

class WorstFirstQueue {
 public:
  /// Items 0..keys.size()-1 with the given keys.
  void reset(const std::vector<double>& keys);
  /// Changes one item's key and restores the heap order.
  void update(int item, double key);
  /// The item with the largest key; the queue must not be empty.
  int worst() const { return heap_[0]; }
  double worstKey() const { return keys_[heap_[0]]; }
  bool empty() const { return heap_.empty(); }

 private:
  bool above(int slotA, int slotB) const { return keys_[heap_[slotA]] > keys_[heap_[slotB]]; }
  void swapSlots(int slotA, int slotB);
  void siftUp(int slot);
  void siftDown(int slot);

  std::vector<int> heap_;     ///< items in heap order
  std::vector<int> slotOf_;   ///< where each item sits in heap_
  std::vector<double> keys_;  ///< by item
};

}  // namespace impulse2d
