// A stress scene: a scene built from one difficulty knob, the figure measured on its run, and
// the limit beyond which the run counts as failed. The catalogue (catalogue()) holds one per way
// a contact method is known to fail; docs/stability.md shows each failure and where it starts.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "impulse2d/scene/scene.h"
#include "impulse2d/simulation.h"

namespace impulse2d::stress {

/// How the knob is searched: whole numbers (a box count), evenly (a coefficient), or by ratio
/// (a mass ratio, a time step, a speed), so each halving of the bracket is a fair halving.
enum class KnobScale { Integer, Linear, Logarithmic };

struct Knob {
  std::string name;   ///< what it sets, e.g. "boxes"
  std::string unit;   ///< e.g. "m/s"; empty for counts and ratios
  double easy = 0.0;  ///< every method is expected to hold here
  double hard = 0.0;  ///< the far end of the search (may be below easy, as for friction)
  KnobScale scale = KnobScale::Linear;
};

/// Watches a run step by step and gives the one figure the failure criterion is about.
class Probe {
 public:
  virtual ~Probe() = default;
  /// Called with the starting state, then after every step.
  virtual void observe(const Simulation& simulation) = 0;
  /// The figure so far; larger is worse.
  virtual double measure() const = 0;
};

/// The failure criterion: the figure, its limit, and what a student sees on the frames.
struct Criterion {
  std::string measure;           ///< what the figure is, with its unit
  double limit = 0.0;            ///< the run fails when the figure exceeds it
  std::string byEye;             ///< what a failed run looks like on its contact sheet
  bool logarithmicChart = true;  ///< plot the figure on a log axis
};

/// Something done to the bodies mid-run, which the World allows and Box2D does not.
struct Intervention {
  long step = 0;  ///< done just before this step is taken
  std::function<void(std::vector<Body>&)> apply;
  std::string description;
};

/// How long a structure is watched, and what its slow motion may do. A structure runs at least
/// `least` steps, then window by window until its motion is bounded (StructureWatch) or `most`
/// steps have run. A run still growing at `most` fails by creep when its creep, kept up for as
/// long again, would carry its largest sideways displacement past `creepLimit`.
struct Horizon {
  long least = 0;   ///< steps run whatever happens; 0: not a structure, the scene's steps are run
  long window = 0;  ///< steps of a window of the boundedness test
  long most = 0;    ///< steps at most
  /// m. The settling sink of the top body (StructureWatch) at a knob value beyond which the run
  /// fails.
  std::function<double(double knob)> sinkLimit;
  /// m. The sideways displacement a creep is judged against: the scene's limit on leaving a place.
  double creepLimit = 0.0;
};

struct StressScene {
  std::string name;   ///< file-name safe, e.g. "box_stack"
  std::string title;  ///< e.g. "Tall stack of boxes"
  Knob knob;
  Criterion criterion;
  /// The scene at a knob value (solver "sequential"; the search sets each method's).
  std::function<Scene(double knob)> build;
  /// A fresh probe for a run of the scene at that knob value.
  std::function<std::unique_ptr<Probe>(const Scene& scene)> probe;
  std::vector<Intervention> interventions;
  /// Per method label or solver name, the hardest knob value searched, where the full range costs
  /// too much; the search starts from `easy` as ever.
  std::map<std::string, double> hardestFor;
  /// Methods searched on this scene besides baseMethods() (labels of extraMethods()): the fix a
  /// lecture would teach for it, or fixes turned off together where one alone hides the failure.
  std::vector<std::string> extraMethods;
  /// Structures (stacks, pyramids, heavy on light, arches, card houses) are watched over a long
  /// horizon for slow failures; other scenes leave it empty.
  Horizon horizon;
};

/// Every stress scene, in the order docs/stability.md presents them.
std::vector<StressScene> catalogue();

/// The scene of that name; throws std::invalid_argument naming the known ones.
StressScene findStressScene(const std::string& name);

}  // namespace impulse2d::stress
