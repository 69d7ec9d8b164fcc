// What one contact method keeps per contact point from one step to the next, beyond the impulses
// every method reports in ContactPoint: soft step's last-substep impulses, micro's bounce mark,
// the reference's contact states. Each method owns one PointMemory of its own State; the world
// and the other methods never see it.
#pragma once

#include <algorithm>
#include <array>
#include <tuple>
#include <vector>

#include "impulse2d/body.h"
#include "impulse2d/contact.h"

namespace impulse2d {

/// Per-point state of one method, carried between steps as the world carries impulses: matched by
/// the pair's two bodies and the point's feature id. Each solve calls `recall` on the manifolds
/// it solves, reads `recalled` (State{} for a point new this step), `store`s each point's state as
/// the solve ends, then `remember`s. A pair that was not solved because neither body is awake
/// keeps its states until it wakes, as the world keeps its manifold; any other point not solved
/// is gone.
template <class State>
class PointMemory {
 public:
  /// Looks up the state each point of `manifolds` ended its last solve with.
  void recall(const std::vector<Manifold>& manifolds) {
    current_.assign(manifolds.size(), {State{}, State{}});
    for (int m = 0; m < static_cast<int>(manifolds.size()); ++m) {
      const Manifold& manifold = manifolds[m];
      auto entry = std::lower_bound(entries_.begin(), entries_.end(), manifold, pairBefore);
      for (; entry != entries_.end() && samePair(*entry, manifold); ++entry) {
        for (int i = 0; i < manifold.pointCount; ++i) {
          if (manifold.points[i].id == entry->id) current_[m][i] = entry->state;
        }
      }
    }
  }

  /// The state point `point` of manifold `manifold` (indices into recall's manifolds) ended its
  /// last solve with.
  const State& recalled(int manifold, int point) const { return current_[manifold][point]; }

  /// The state point `point` of manifold `manifold` ends this solve with.
  void store(int manifold, int point, const State& state) { current_[manifold][point] = state; }

  /// Keeps what was stored for the next solve, with the states of the pairs whose bodies all
  /// sleep (or are static); `manifolds` are recall's.
  void remember(const std::vector<Manifold>& manifolds, const std::vector<Body>& bodies) {
    next_.clear();
    for (int m = 0; m < static_cast<int>(manifolds.size()); ++m) {
      const Manifold& manifold = manifolds[m];
      for (int i = 0; i < manifold.pointCount; ++i) {
        next_.push_back({manifold.bodyA, manifold.bodyB, manifold.points[i].id, current_[m][i]});
      }
    }
    const auto solved = static_cast<std::ptrdiff_t>(next_.size());
    for (const Entry& entry : entries_) {
      if (!bodies[entry.bodyA].isAwake() && !bodies[entry.bodyB].isAwake()) next_.push_back(entry);
    }
    if (std::is_sorted(next_.begin(), next_.begin() + solved, entryBefore)) {
      std::inplace_merge(next_.begin(), next_.begin() + solved, next_.end(), entryBefore);
    } else {
      std::stable_sort(next_.begin(), next_.end(), entryBefore);
    }
    entries_.swap(next_);
  }

 private:
  struct Entry {
    int bodyA;
    int bodyB;
    FeatureId id;
    State state;
  };

  static bool entryBefore(const Entry& a, const Entry& b) {
    return std::tie(a.bodyA, a.bodyB) < std::tie(b.bodyA, b.bodyB);
  }
  static bool pairBefore(const Entry& entry, const Manifold& manifold) {
    return std::tie(entry.bodyA, entry.bodyB) < std::tie(manifold.bodyA, manifold.bodyB);
  }
  static bool samePair(const Entry& entry, const Manifold& manifold) {
    return entry.bodyA == manifold.bodyA && entry.bodyB == manifold.bodyB;
  }

  std::vector<Entry> entries_;  ///< sorted by (bodyA, bodyB)
  std::vector<Entry> next_;
  std::vector<std::array<State, 2>> current_;
};

}  // namespace impulse2d
