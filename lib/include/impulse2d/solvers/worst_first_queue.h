// An indexed max-heap: the worst-first choice of the micro-collision resolver without rescanning
// every contact at every iteration. Only the items that still need resolving (key above the
// threshold) wait in the heap: changing the key of one that does costs O(log waiting), and of one
// that stays below the threshold O(1), so a nearly converged pile costs little per impulse.
#pragma once

#include <vector>

namespace impulse2d {

class WorstFirstQueue {
 public:
  /// Items 0..keys.size()-1 with the given keys; those above `threshold` wait in the queue.
  void reset(const std::vector<double>& keys, double threshold);
  /// Changes one item's key: it joins, moves within or leaves the queue.
  void update(int item, double key);
  /// The waiting item with the largest key; the queue must not be empty.
  int worst() const { return heap_[0].item; }
  double worstKey() const { return heap_[0].key; }
  /// No item's key is above the threshold.
  bool empty() const { return heap_.empty(); }
  /// Items waiting (keys above the threshold).
  int size() const { return int(heap_.size()); }
  /// The sum of the waiting items' keys, kept as they join, change and leave.
  double waitingTotal() const { return waitingTotal_; }

 private:
  struct Entry {
    double key;
    int item;
  };
  static constexpr int kOutside = -1;  ///< slotOf_ of an item not waiting
  /// Children per node: a 4-ary heap is half as deep as a binary one, and a node's four children
  /// share a cache line or two.
  static constexpr int kArity = 4;

  void place(int slot, const Entry& entry);
  void siftUp(int slot, Entry entry);
  void siftDown(int slot, Entry entry);
  void push(const Entry& entry);
  void remove(int slot);

  std::vector<Entry> heap_;  ///< waiting items in heap order, each with its key
  std::vector<int> slotOf_;  ///< where each item sits in heap_, or kOutside
  double threshold_ = 0.0;
  double waitingTotal_ = 0.0;
};

}  // namespace impulse2d
