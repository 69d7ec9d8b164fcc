// The i2d command line on CLI11: each option is declared once, with what its value must be,
// what it needs or excludes, and its help line, from which `i2d COMMAND --help` is made.
#include "options.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <map>

#include "failures.h"
#include "help.h"
#include "impulse2d/box2d/box2d_simulation.h"
#include "impulse2d/presets.h"
#include "impulse2d/scene/scene_file.h"
#include "impulse2d/scene/setting_ranges.h"
#include "output_file.h"
#include "scene_search.h"

namespace i2d {
namespace {

using impulse2d::render::ImageFormat;
using impulse2d::render::Overlays;

const std::string kOptionsGroup =
    "options (a value follows the option or '=': --steps 100, --steps=100)";

/// The range of a [world] setting (steps, dt) from the table a scene file is checked against,
/// so an option refuses what the scene key would: "must be an integer in [0, 10000000]".
CLI::Validator worldRange(const std::string& key) {
  const impulse2d::SettingRange range = impulse2d::findSettingRange("world", key).value();
  const bool integer = key == "steps";
  CLI::Validator validator(
      [range, integer](std::string& text) -> std::string {
        double value = 0.0;
        if (CLI::detail::lexical_cast(text, value) && impulse2d::inSettingRange(value, range) &&
            (!integer || value == double(long(value)))) {
          return "";
        }
        return impulse2d::describeSettingRange(range, integer, value) + ", not '" + text + "'";
      },
      "");
  const std::string mustBe = "must be ";
  return validator.description(
      impulse2d::describeSettingRange(range, integer, range.lowest).substr(mustBe.size()));
}

/// The most steps a run may take: the top of [world] steps' range.
int mostSteps() {
  return int(impulse2d::findSettingRange("world", "steps")->highest);
}

/// A --set or --panel assignment has the shape section.key=value; what the key and value mean is
/// the scene reader's to judge (a refused value is an invalid scene, exit 3).
std::string assignmentProblem(const std::string& assignment) {
  if (impulse2d::isSettingAssignment(assignment)) return "";
  return "needs section.key=value, such as solver.velocity_iterations=12, not '" + assignment + "'";
}

const CLI::Validator kAssignment([](std::string& text) { return assignmentProblem(text); }, "");

/// --solvers SOLVER or SOLVER:PRESET, a preset of that solver (presets.h).
const CLI::Validator kSolverAndPreset(
    [](std::string& entry) -> std::string {
      const size_t colon = entry.find(':');
      const std::string solver = entry.substr(0, colon);
      const std::vector<std::string> known = impulse2d::simulationNames();
      if (std::find(known.begin(), known.end(), solver) == known.end()) {
        return "unknown solver '" + solver + "' (known: " + CLI::detail::join(known, ", ") + ")";
      }
      if (colon != std::string::npos && !impulse2d::findPreset(solver, entry.substr(colon + 1))) {
        return "unknown preset '" + entry.substr(colon + 1) + "' for solver '" + solver +
               "' (known: " + impulse2d::presetNames(solver) + "; see i2d presets)";
      }
      return "";
    },
    "");

/// The panel of `--panel 'LABEL: section.key=value; section.key=value'` (assignments optional).
PanelOption parsePanel(const std::string& text) {
  const auto refuse = [](const std::string& problem) {
    throw CLI::ValidationError("--panel", problem);
  };
  const size_t colon = text.find(':');
  PanelOption panel;
  panel.label = CLI::detail::trim_copy(text.substr(0, colon));
  if (panel.label.empty()) refuse("needs 'LABEL: section.key=value; ...', not '" + text + "'");
  if (colon == std::string::npos && text.find('=') != std::string::npos) {
    refuse("needs a colon after its label, 'LABEL: section.key=value; ...', not '" + text + "'");
  }
  const std::string assignments =
      colon == std::string::npos ? "" : CLI::detail::trim_copy(text.substr(colon + 1));
  if (assignments.empty()) return panel;
  for (const std::string& assignment : CLI::detail::split(assignments, ';')) {
    panel.settings.push_back(CLI::detail::trim_copy(assignment));
    const std::string problem = assignmentProblem(panel.settings.back());
    if (!problem.empty()) refuse(problem);
  }
  return panel;
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

/// The names --hide and --show take: each overlay, and all.
std::vector<std::string> overlayNames() {
  std::vector<std::string> names = {"all"};
  for (const auto& [name, field] : overlayFields()) names.push_back(name);
  return names;
}

/// Turns the named overlays (or all) on or off.
void switchOverlays(Overlays& overlays, const std::vector<std::string>& names, bool on) {
  for (const std::string& name : names) {
    for (const auto& [field, member] : overlayFields()) {
      if (name == "all" || name == field) overlays.*member = on;
    }
  }
}

/// The smallest side --size accepts: room for the strips and a scene.
constexpr int kMinFrameSide = 160;

/// --size WxH: two integers of at least kMinFrameSide, at most the frame pixel limit a scene's
/// [render] table has (impulse2d::kMostFramePixels) together.
FrameSize parseSize(const std::string& text) {
  FrameSize size;
  char x = 0;
  char rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &size.width, &x, &size.height, &rest) != 3 ||
      x != 'x' || !std::isdigit(static_cast<unsigned char>(text.front()))) {
    throw CLI::ValidationError("--size",
                               "needs WIDTHxHEIGHT in pixels (e.g. 1280x720), not '" + text + "'");
  }
  if (size.width < kMinFrameSide || size.height < kMinFrameSide ||
      long(size.width) * size.height > impulse2d::kMostFramePixels) {
    throw CLI::ValidationError("--size", "each side at least " + std::to_string(kMinFrameSide) +
                                             " pixels and at most " +
                                             std::to_string(impulse2d::kMostFramePixels) +
                                             " pixels in all, not '" + text + "'");
  }
  return size;
}

/// The frames' formats by name: png, svg, pdf.
std::map<std::string, ImageFormat> imageFormats() {
  std::map<std::string, ImageFormat> formats;
  for (const ImageFormat format : {ImageFormat::Png, ImageFormat::Svg, ImageFormat::Pdf}) {
    formats[impulse2d::render::extensionOf(format)] = format;
  }
  return formats;
}

/// --no-overlays, --hide and --show, applied in the order given.
void addOverlaySwitches(CLI::App& command, Overlays& overlays) {
  command
      .add_flag_callback(
          "--no-overlays", [&overlays] { switchOverlays(overlays, {"all"}, false); },
          "frames show the bodies in their state colours only")
      ->trigger_on_parse();
  const auto addList = [&](const std::string& name, bool on, const std::string& description) {
    command
        .add_option_function<std::vector<std::string>>(
            name,
            [&overlays, on](const std::vector<std::string>& names) {
              switchOverlays(overlays, names, on);
            },
            description)
        ->type_name("LIST")
        ->delimiter(',')
        ->check(CLI::IsMember(overlayNames()))
        ->trigger_on_parse();
  };
  addList("--hide", false, "turn these overlays off, LIST comma-separated");
  addList("--show", true,
          "turn these overlays on (contact_normals, weights and velocities are off by default)");
}

/// The scene file: a path, or a shipped scene's name (scene_search.h).
void addScene(CLI::App& command, SceneOptions& options) {
  command.add_option("SCENE", options.scenePath, "a scene file, or a shipped scene's name")
      ->required()
      ->transform([](std::string name) { return findScene(name); });
}

/// --solver and --preset, for the commands that run one solver.
void addSolverOptions(CLI::App& command, SceneOptions& options) {
  command
      .add_option("--solver", options.solver,
                  "run this solver instead of the scene's; its settings are then the defaults, "
                  "change them with --set")
      ->type_name("NAME")
      ->check(CLI::IsMember(impulse2d::simulationNames()));
  command
      .add_option("--preset", options.preset,
                  "the solver's settings as its authors published them (i2d presets), applied "
                  "after --solver and before --set")
      ->type_name("NAME");
}

/// --steps, --dt and --set: the [world] and [solver] keys a command line may change.
void addSceneOverrides(CLI::App& command, SceneOptions& options) {
  command.add_option("--steps", options.steps, "number of steps instead of [world] steps")
      ->type_name("N")
      ->check(worldRange("steps"));
  command.add_option("--dt", options.dt, "time step in seconds instead of [world] dt")
      ->type_name("S")
      ->check(worldRange("dt"));
  command
      .add_option("--set", options.settings,
                  "change one setting as a scene file would, SECTION world, solver (the solver's "
                  "own settings) or render (the view); repeatable, applied in order after "
                  "--solver: --set solver.velocity_iterations=20 --set "
                  "world.gravity=[0,-1.62] --set render.follow=box; a bare word is a string")
      ->type_name("SECTION.KEY=VALUE")
      ->check(kAssignment);
}

/// --frames, --every and how the frames look; --video, --animation and the overlay switches.
void addFrameOptions(CLI::App& command, FrameOptions& options, int& every) {
  CLI::Option* frames =
      command.add_option("--frames", options.directory, "write frames under DIR/<scene>/")
          ->type_name("DIR");
  command.add_option("--every", every, "record every K-th step (K >= 1), plus step 0 and the last")
      ->type_name("K")
      ->check(CLI::Range(1, mostSteps()).description(""));
  command
      .add_option_function<std::string>(
          "--format",
          [&options](const std::string& name) { options.format = imageFormats().at(name); },
          "the frames' and sheet's format (default png); svg and pdf are vector drawings with "
          "their text as text")
      ->type_name("FORMAT")
      ->check(CLI::IsMember(imageFormats()));
  command
      .add_option_function<std::string>(
          "--size", [&options](const std::string& text) { options.size = parseSize(text); },
          "the frames' size in pixels, strips included (default: the scene's [render] width "
          "and height); the view is fitted into it")
      ->type_name("WxH");
  command
      .add_option_function<std::string>(
          "--theme",
          [&options](const std::string& theme) { options.printTheme = theme == "print"; },
          "print: white background and dark lines, for handouts and slides (default screen)")
      ->type_name("THEME")
      ->check(CLI::IsMember({"screen", "print"}));
  command
      .add_flag("--video", options.video,
                "also write DIR/<scene>/<scene>.mp4 in real time (needs ffmpeg on PATH)")
      ->needs(frames);
  command
      .add_option("--animation", options.animation,
                  "also write one file of the frames, in real time: gif (always possible, "
                  "DIR/<scene>/<scene>.gif) or mp4 (needs ffmpeg on PATH)")
      ->type_name("KIND")
      ->check(CLI::IsMember({"gif", "mp4"}))
      ->needs(frames);
  addOverlaySwitches(command, options.overlays);
}

/// What --error-vs-reference and --trace-step refuse beside them, and the checks that depend on
/// two options' values.
void checkRunOutputs(const RunOptions& options) {
  if (options.csvPath && options.contactsPath &&
      sameOutputFile(*options.csvPath, *options.contactsPath)) {
    throw UsageError("--csv and --contacts both write '" + *options.contactsPath +
                     "'; give each its own file");
  }
  if ((options.frames.video || options.frames.animation == std::optional<std::string>("mp4")) &&
      options.frames.format != ImageFormat::Png) {
    throw UsageError("a video is made of PNG frames; leave out --format or --video");
  }
}

void addRun(CLI::App& app, RunOptions& options) {
  CLI::App* run = app.add_subcommand(
      "run",
      "run a scene, print a summary; optionally write its trajectory (--csv), PNG frames and a "
      "contact sheet (--frames), or one frame per solver event of one step (--trace-step)");
  addScene(*run, options.scene);
  addSolverOptions(*run, options.scene);
  addSceneOverrides(*run, options.scene);
  CLI::Option* csv =
      run->add_option("--csv", options.csvPath,
                      "write the trajectory; FILE appears only when complete; - or /dev/stdout "
                      "is standard output, a device or pipe is written in place")
          ->type_name("FILE");
  CLI::Option* contacts =
      run->add_option("--contacts", options.contactsPath,
                      "write every contact point's forces per recorded step: bodies, point, "
                      "normal, impulses and forces, mu, the limit mu N, static or sliding, each "
                      "body's applied load (header below); FILE appears when complete")
          ->type_name("FILE");
  addFrameOptions(*run, options.frames, options.every);
  CLI::Option* frames = run->get_option("--frames");
  frames->description(
      "write PNG frames DIR/<scene>/<scene>_00000.png, _00001.png, ... (one per recorded step, "
      "numbered without gaps), the contact sheet DIR/<scene>/<scene>_sheet.png and the viewer "
      "page DIR/<scene>/index.html (open it in a browser: slider, arrow keys, each frame's "
      "figures)");
  CLI::Option* plots =
      run->add_option("--plots", options.plots,
                      "gnuplot PNGs of the run against time: DIR/<scene>_kinetic.png, "
                      "_potential.png, _total.png (energy), _contacts.png (contact points), "
                      "_penetration.png (largest); with --trace-step, the velocity error each "
                      "solver event of the step removes, DIR/<scene>_stepNNNNN_velocity_error.png")
          ->type_name("DIR");
  CLI::Option* trace =
      run->add_option("--trace-step", options.traceStep,
                      "run to step N and draw one frame per solver event of that step, "
                      "DIR/<scene>/<scene>_stepNNNNN_00000.png, ..., and its sheet "
                      "<scene>_stepNNNNN_sheet.png; box2d cannot be traced")
          ->type_name("N")
          ->check(CLI::Range(1, mostSteps()).description("1 to the run's steps"))
          ->needs(frames)
          ->excludes(csv)
          ->excludes(contacts)
          ->excludes(run->get_option("--video"))
          ->excludes(run->get_option("--animation"));
  run->add_option("--error-vs-reference", options.errorVsReferencePath,
                  "at every step also solve the method's pre-solve state exactly (the global "
                  "reference) and write solve,t,points,impulse_error,violation to FILE: "
                  "||λ - λ*||/||λ*|| and the worst violated contact condition; the summary "
                  "gives their median and largest (docs/global-reference.md)")
      ->type_name("FILE")
      ->excludes(csv)
      ->excludes(contacts)
      ->excludes(frames)
      ->excludes(trace)
      ->excludes(plots);
  run->callback([&options] { checkRunOutputs(options); });
  run->footer(kRunFooter);
}

void addCheck(CLI::App& app, CheckOptions& options) {
  CLI::App* check = app.add_subcommand(
      "check",
      "validate a scene and print what it holds, marking each solver setting that differs from "
      "the published method");
  addScene(*check, options.scene);
  addSolverOptions(*check, options.scene);
  addSceneOverrides(*check, options.scene);
  check->footer(kCheckFooter);
}

/// The panels of `--solvers`: each entry SOLVER or SOLVER:PRESET, labelled with it.
void addSolverPanels(std::vector<PanelOption>& panels, const std::vector<std::string>& entries) {
  for (const std::string& entry : entries) {
    const size_t colon = entry.find(':');
    PanelOption panel{entry, entry.substr(0, colon), std::nullopt, {}};
    if (colon != std::string::npos) panel.preset = entry.substr(colon + 1);
    panels.push_back(panel);
  }
}

void addCompare(CLI::App& app, CompareOptions& options) {
  CLI::App* compare = app.add_subcommand(
      "compare",
      "run the scene once per solver (--solvers) or once per set of settings (--panel) and "
      "write the runs side by side as frames");
  addScene(*compare, options.scene);
  const std::string panelsGroup = "panels (one of the two)";
  CLI::Option* solvers =
      compare
          ->add_option_function<std::vector<std::string>>(
              "--solvers",
              [&options](const std::vector<std::string>& entries) {
                addSolverPanels(options.panels, entries);
              },
              "one panel per solver, labelled with its name, LIST comma-separated; "
              "SOLVER:PRESET runs a preset: --solvers sequential,sequential:box2d_2_4 shows "
              "Box2D 2.4.1's method beside our default")
          ->type_name("LIST")
          ->delimiter(',')
          ->check(kSolverAndPreset)
          ->group(panelsGroup);
  compare
      ->add_option_function<std::vector<std::string>>(
          "--panel",
          [&options](const std::vector<std::string>& texts) {
            for (const std::string& text : texts) options.panels.push_back(parsePanel(text));
          },
          "one panel, repeatable, SPEC 'LABEL: SECTION.KEY=VALUE; SECTION.KEY=VALUE': the "
          "scene with these --set changes, labelled LABEL; the changes after ':' are separated "
          "by ';' and may be left out")
      ->type_name("SPEC")
      ->group(panelsGroup)
      ->excludes(solvers);
  addSolverOptions(*compare, options.scene);
  compare->get_option("--solver")->description("the solver of every --panel panel");
  compare->get_option("--preset")->description("the preset of every --panel panel");
  addSceneOverrides(*compare, options.scene);
  addFrameOptions(*compare, options.frames, options.every);
  compare->get_option("--frames")->required();
  compare
      ->add_option("--plots", options.plots,
                   "the panels' figures overlaid, one curve per panel: "
                   "DIR/<scene>_compare_kinetic.png, ... as for i2d run")
      ->type_name("DIR");
  compare->callback([&options] {
    if (options.panels.empty()) throw UsageError("i2d compare needs --solvers or --panel");
  });
  compare->footer(kCompareFooter);
}

void addAgree(CLI::App& app, AgreeOptions& options) {
  CLI::App* agree =
      app.add_subcommand("agree", "print how far each method strays from Box2D, as Markdown");
  addScene(*agree, options.scene);
  options.solvers = impulse2d::solverNames();
  agree
      ->add_option("--solvers", options.solvers,
                   "the methods to measure, LIST comma-separated (default " +
                       CLI::detail::join(options.solvers, ",") + "); Box2D is always the reference")
      ->type_name("LIST")
      ->delimiter(',')
      ->check(CLI::IsMember(impulse2d::solverNames()));
  agree->add_flag("--summary", options.summaryOnly,
                  "the summary table only (for scenes of many bodies)");
  addSceneOverrides(*agree, options.scene);
  agree->footer(kAgreeFooter);
}

/// The command named first, or a usage error naming what is there instead.
void checkCommandName(const CLI::App& app, const std::vector<std::string>& arguments) {
  if (arguments.empty()) throw UsageError("no command given (see i2d --help)");
  const std::string& name = arguments.front();
  if (name == "--help" || name == "-h" || name == "help") return;
  if (name.rfind('-', 0) == 0)
    throw UsageError("no command given before '" + name + "' (see i2d --help)");
  for (const CLI::App* command : app.get_subcommands({})) {
    if (command->get_name() == name) return;
  }
  throw UsageError("unknown command '" + name + "' (see i2d --help)");
}

}  // namespace

CommandLine parseCommandLine(const std::vector<std::string>& arguments) {
  CommandLine line;
  CLI::App app("i2d - run, draw, compare and check impulse2d scene files", "i2d");
  app.formatter(std::make_shared<HelpFormatter>());
  app.set_help_flag("-h,--help", "print this help");
  app.require_subcommand(1);
  app.footer(generalFooter());
  app.option_defaults()
      ->group(kOptionsGroup)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast)
      ->disable_flag_override();
  addRun(app, line.run);
  addCompare(app, line.compare);
  addAgree(app, line.agree);
  addCheck(app, line.check);
  for (CLI::App* command : app.get_subcommands({})) command->get_help_ptr()->group(kOptionsGroup);
  app.add_subcommand("presets", "list the presets: each method as its authors published it")
      ->footer(kPresetsFooter)
      ->get_help_ptr()
      ->group("options");
  checkCommandName(app, arguments);
  try {
    if (arguments.front() == "help") throw CLI::CallForHelp();
    app.parse(std::vector<std::string>(arguments.rbegin(), arguments.rend()));
  } catch (const CLI::CallForHelp&) {
    line.help = app.help();
    return line;
  } catch (const CLI::ParseError& error) {
    const std::vector<CLI::App*> chosen = app.get_subcommands();
    std::string message = error.what();
    if (dynamic_cast<const CLI::ExtrasError*>(&error) && !chosen.empty()) {
      message += " (see i2d " + chosen.front()->get_name() + " --help)";
    }
    throw UsageError(message);
  }
  const std::map<std::string, Command> commands = {{"run", Command::Run},
                                                   {"check", Command::Check},
                                                   {"compare", Command::Compare},
                                                   {"agree", Command::Agree},
                                                   {"presets", Command::Presets}};
  line.command = commands.at(app.get_subcommands().front()->get_name());
  return line;
}

}  // namespace i2d
