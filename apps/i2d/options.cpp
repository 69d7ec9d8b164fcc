// Parsing the options of the i2d commands.
#include "options.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <map>
#include <utility>

#include "failures.h"
#include "impulse2d/box2d/box2d_simulation.h"
#include "impulse2d/presets.h"
#include "impulse2d/scene/scene_file.h"
#include "impulse2d/scene/setting_ranges.h"
#include "output_file.h"
#include "scene_search.h"

namespace i2d {
namespace {

using impulse2d::render::Overlays;

/// An argument list read front to back; options find their value in "--name=value" or next.
class Arguments {
 public:
  explicit Arguments(const std::vector<std::string>& arguments) : arguments_(arguments) {}

  bool done() const { return next_ == arguments_.size(); }
  /// The next argument; for "--name=value" just "--name", keeping the value for value().
  std::string take() {
    const std::string& argument = arguments_[next_++];
    const size_t equals = argument.find('=');
    if (argument.rfind("--", 0) != 0 || equals == std::string::npos) return argument;
    inlineValue_ = argument.substr(equals + 1);
    return argument.substr(0, equals);
  }
  /// The value of the option just taken.
  std::string value(const std::string& option) {
    std::string value;
    if (inlineValue_) {
      value = std::exchange(inlineValue_, std::nullopt).value();
    } else if (!done()) {
      value = arguments_[next_++];
    }
    if (value.empty()) throw UsageError("option " + option + " needs a value");
    return value;
  }
  /// Checks that the switch just taken was not given "=value".
  void noValue(const std::string& option) {
    if (std::exchange(inlineValue_, std::nullopt)) {
      throw UsageError("option " + option + " takes no value");
    }
  }

 private:
  const std::vector<std::string>& arguments_;
  size_t next_ = 0;
  std::optional<std::string> inlineValue_;
};

int parseInteger(const std::string& text, const std::string& option, int minimum) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < minimum) {
    throw UsageError("option " + option + " needs an integer >= " + std::to_string(minimum) +
                     ", not '" + text + "'");
  }
  return value;
}

double parsePositive(const std::string& text, const std::string& option) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value) ||
      value <= 0.0) {
    throw UsageError("option " + option + " needs a finite number > 0, not '" + text + "'");
  }
  return value;
}

/// An option that stands for a [world] setting (--steps, --dt, --trace-step's steps) takes
/// the setting's range from the same table as the scene file.
void checkWorldRange(double value, const std::string& option, const std::string& key,
                     const std::string& text) {
  const std::optional<impulse2d::SettingRange> range = impulse2d::findSettingRange("world", key);
  if (range && !impulse2d::inSettingRange(value, *range)) {
    throw UsageError("option " + option + " " +
                     impulse2d::describeSettingRange(*range, key == "steps", value) + ", not '" +
                     text + "'");
  }
}

std::string trim(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

/// "a,b,c" -> {"a", "b", "c"}, each trimmed; empty items are an error.
std::vector<std::string> splitList(const std::string& text, char separator,
                                   const std::string& option) {
  std::vector<std::string> items;
  size_t begin = 0;
  while (begin <= text.size()) {
    const size_t end = std::min(text.find(separator, begin), text.size());
    items.push_back(trim(text.substr(begin, end - begin)));
    if (items.back().empty()) throw UsageError("option " + option + " has an empty item");
    begin = end + 1;
  }
  return items;
}

/// A --set or --panel assignment has the shape section.key=value; what the key and value mean is
/// the scene reader's to judge (a refused value is an invalid scene, exit 3).
void checkAssignment(const std::string& assignment, const std::string& option) {
  if (!impulse2d::isSettingAssignment(assignment)) {
    throw UsageError("option " + option +
                     " needs section.key=value, such as solver.velocity_iterations=12, not '" +
                     assignment + "'");
  }
}

/// Every name makeSimulation accepts, as "a, b, c".
std::string knownSolvers() {
  std::string names;
  for (const std::string& name : impulse2d::simulationNames()) {
    names += (names.empty() ? "" : ", ") + name;
  }
  return names;
}

/// A solver name makeSimulation accepts; a usage error naming them all otherwise.
std::string checkSolver(const std::string& name) {
  const std::vector<std::string> known = impulse2d::simulationNames();
  if (std::find(known.begin(), known.end(), name) == known.end()) {
    throw UsageError("unknown solver '" + name + "' (known: " + knownSolvers() + ")");
  }
  return name;
}

/// A preset of that solver (presets.h); a usage error naming the solver's presets otherwise.
void checkPreset(const std::string& solver, const std::string& name) {
  if (!impulse2d::findPreset(solver, name)) {
    throw UsageError("unknown preset '" + name + "' for solver '" + solver +
                     "' (known: " + impulse2d::presetNames(solver) + "; see i2d presets)");
  }
}

/// The overlay switches by name: the snake_case names of RenderSettings::overlays.
const std::map<std::string, bool Overlays::*>& overlayFields() {
  static const std::map<std::string, bool Overlays::*> fields = {
      {"rotation_marks", &Overlays::rotationMarks},
      {"contact_points", &Overlays::contactPoints},
      {"contact_normals", &Overlays::contactNormals},
      {"normal_impulses", &Overlays::normalImpulses},
      {"friction_impulses", &Overlays::frictionImpulses},
      {"loads", &Overlays::loads},
      {"weights", &Overlays::weights},
      {"sliding_velocities", &Overlays::slidingVelocities},
      {"velocities", &Overlays::velocities},
      {"heads_up", &Overlays::headsUp},
      {"friction_gauges", &Overlays::frictionGauges},
      {"legend", &Overlays::legend},
  };
  return fields;
}

/// --show or --hide LIST: turns the named overlays (or "all") on or off.
void switchOverlays(Overlays& overlays, const std::string& list, bool on,
                    const std::string& option) {
  for (const std::string& name : splitList(list, ',', option)) {
    if (name == "all") {
      for (const auto& [field, member] : overlayFields()) overlays.*member = on;
      continue;
    }
    const auto field = overlayFields().find(name);
    if (field == overlayFields().end()) {
      std::string known = "all";
      for (const auto& [knownName, member] : overlayFields()) known += ", " + knownName;
      throw UsageError("unknown overlay '" + name + "' for " + option + " (known: " + known + ")");
    }
    overlays.*(field->second) = on;
  }
}

using OptionHandler = std::function<void(const std::string& value)>;
using SwitchHandler = std::function<void()>;

/// The options of a command: those that take a value and the switches that take none.
struct Handlers {
  std::map<std::string, OptionHandler> options;
  std::map<std::string, SwitchHandler> switches;
};

/// Reads options by their handlers and the one positional argument, the scene.
void parse(const std::vector<std::string>& arguments, const std::string& command,
           const Handlers& handlers, std::string& scenePath) {
  Arguments reader(arguments);
  while (!reader.done()) {
    const std::string argument = reader.take();
    if (argument.size() > 1 && argument[0] == '-') {
      if (const auto handler = handlers.options.find(argument); handler != handlers.options.end()) {
        handler->second(reader.value(argument));
      } else if (const auto flag = handlers.switches.find(argument);
                 flag != handlers.switches.end()) {
        reader.noValue(argument);
        flag->second();
      } else {
        throw UsageError("unknown option '" + argument + "' for i2d " + command + " (see i2d " +
                         command + " --help)");
      }
    } else if (scenePath.empty()) {
      scenePath = findScene(argument);
    } else {
      throw UsageError("unexpected argument '" + argument + "': i2d " + command +
                       " takes one SCENE");
    }
  }
  if (scenePath.empty()) throw UsageError("i2d " + command + " needs a SCENE file");
}

/// --steps, --dt and --set; --solver and --preset too when the command runs one solver.
void addSceneHandlers(Handlers& handlers, SceneOptions& options, bool withSolver) {
  if (withSolver) {
    handlers.options["--solver"] = [&](const std::string& value) {
      options.solver = checkSolver(value);
    };
    handlers.options["--preset"] = [&](const std::string& value) { options.preset = value; };
  }
  handlers.options["--steps"] = [&](const std::string& value) {
    options.steps = parseInteger(value, "--steps", 0);
    checkWorldRange(*options.steps, "--steps", "steps", value);
  };
  handlers.options["--dt"] = [&](const std::string& value) {
    options.dt = parsePositive(value, "--dt");
    checkWorldRange(*options.dt, "--dt", "dt", value);
  };
  handlers.options["--set"] = [&](const std::string& value) {
    checkAssignment(value, "--set");
    options.settings.push_back(value);
  };
}

/// The smallest side --size accepts: room for the strips and a scene.
constexpr int kMinFrameSide = 160;

/// --size WxH: two integers of at least kMinFrameSide, at most the frame pixel limit a scene's
/// [render] table has (impulse2d::kMostFramePixels) together.
FrameSize parseSize(const std::string& text) {
  const size_t x = text.find('x');
  const std::string usage =
      "option --size needs WIDTHxHEIGHT in pixels (e.g. 1280x720), not '" + text + "'";
  if (x == std::string::npos) throw UsageError(usage);
  FrameSize size;
  const char* end = text.data() + text.size();
  const auto [widthEnd, widthError] = std::from_chars(text.data(), text.data() + x, size.width);
  const auto [heightEnd, heightError] = std::from_chars(text.data() + x + 1, end, size.height);
  if (widthError != std::errc() || heightError != std::errc() || widthEnd != text.data() + x ||
      heightEnd != end) {
    throw UsageError(usage);
  }
  if (size.width < kMinFrameSide || size.height < kMinFrameSide ||
      long(size.width) * size.height > impulse2d::kMostFramePixels) {
    throw UsageError("option --size: each side at least " + std::to_string(kMinFrameSide) +
                     " pixels and at most " + std::to_string(impulse2d::kMostFramePixels) +
                     " pixels in all, not '" + text + "'");
  }
  return size;
}

impulse2d::render::ImageFormat parseFormat(const std::string& text) {
  using impulse2d::render::ImageFormat;
  for (const ImageFormat format : {ImageFormat::Png, ImageFormat::Svg, ImageFormat::Pdf}) {
    if (text == impulse2d::render::extensionOf(format)) return format;
  }
  throw UsageError("unknown format '" + text + "' for --format (known: png, svg, pdf)");
}

/// --frames, --every, --video and the overlay switches.
void addFrameHandlers(Handlers& handlers, FrameOptions& options, int& every) {
  handlers.options["--frames"] = [&](const std::string& value) { options.directory = value; };
  handlers.options["--every"] = [&](const std::string& value) {
    every = parseInteger(value, "--every", 1);
  };
  handlers.switches["--video"] = [&] { options.video = true; };
  handlers.options["--animation"] = [&](const std::string& value) {
    if (value != "gif" && value != "mp4") {
      throw UsageError("unknown animation kind '" + value + "' for --animation (known: gif, mp4)");
    }
    options.animation = value;
  };
  handlers.options["--format"] = [&](const std::string& value) {
    options.format = parseFormat(value);
  };
  handlers.options["--size"] = [&](const std::string& value) { options.size = parseSize(value); };
  handlers.options["--theme"] = [&](const std::string& value) {
    if (value != "screen" && value != "print") {
      throw UsageError("unknown theme '" + value + "' for --theme (known: screen, print)");
    }
    options.printTheme = value == "print";
  };
  handlers.switches["--no-overlays"] = [&] {
    switchOverlays(options.overlays, "all", false, "--no-overlays");
  };
  handlers.options["--hide"] = [&](const std::string& value) {
    switchOverlays(options.overlays, value, false, "--hide");
  };
  handlers.options["--show"] = [&](const std::string& value) {
    switchOverlays(options.overlays, value, true, "--show");
  };
}

/// Switches and per-step output need a frame directory to write into.
void requireFrames(const FrameOptions& frames, const std::string& what) {
  if (!frames.directory) throw UsageError(what + " needs --frames DIR");
}

std::vector<std::string> parseSolverList(const std::string& value) {
  std::vector<std::string> solvers = splitList(value, ',', "--solvers");
  for (const std::string& solver : solvers) checkSolver(solver);
  return solvers;
}

/// `--solvers` of compare: each entry SOLVER or SOLVER:PRESET, one panel each, labelled with it.
std::vector<PanelOption> parseSolverPanels(const std::string& value) {
  std::vector<PanelOption> panels;
  for (const std::string& entry : splitList(value, ',', "--solvers")) {
    const size_t colon = entry.find(':');
    PanelOption panel{entry, checkSolver(entry.substr(0, colon)), std::nullopt, {}};
    if (colon != std::string::npos) {
      panel.preset = entry.substr(colon + 1);
      checkPreset(*panel.solver, *panel.preset);
    }
    panels.push_back(panel);
  }
  return panels;
}

}  // namespace

PanelOption parsePanel(const std::string& text) {
  const size_t colon = text.find(':');
  PanelOption panel;
  panel.label = trim(text.substr(0, colon));
  if (panel.label.empty()) {
    throw UsageError("option --panel needs 'LABEL: section.key=value; ...', not '" + text + "'");
  }
  if (colon == std::string::npos && text.find('=') != std::string::npos) {
    throw UsageError(
        "option --panel needs a colon after its label, 'LABEL: section.key=value; "
        "...', not '" +
        text + "'");
  }
  const std::string assignments = colon == std::string::npos ? "" : trim(text.substr(colon + 1));
  if (!assignments.empty()) panel.settings = splitList(assignments, ';', "--panel");
  for (const std::string& assignment : panel.settings) {
    checkAssignment(assignment, "--panel");
  }
  return panel;
}

RunOptions parseRunOptions(const std::vector<std::string>& arguments) {
  RunOptions options;
  Handlers handlers;
  addSceneHandlers(handlers, options.scene, true);
  addFrameHandlers(handlers, options.frames, options.every);
  handlers.options["--csv"] = [&](const std::string& value) { options.csvPath = value; };
  handlers.options["--contacts"] = [&](const std::string& value) { options.contactsPath = value; };
  handlers.options["--trace-step"] = [&](const std::string& value) {
    options.traceStep = parseInteger(value, "--trace-step", 1);
    checkWorldRange(*options.traceStep, "--trace-step", "steps", value);
  };
  handlers.options["--error-vs-reference"] = [&](const std::string& value) {
    options.errorVsReferencePath = value;
  };
  handlers.options["--plots"] = [&](const std::string& value) { options.plots = value; };
  parse(arguments, "run", handlers, options.scene.scenePath);
  if (options.errorVsReferencePath &&
      (options.csvPath || options.contactsPath || options.frames.directory || options.traceStep ||
       options.plots)) {
    throw UsageError(
        "--error-vs-reference writes its own CSV only; leave out --csv, --contacts, --frames, "
        "--trace-step and --plots");
  }
  if (options.csvPath && options.contactsPath &&
      sameOutputFile(*options.csvPath, *options.contactsPath)) {
    throw UsageError("--csv and --contacts both write '" + *options.contactsPath +
                     "'; give each its own file");
  }
  if (options.frames.video) requireFrames(options.frames, "--video");
  if ((options.frames.video || options.frames.animation == std::optional<std::string>("mp4")) &&
      options.frames.format != impulse2d::render::ImageFormat::Png) {
    throw UsageError("a video is made of PNG frames; leave out --format or --video");
  }
  if (options.frames.animation) requireFrames(options.frames, "--animation");
  if (options.traceStep) requireFrames(options.frames, "--trace-step");
  if (options.traceStep && (options.csvPath || options.contactsPath || options.frames.video ||
                            options.frames.animation)) {
    throw UsageError(
        "--trace-step writes trace frames (and --plots) only; leave out --csv, --contacts, "
        "--video and --animation");
  }
  return options;
}

CheckOptions parseCheckOptions(const std::vector<std::string>& arguments) {
  CheckOptions options;
  Handlers handlers;
  addSceneHandlers(handlers, options.scene, true);
  parse(arguments, "check", handlers, options.scene.scenePath);
  return options;
}

CompareOptions parseCompareOptions(const std::vector<std::string>& arguments) {
  CompareOptions options;
  Handlers handlers;
  addSceneHandlers(handlers, options.scene, true);
  addFrameHandlers(handlers, options.frames, options.every);
  bool bySolver = false;
  bool byPanel = false;
  handlers.options["--solvers"] = [&](const std::string& value) {
    for (const PanelOption& panel : parseSolverPanels(value)) options.panels.push_back(panel);
    bySolver = true;
  };
  handlers.options["--panel"] = [&](const std::string& value) {
    options.panels.push_back(parsePanel(value));
    byPanel = true;
  };
  handlers.options["--plots"] = [&](const std::string& value) { options.plots = value; };
  parse(arguments, "compare", handlers, options.scene.scenePath);
  if (options.panels.empty()) throw UsageError("i2d compare needs --solvers or --panel");
  if (bySolver && byPanel) {
    throw UsageError("i2d compare takes either --solvers or --panel, not both");
  }
  requireFrames(options.frames, "i2d compare");
  return options;
}

AgreeOptions parseAgreeOptions(const std::vector<std::string>& arguments) {
  AgreeOptions options;
  options.solvers = impulse2d::solverNames();
  Handlers handlers;
  addSceneHandlers(handlers, options.scene, false);
  handlers.options["--solvers"] = [&](const std::string& value) {
    options.solvers = parseSolverList(value);
    if (std::find(options.solvers.begin(), options.solvers.end(), impulse2d::kBox2dName) !=
        options.solvers.end()) {
      throw UsageError("--solvers of i2d agree lists our methods; box2d is always the reference");
    }
  };
  handlers.switches["--summary"] = [&] { options.summaryOnly = true; };
  parse(arguments, "agree", handlers, options.scene.scenePath);
  return options;
}

}  // namespace i2d
