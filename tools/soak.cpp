// soak: runs a scene for many steps and checks, every step, that every body stays finite and,
// once the scene has settled, that no contact penetrates deeper than a bound; after settling it
// also samples the resident memory (/proc/self/statm) to show that a step allocates nothing that
// it keeps. docs/hardening.md.
//
//   soak [--steps N] [--settle N] [--max-penetration M] [--solver NAME] SCENE.toml
//
// Exit 0 when every check held, 1 when one failed (the line says which and at what step), 2 for
// a bad command line.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "impulse2d/scene/scene.h"
#include "impulse2d/scene/scene_file.h"

using impulse2d::Scene;

namespace {

struct SoakOptions {
  long steps = 100000;
  /// Steps after which the scene counts as settled and memory is sampled for growth.
  long settleSteps = 2000;
  /// m. Deepest contact penetration allowed at any step after settling. Before, bodies still
  /// fall onto each other and overlap by up to their speed times the step.
  double maxPenetration = 0.05;
  /// The solver to run instead of the scene's own; empty keeps the scene's.
  std::string solver;
  std::string scene;
};

Scene loadScene(const SoakOptions& options) {
  Scene scene = impulse2d::loadSceneFile(options.scene);
  if (!options.solver.empty()) scene.solver = options.solver;
  return scene;
}

/// Bytes of resident memory: the second field of /proc/self/statm, in pages.
long residentBytes() {
  std::ifstream statm("/proc/self/statm");
  long size = 0;
  long resident = 0;
  statm >> size >> resident;
  return resident * sysconf(_SC_PAGESIZE);
}

bool finite(const impulse2d::Body& body) {
  return body.position.allFinite() && std::isfinite(body.angle) && body.velocity.allFinite() &&
         std::isfinite(body.angularVelocity);
}

/// What the soak saw.
struct SoakFigures {
  double maxPenetrationFalling = 0.0;  ///< m, before settling
  double maxPenetration = 0.0;         ///< m, after settling
  long residentAtSettle = 0;
  long residentMax = 0;
  long residentAtEnd = 0;
  double seconds = 0.0;
};

void checkStep(const impulse2d::World& world, const SoakOptions& options, SoakFigures& figures) {
  for (const impulse2d::Body& body : world.bodies()) {
    if (!finite(body)) {
      throw std::runtime_error("body " + body.name + " became non-finite at step " +
                               std::to_string(world.stepCount()));
    }
  }
  const double penetration = impulse2d::largestPenetration(world);
  if (world.stepCount() <= options.settleSteps) {
    figures.maxPenetrationFalling = std::max(figures.maxPenetrationFalling, penetration);
    return;
  }
  figures.maxPenetration = std::max(figures.maxPenetration, penetration);
  if (penetration > options.maxPenetration) {
    throw std::runtime_error("penetration " + std::to_string(penetration) + " m at step " +
                             std::to_string(world.stepCount()) + " exceeds the bound " +
                             std::to_string(options.maxPenetration) + " m");
  }
}

/// Memory is sampled every this many steps after settling: often enough to see growth, rarely
/// enough to cost nothing.
constexpr long kMemorySampleInterval = 1000;

void sampleMemory(long step, const SoakOptions& options, SoakFigures& figures) {
  if (step == options.settleSteps) figures.residentAtSettle = residentBytes();
  if (step < options.settleSteps || step % kMemorySampleInterval != 0) return;
  figures.residentMax = std::max(figures.residentMax, residentBytes());
}

SoakFigures soak(impulse2d::World& world, const SoakOptions& options) {
  SoakFigures figures;
  const auto start = std::chrono::steady_clock::now();
  for (long step = 1; step <= options.steps; ++step) {
    world.step();
    checkStep(world, options, figures);
    sampleMemory(step, options, figures);
  }
  figures.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  figures.residentAtEnd = residentBytes();
  figures.residentMax = std::max(figures.residentMax, figures.residentAtEnd);
  return figures;
}

/// Memory may not grow after settling by more than this: a few pages of allocator slack, far
/// less than one byte a step over a long soak.
constexpr long kAllowedGrowthBytes = 256 * 1024;

void report(const Scene& scene, const impulse2d::World& world, const SoakOptions& options,
            const SoakFigures& figures) {
  std::printf("scene            %s (solver %s, %zu bodies)\n", scene.name.c_str(),
              world.solverName().c_str(), world.bodies().size());
  std::printf("steps            %ld in %.1f s (%.3f ms per step)\n", options.steps, figures.seconds,
              1e3 * figures.seconds / double(options.steps));
  std::printf("max penetration  %.6f m while settling, %.6f m after (bound %.6f m)\n",
              figures.maxPenetrationFalling, figures.maxPenetration, options.maxPenetration);
  std::printf("kinetic energy   %.6g J at the end\n", impulse2d::kineticEnergy(world));
  std::printf("resident memory  %.1f MiB at step %ld, %.1f MiB at most after, %.1f MiB at end\n",
              figures.residentAtSettle / 1048576.0, options.settleSteps,
              figures.residentMax / 1048576.0, figures.residentAtEnd / 1048576.0);
}

SoakOptions parseOptions(int argc, char** argv) {
  SoakOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    const bool hasValue = i + 1 < argc;
    if (argument == "--steps" && hasValue) {
      options.steps = std::stol(argv[++i]);
    } else if (argument == "--settle" && hasValue) {
      options.settleSteps = std::stol(argv[++i]);
    } else if (argument == "--max-penetration" && hasValue) {
      options.maxPenetration = std::stod(argv[++i]);
    } else if (argument == "--solver" && hasValue) {
      options.solver = argv[++i];
    } else if (options.scene.empty() && argument.rfind("--", 0) != 0) {
      options.scene = argument;
    } else {
      throw std::invalid_argument("unexpected argument '" + argument + "'");
    }
  }
  if (options.scene.empty() || options.steps < options.settleSteps || options.settleSteps < 1) {
    throw std::invalid_argument("need a scene, and steps >= settle >= 1");
  }
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  SoakOptions options;
  try {
    options = parseOptions(argc, argv);
  } catch (const std::exception& error) {
    std::fprintf(stderr,
                 "error: %s\nusage: soak [--steps N] [--settle N] "
                 "[--max-penetration M] [--solver NAME] SCENE.toml\n",
                 error.what());
    return 2;
  }
  try {
    const Scene scene = loadScene(options);
    const std::unique_ptr<impulse2d::World> world = impulse2d::buildWorld(scene);
    const SoakFigures figures = soak(*world, options);
    report(scene, *world, options, figures);
    if (figures.residentMax - figures.residentAtSettle > kAllowedGrowthBytes) {
      throw std::runtime_error("resident memory grew after settling");
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
  return 0;
}
