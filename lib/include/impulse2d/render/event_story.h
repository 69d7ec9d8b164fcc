// What one solver event did, in the lecture's words: which contact was resolved and why, its
// closing speed before and after, the impulse, the accelerative velocity, and whether friction
// held (|λt| against μλn). The text of a traced step's frames (trace.h) and of the browser's trace.
#pragma once

#include <string>
#include <vector>

#include "impulse2d/body.h"
#include "impulse2d/contact.h"
#include "impulse2d/solver.h"

namespace impulse2d::render {

/// What one event did, in the lecture's words: the lines a trace frame adds under its heads-up.
struct EventStory {
  /// "velocity 3: contact 5.0" (soft step: "substep 3: ..."): the thumbnail's caption
  std::string label;
  std::vector<std::string> lines;  ///< the heads-up lines
};

/// The story of `event`, from the bodies before its impulse (`before`) and after it (`after`),
/// under `solver` ("micro" picks the worst point first; the others sweep in order) with time step
/// dt. `partner` is the other point of the same manifold that one impulse resolved with this one
/// (the micro-collision resolver's pair of corners), -1 when it was resolved alone. Only the point
/// that closes fastest is called "the worst closing speed"; a frictionless contact gets no
/// friction line.
EventStory tellEvent(const SolverEvent& event, const std::vector<Body>& before,
                     const std::vector<Body>& after, const std::vector<Manifold>& manifolds,
                     const std::string& solver, double dt, int partner = -1);

/// Whether the event names a contact point of `manifolds` between two of `bodies`.
bool refersToPoint(const SolverEvent& event, const std::vector<Body>& bodies,
                   const std::vector<Manifold>& manifolds);
/// B's velocity relative to A's at `point` of the manifold.
Vec2 pointVelocity(const std::vector<Body>& bodies, const Manifold& manifold, const Vec2& point);

/// Tells the events of one step as they come, each from the bodies before its impulse: the
/// micro-collision resolver's pair impulse is two events that both start from the bodies before
/// it.
class EventTeller {
 public:
  /// The step starts from `bodies`.
  explicit EventTeller(std::vector<Body> bodies) : before_(std::move(bodies)) {}
  /// The velocities changed outside any event (SolverObserver::onVelocitiesChanged).
  void restart(const std::vector<Body>& bodies) { before_ = bodies; }
  /// The story of `event`, which left `bodies`, under `solver` with time step dt.
  EventStory tell(const SolverEvent& event, const std::vector<Body>& bodies,
                  const std::vector<Manifold>& manifolds, const std::string& solver, double dt);
  /// The bodies before the impulse the last event told belongs to.
  const std::vector<Body>& impulseBefore() const { return impulseBefore_; }

 private:
  std::vector<Body> before_;         ///< the bodies as the last event left them
  std::vector<Body> impulseBefore_;  ///< the bodies before the impulse the event belongs to
  SolverEvent last_;                 ///< the last event, to find a pair's second point
};

}  // namespace impulse2d::render
