// The figures a stress run is judged by, each a Probe watching the run step by step: how far a
// body strayed, how deep a contact sank, how much energy appeared, whether a ball got past a
// wall, how much of a cradle's speed arrived, how far bodies popped up after a removal.
#pragma once

#include <algorithm>
#include <vector>

#include "stress_scene.h"

namespace impulse2d::stress {

/// m. Largest sideways distance of any dynamic body from where it was at step `from`, over the
/// rest of the run: how far a body left its place after settling. Vertical motion is judged
/// apart: a structure's sink and energy (StructureWatch), so that a stack rising as Box2D pushes
/// out its polygon skin, or sinking into soft contacts, is not taken for a body leaving its place.
class DisplacementProbe : public Probe {
 public:
  explicit DisplacementProbe(long from) : from_(from) {}
  void observe(const Simulation& simulation) override;
  double measure() const override { return largest_; }

 private:
  long from_;
  std::vector<Vec2> start_;
  double largest_ = 0.0;
};

/// m. Deepest contact penetration from step `from` on.
class PenetrationProbe : public Probe {
 public:
  explicit PenetrationProbe(long from) : from_(from) {}
  void observe(const Simulation& simulation) override;
  double measure() const override { return deepest_; }

 private:
  long from_;
  double deepest_ = 0.0;
};

/// m. How far sideways, at the end of the run, the dynamic bodies (in scene order) lie from
/// `places`: a leaning, toppled or scattered stack, not the height its contacts settle at.
class PlaceProbe : public Probe {
 public:
  explicit PlaceProbe(std::vector<Vec2> places) : places_(std::move(places)) {}
  void observe(const Simulation& simulation) override;
  double measure() const override { return largest_; }

 private:
  std::vector<Vec2> places_;
  double largest_ = 0.0;
};

/// m. From step `from` on, the largest rise of the total (kinetic plus potential) energy above its
/// value at that step, divided by the total weight Σm·|g|: the height the whole scene would have
/// to be lifted to hold the energy gained at rest.
class EnergyRiseProbe : public Probe {
 public:
  explicit EnergyRiseProbe(long from) : from_(from) {}
  void observe(const Simulation& simulation) override;
  double measure() const override { return largest_; }

 private:
  long from_;
  bool started_ = false;
  double start_ = 0.0;
  double weight_ = 0.0;
  double largest_ = 0.0;
};

/// m. How far the centre of body `ball` got past the plane x = wallX, capped at `cap`; negative
/// while it never reached it (a ball bouncing off stays a radius and a half-wall short).
class WallProbe : public Probe {
 public:
  WallProbe(int ball, double wallX, double cap) : ball_(ball), wallX_(wallX), cap_(cap) {}
  void observe(const Simulation& simulation) override;
  double measure() const override { return std::min(largest_, cap_); }

 private:
  int ball_;
  double wallX_;
  double cap_;
  double largest_ = -1e300;
};

/// The fraction of the striker's speed `strikeSpeed` that the far ball `last` of a cradle does
/// NOT carry away along x at the end of the run: 0 for a perfect cradle.
class CradleProbe : public Probe {
 public:
  CradleProbe(int last, double strikeSpeed) : last_(last), strikeSpeed_(strikeSpeed) {}
  void observe(const Simulation& simulation) override;
  double measure() const override { return 1.0 - lastSpeed_ / strikeSpeed_; }

 private:
  int last_;
  double strikeSpeed_;
  double lastSpeed_ = 0.0;
};

/// m. From step `from` on, the largest rise of any of `bodies` above its height at that step.
class RiseProbe : public Probe {
 public:
  RiseProbe(std::vector<int> bodies, long from) : bodies_(std::move(bodies)), from_(from) {}
  void observe(const Simulation& simulation) override;
  double measure() const override { return largest_; }

 private:
  std::vector<int> bodies_;
  long from_;
  std::vector<double> heights_;
  double largest_ = 0.0;
};

/// m. Largest difference between where a body is (less `offset`) and where it is in a twin run of
/// the same scene moved back by `offset`, stepped in lockstep: what distance from the origin
/// alone changes. The twin is run by the same method (the scene's solver and settings).
class TwinProbe : public Probe {
 public:
  TwinProbe(const Scene& scene, const Vec2& offset);
  ~TwinProbe() override;
  void observe(const Simulation& simulation) override;
  double measure() const override { return largest_; }

 private:
  std::unique_ptr<Simulation> twin_;
  Vec2 offset_;
  double largest_ = 0.0;
};

}  // namespace impulse2d::stress

namespace impulse2d::stress {

/// The slow figures of a structure's run, all from the positions at the start.
struct StructureFigures {
  double sway = 0.0;     ///< m. Largest sideways distance of the top body from its start
  double sink = 0.0;     ///< m. Largest drop of the top body below its start (0 if it only rose)
  double creep = 0.0;    ///< m/s. Growth of the largest sideways displacement, last window
  double drift = 0.0;    ///< m. The largest sideways displacement over the last window, D_k
  bool bounded = false;  ///< neither displacement nor energy grew over the last window
};

/// Watches a structure window by window. The top body is the dynamic body that starts highest.
/// Window k's displacement D_k is the largest sideways distance of any dynamic body from its
/// start over the window's steps (vertical motion shows in the energy and the sink), its energy E_k
/// the largest total (kinetic plus potential) energy over them, as a height of the whole
/// structure's weight. The first window is the settling and is no reference; after each window from
/// the third on, the motion is bounded when neither figure rose above its largest over the windows
/// between by more than its tolerance: D_k ≤ max(D_1 … D_(k−1)) + displacementTolerance, E_k ≤
/// max(E_1 … E_(k−1)) + energyTolerance. A jitter then counts as bounded, a steady drift never
/// does; the creep is how far D_k rose above that largest, per second of the window.
class StructureWatch {
 public:
  /// m. Growth of a window's largest displacement, and of its largest energy as a height of
  /// the structure's weight, that still counts as bounded: a hundredth of a 1 m box's 10 cm
  /// displacement limit.
  static constexpr double kDisplacementTolerance = 1e-3;
  static constexpr double kEnergyTolerance = 1e-3;

  explicit StructureWatch(long window) : window_(window) {}
  /// Called with the starting state, then after every step.
  void observe(const Simulation& simulation);
  const StructureFigures& figures() const { return figures_; }
  /// Whether the step just observed ended a window.
  bool windowEnded() const { return ended_; }

 private:
  void endWindow(double seconds);

  long window_;
  std::vector<Vec2> start_;
  size_t top_ = 0;
  double weight_ = 0.0;
  double displacement_ = 0.0;  ///< over the current window
  double energy_ = 0.0;        ///< over the current window, as a height
  bool windowStarted_ = false;
  int windows_ = 0;                   ///< windows ended so far
  double largestDisplacement_ = 0.0;  ///< over the windows ended, the first left out
  double largestEnergy_ = 0.0;
  bool ended_ = false;
  StructureFigures figures_;
};

}  // namespace impulse2d::stress
