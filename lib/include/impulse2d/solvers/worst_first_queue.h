// An indexed max-heap: the worst-first choice of the micro-collision resolver without rescanning
// every contact at every iteration. Only the items that may still need resolving wait in the
// heap. A key that rises moves its item up at once, O(log waiting); a key that falls costs O(1):
// the heap keeps the old key as a bound above the new one, and the item is moved down (or out)
// only if it reaches the top. An impulse changes the keys of the points around it, most of them
// falling, so most changes cost nothing (docs/design/micro-collision-cost.md).
#pragma once

#include <vector>

namespace impulse2d {

/// The items waiting to be resolved, worst (largest key) first: a heap that settles lazily.
class WorstFirstQueue {
 public:
  /// Items 0..keys.size()-1 with the given keys; those above `threshold` wait in the queue.
  void reset(const std::vector<double>& keys, double threshold);
  /// Changes one item's key: it joins the queue, rises in it, or has its fall noted.
  void update(int item, double key);
  /// The waiting item with the largest key; the queue must not be empty.
  int worst() {
    settle();
    return heap_[0].item;
  }
  /// The key of worst(); the queue must not be empty.
  double worstKey() {
    settle();
    return heap_[0].bound;
  }
  /// No item's key is above the threshold.
  bool empty() {
    settle();
    return heap_.empty();
  }
  /// Items waiting (keys above the threshold).
  int size() const { return waiting_; }
  /// The sum of the waiting items' keys, kept as they join, change and leave.
  double waitingTotal() const { return waitingTotal_; }

 private:
  struct Entry {
    double bound;  ///< the item's key when it last moved in the heap: at least its key now
    int item;
  };
  static constexpr int kOutside = -1;  ///< slotOf_ of an item not in the heap
  /// Children per node: a 4-ary heap is half as deep as a binary one, and a node's four children
  /// share a cache line or two.
  static constexpr int kArity = 4;

  void settle();
  void place(int slot, const Entry& entry);
  void siftUp(int slot, Entry entry);
  void siftDown(int slot, Entry entry);
  void push(const Entry& entry);
  void remove(int slot);

  std::vector<double> keys_;  ///< every item's key now
  std::vector<Entry> heap_;   ///< items that may wait, in heap order of their bounds
  std::vector<int> slotOf_;   ///< where each item sits in heap_, or kOutside
  double threshold_ = 0.0;
  double waitingTotal_ = 0.0;
  int waiting_ = 0;
};

}  // namespace impulse2d
