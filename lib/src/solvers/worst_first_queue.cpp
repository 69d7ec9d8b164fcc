// The indexed max-heap behind worst-first resolution.
#include "impulse2d/solvers/worst_first_queue.h"

#include <algorithm>

namespace impulse2d {

void WorstFirstQueue::reset(const std::vector<double>& keys, double threshold) {
  threshold_ = threshold;
  keys_ = keys;
  heap_.clear();
  waitingTotal_ = 0.0;
  waiting_ = 0;
  slotOf_.assign(keys.size(), kOutside);
  for (int item = 0; item < static_cast<int>(keys.size()); ++item) {
    if (keys[item] <= threshold_) continue;
    place(static_cast<int>(heap_.size()), {keys[item], item});
    waitingTotal_ += keys[item];
    ++waiting_;
  }
  for (int slot = static_cast<int>(heap_.size()) / 2 - 1; slot >= 0; --slot)
    siftDown(slot, heap_[slot]);
}

void WorstFirstQueue::update(int item, double key) {
  const double old = keys_[item];
  keys_[item] = key;
  if (old > threshold_) {
    waitingTotal_ -= old;
    --waiting_;
  }
  if (key > threshold_) {
    waitingTotal_ += key;
    ++waiting_;
  }
  const int slot = slotOf_[item];
  if (slot == kOutside) {
    if (key > threshold_) push({key, item});
  } else if (key > heap_[slot].bound) {
    siftUp(slot, {key, item});
  }
}

// Until the top entry's bound is its item's key: an item whose key fell is moved down to its
// place, or out if it no longer waits. Every other bound is at least its item's key, so the top
// is then the item with the largest key.
void WorstFirstQueue::settle() {
  while (!heap_.empty()) {
    const Entry top = heap_[0];
    const double key = keys_[top.item];
    if (key == top.bound) return;
    if (key > threshold_) {
      siftDown(0, {key, top.item});
    } else {
      remove(0);
    }
  }
}

// Puts the entry at the slot (which may be one past the end) and records where it is.
void WorstFirstQueue::place(int slot, const Entry& entry) {
  if (slot == static_cast<int>(heap_.size())) heap_.push_back(entry);
  heap_[slot] = entry;
  slotOf_[entry.item] = slot;
}

// Moves the hole at `slot` up past every parent with a smaller key, then fills it with entry.
void WorstFirstQueue::siftUp(int slot, Entry entry) {
  while (slot > 0) {
    const int parent = (slot - 1) / kArity;
    if (!(entry.bound > heap_[parent].bound)) break;
    place(slot, heap_[parent]);
    slot = parent;
  }
  place(slot, entry);
}

// Moves the hole at `slot` down past every larger child, then fills it with entry.
void WorstFirstQueue::siftDown(int slot, Entry entry) {
  const int count = static_cast<int>(heap_.size());
  for (;;) {
    const int first = kArity * slot + 1;
    if (first >= count) break;
    int child = first;
    for (int other = first + 1; other < std::min(first + kArity, count); ++other) {
      if (heap_[other].bound > heap_[child].bound) child = other;
    }
    if (!(heap_[child].bound > entry.bound)) break;
    place(slot, heap_[child]);
    slot = child;
  }
  place(slot, entry);
}

void WorstFirstQueue::push(const Entry& entry) {
  heap_.push_back(entry);
  siftUp(static_cast<int>(heap_.size()) - 1, entry);
}

// Takes the entry at `slot` out: the last entry fills the hole and moves to its place.
void WorstFirstQueue::remove(int slot) {
  slotOf_[heap_[slot].item] = kOutside;
  const Entry last = heap_.back();
  heap_.pop_back();
  if (slot == static_cast<int>(heap_.size())) return;
  if (slot > 0 && last.bound > heap_[(slot - 1) / kArity].bound) {
    siftUp(slot, last);
  } else {
    siftDown(slot, last);
  }
}

}  // namespace impulse2d
