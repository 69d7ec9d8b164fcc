// What one contact method keeps per contact point from one step to the next, beyond the impulses
// every method reports in ContactPoint: soft step's last-substep impulses, micro's bounce mark,
// the reference's contact states. Each method owns one PointMemory of its own State; the world
// and the other methods never see it.
#pragma once

#include <algorithm>
#include <array>
#include <utility>
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
  /// Looks up the state each point of `manifolds` ended its last solve with. One walk when the
  /// manifolds come sorted by their bodies, as the world gives them; a search for any that do not.
  void recall(const std::vector<Manifold>& manifolds) {
    current_.assign(manifolds.size(), {State{}, State{}});
    auto entry = entries_.cbegin();
    for (int m = 0; m < static_cast<int>(manifolds.size()); ++m) {
      const Manifold& manifold = manifolds[m];
      if (entry != entries_.cbegin() && pairOf(manifold) < pairOf(*(entry - 1))) {
        entry = std::lower_bound(entries_.cbegin(), entries_.cend(), pairOf(manifold),
                                 [](const Entry& e, const Pair& pair) { return pairOf(e) < pair; });
      }
      while (entry != entries_.cend() && pairOf(*entry) < pairOf(manifold)) ++entry;
      for (; entry != entries_.cend() && pairOf(*entry) == pairOf(manifold); ++entry) {
        const int i = manifold.pointMadeBy(entry->id);
        if (i >= 0) current_[m][i] = entry->state;
      }
    }
  }

  /// The state point `point` of manifold `manifold` (indices into recall's manifolds) ended its
  /// last solve with.
  const State& recalled(int manifold, int point) const { return current_[manifold][point]; }

  /// The state point `point` of manifold `manifold` ends this solve with.
  void store(int manifold, int point, const State& state) { current_[manifold][point] = state; }

  /// Keeps what was stored for the next solve, with the states of the pairs whose bodies all
  /// sleep (or are static); `manifolds` are recall's. One merge walk of the stored and the kept
  /// states when the manifolds come sorted; a sort when they do not.
  void remember(const std::vector<Manifold>& manifolds, const std::vector<Body>& bodies) {
    next_.clear();
    bool sorted = true;
    auto old = entries_.cbegin();
    for (int m = 0; m < static_cast<int>(manifolds.size()); ++m) {
      const Manifold& manifold = manifolds[m];
      if (m > 0 && pairOf(manifold) < pairOf(manifolds[m - 1])) sorted = false;
      for (; old != entries_.cend() && pairOf(*old) < pairOf(manifold); ++old) {
        keepAsleep(*old, bodies);
      }
      while (old != entries_.cend() && pairOf(*old) == pairOf(manifold)) ++old;  // solved again
      for (int i = 0; i < manifold.pointCount; ++i) {
        next_.push_back({manifold.bodyA, manifold.bodyB, manifold.points[i].id, current_[m][i]});
      }
    }
    for (; old != entries_.cend(); ++old) keepAsleep(*old, bodies);
    if (!sorted) {
      std::stable_sort(next_.begin(), next_.end(),
                       [](const Entry& a, const Entry& b) { return pairOf(a) < pairOf(b); });
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

  /// An old state whose pair was not solved: kept while no body of the pair is awake.
  void keepAsleep(const Entry& entry, const std::vector<Body>& bodies) {
    if (!bodies[entry.bodyA].isAwake() && !bodies[entry.bodyB].isAwake()) next_.push_back(entry);
  }

  /// The two bodies of an entry or a manifold: states and manifolds are ordered by them.
  using Pair = std::pair<int, int>;
  template <class T>
  static Pair pairOf(const T& entryOrManifold) {
    return {entryOrManifold.bodyA, entryOrManifold.bodyB};
  }

  std::vector<Entry> entries_;  ///< sorted by (bodyA, bodyB)
  std::vector<Entry> next_;
  std::vector<std::array<State, 2>> current_;
};

}  // namespace impulse2d
