// The indexed max-heap behind worst-first resolution.
#include "impulse2d/solvers/worst_first_queue.h"

#include <utility>

namespace impulse2d {

void WorstFirstQueue::reset(const std::vector<double>& keys) {
  keys_ = keys;
  const int count = int(keys_.size());
  heap_.resize(count);
  slotOf_.resize(count);
  for (int i = 0; i < count; ++i) heap_[i] = slotOf_[i] = i;
  for (int slot = count / 2 - 1; slot >= 0; --slot) siftDown(slot);
}

void WorstFirstQueue::update(int item, double key) {
  const double old = keys_[item];
  keys_[item] = key;
  if (key > old) {
    siftUp(slotOf_[item]);
  } else {
    siftDown(slotOf_[item]);
  }
}

void WorstFirstQueue::swapSlots(int slotA, int slotB) {
  std::swap(heap_[slotA], heap_[slotB]);
  slotOf_[heap_[slotA]] = slotA;
  slotOf_[heap_[slotB]] = slotB;
}

void WorstFirstQueue::siftUp(int slot) {
  while (slot > 0) {
    const int parent = (slot - 1) / 2;
    if (!above(slot, parent)) return;
    swapSlots(slot, parent);
    slot = parent;
  }
}

void WorstFirstQueue::siftDown(int slot) {
  const int count = int(heap_.size());
  for (;;) {
    int largest = slot;
    for (int child : {2 * slot + 1, 2 * slot + 2}) {
      if (child < count && above(child, largest)) largest = child;
    }
    if (largest == slot) return;
    swapSlots(slot, largest);
    slot = largest;
  }
}

}  // namespace impulse2d
