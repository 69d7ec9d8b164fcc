// The help texts: CLI11's, laid out so a student can run a scene without opening the docs.
#include "help.h"

#include <algorithm>
#include <sstream>
#include <vector>

#include "impulse2d/presets.h"

namespace i2d {
namespace {

/// The width the help is wrapped to, and where option descriptions start.
constexpr size_t kHelpWidth = 96;
constexpr size_t kOptionColumn = 24;
constexpr size_t kCommandColumn = 32;

/// `text` wrapped at kHelpWidth, each line after the first indented by `indent` columns, the first
/// starting `used` columns in.
std::string wrap(const std::string& text, size_t indent, size_t used) {
  std::istringstream words(text);
  std::string wrapped;
  size_t column = used;
  for (std::string word; words >> word;) {
    if (column > used && column + 1 + word.size() > kHelpWidth) {
      wrapped += "\n" + std::string(indent, ' ');
      column = indent;
    } else if (column > used) {
      wrapped += ' ';
      ++column;
    }
    wrapped += word;
    column += word.size();
  }
  return wrapped;
}

/// A name in its column and its description beside it (on the next line when the name is wider).
std::string row(const std::string& name, const std::string& description, size_t column) {
  std::string line = "  " + name;
  if (line.size() + 1 > column) {
    line += "\n" + std::string(column, ' ');
  } else {
    line += std::string(column - line.size(), ' ');
  }
  return line + wrap(description, column, column) + "\n";
}

/// "--a, --b" for a set of options, by name.
std::string names(const std::set<CLI::Option*>& options) {
  std::vector<std::string> sorted;
  for (const CLI::Option* option : options) sorted.push_back(option->get_name());
  std::sort(sorted.begin(), sorted.end());
  return CLI::detail::join(sorted, ", ");
}

/// The value an option takes, "N" of "N:an integer in [0, 10000000]", and what its validators
/// say of it after the colons.
std::pair<std::string, std::vector<std::string>> typeAndValues(const CLI::Option* option) {
  std::vector<std::string> parts = CLI::detail::split(option->get_type_name(), ':');
  const std::string type = parts.front();
  parts.erase(parts.begin());
  parts.erase(std::remove(parts.begin(), parts.end(), ""), parts.end());
  for (std::string& part : parts) part = CLI::detail::find_and_replace(part, ",", ", ");
  return {type, parts};
}

/// "SCENE --frames DIR [options]": the positionals, the required options, then the others.
std::string usageTail(const CLI::App* app) {
  std::string tail;
  bool optional = false;
  for (const CLI::Option* option : app->get_options()) {
    if (!option->nonpositional()) {
      tail += " " + option->get_name();
    } else if (option->get_required()) {
      tail += " " + option->get_name() + " " + typeAndValues(option).first;
    } else if (option != app->get_help_ptr()) {
      optional = true;
    }
  }
  return tail + (optional ? " [options]" : "");
}

}  // namespace

std::string HelpFormatter::make_help(const CLI::App* app, std::string name,
                                     CLI::AppFormatMode mode) const {
  if (app->get_parent() == nullptr) {
    std::string text = app->get_description() + "\n\nusage:\n";
    for (const CLI::App* command : app->get_subcommands({})) text += make_subcommand(command);
    text += row("i2d --help", "this text", kCommandColumn);
    text += row("i2d COMMAND --help", "the options of one command", kCommandColumn);
    return text + "\n" + make_footer(app);
  }
  return make_usage(app, name) + "\n" + wrap(app->get_description(), 0, 0) + "\n\n" +
         make_groups(app, mode) + "\n" + make_footer(app);
}

std::string HelpFormatter::make_group(std::string group, bool positional,
                                      std::vector<const CLI::Option*> options) const {
  std::string text = group + ":\n";
  for (const CLI::Option* option : options) text += make_option(option, positional);
  return text;
}

std::string HelpFormatter::make_usage(const CLI::App* app, std::string name) const {
  return "usage: " + name + usageTail(app) + "\n";
}

std::string HelpFormatter::make_option(const CLI::Option* option, bool) const {
  const auto [type, values] = typeAndValues(option);
  std::string description = option->get_description();
  for (const std::string& value : values) description += " (" + type + ": " + value + ")";
  if (option->get_required()) description += "; required";
  if (!option->get_needs().empty()) description += "; needs " + names(option->get_needs());
  if (!option->get_excludes().empty()) description += "; not with " + names(option->get_excludes());
  const std::string name = option->get_name(false, true);
  return row(option->get_type_size() == 0 ? name : name + " " + type, description, kOptionColumn);
}

std::string HelpFormatter::make_subcommand(const CLI::App* command) const {
  return row("i2d " + command->get_name() + usageTail(command), command->get_description(),
             kCommandColumn);
}

std::string generalFooter() {
  std::string presets;
  for (const impulse2d::Preset& preset : impulse2d::presets()) {
    std::string name = "  " + preset.solver;
    name.resize(15, ' ');
    name += preset.name;
    name.resize(29, ' ');
    presets += name + wrap(preset.summary, 29, 29) + "\n";
  }
  return R"(SCENE is a TOML scene file (docs/scene-format.md); demos/scenes/ holds one per lecture concept,
and an installed i2d runs those by name: i2d run resting_box.
The solvers are micro, sequential, soft_step, reference and box2d (Box2D 2.4, the behaviour
reference). Our default of a method is the published method plus refinements; a preset runs
the method as published ([solver] preset = "NAME" in a scene, --preset NAME on the command
line; i2d presets says what each is):
)" + presets +
         R"(
examples:
  i2d run demos/scenes/bouncing_ball.toml --csv ball.csv
  i2d run demos/scenes/bouncing_ball.toml --frames frames --every 5
  i2d run demos/scenes/resting_box.toml --trace-step 40 --frames frames
  i2d compare demos/scenes/stack.toml --solvers micro,sequential,reference --frames frames
  i2d compare demos/scenes/pyramid40.toml --solvers sequential,sequential:box2d_2_4 --frames f
  i2d check demos/scenes/stack.toml --preset box2d_2_4 --set solver.velocity_iterations=20
  i2d agree demos/scenes/bouncing_ball.toml
  scripts/demos                 every lecture demo, frames and sheets under frames/

exit codes:
  0  success
  1  failure while running: a body became non-finite, a file or frame could not be written,
     --video without ffmpeg on PATH, a step with nothing to trace
  2  bad command line: unknown command or option, missing or malformed value, a --set or
     --panel assignment not of the form section.key=value
  3  invalid scene: unreadable file, TOML syntax error, unknown key, wrong type, missing key,
     number out of range, degenerate or non-convex polygon, unknown solver or shape, empty file;
     the same from a --set or --panel assignment

errors are one line on stderr: "error: FILE:LINE:COLUMN: what is wrong" for a scene.)";
}

const char* const kRunFooter =
    R"(Runs the scene for its [world] steps and prints: steps and simulated time, wall time and
microseconds per step, the contact points at the end and the penetration of the last state, the
kinetic and potential energy at the start and the end, and what it wrote.

frames: each frame's legend strip says what its colours and arrows mean. Body colours: grey
static, sky blue flying, green resting, purple touching (rolling, bouncing), orange sliding.
Everything that acts is an arrow at one force scale, shown in the legend: black applied loads
with their value, blue normal forces (impulse / dt), violet friction that held (static) and
vermilion friction on its limit (dynamic), each friction arrow crossed at its limit mu N. The bar
under each contact is its friction gauge, |friction| / (mu normal), vermilion when full.
The overlay switches (--no-overlays, --hide, --show) apply in the order given:
--no-overlays --show normal_impulses.

contacts CSV: the header is exactly
  step,t,body_a,body_b,point,x,y,nx,ny,normal_impulse_Ns,friction_impulse_Ns,normal_force_N,
  friction_force_N,mu,friction_limit_N,friction,load_a_x_N,load_a_y_N,load_b_x_N,load_b_y_N
(one line) then one row per contact point per recorded step; the normal points from body_a to
body_b, forces are impulse / dt, friction is static, sliding or none.

CSV: the header is exactly
  step,t,body,x,y,angle_rad,vx,vy,omega_rad_s
then one row per dynamic body per recorded step; step 0 is the initial state, t = step * dt in
seconds, body is the body's name, x and y are its centre of mass in m (for a polygon this is
its centroid, not the origin its vertices were given in), vx and vy in m/s, the angle in rad and
omega in rad/s, counter-clockwise.

If a body's state becomes non-finite the run stops with
  error: body NAME became non-finite at step N (solver S)
and exit code 1, keeping the CSV rows, frames and sheet of the steps before. Bodies that start
overlapping by more than the solver's allowed overlap are warned about before the run.

exit codes: 0 success, 1 failure while running (non-finite state, unwritable file or frame
directory or plot directory, --video or --animation mp4 without ffmpeg), 2 bad command line,
3 invalid scene.)";

const char* const kCompareFooter =
    R"(The panels run in lockstep for the first panel's time, each under a bar with its label, all
drawn with one camera: DIR/<scene>/<scene>_compare_00000.png, ... and
DIR/<scene>/<scene>_compare_sheet.png, then each panel's energies at the end are printed. A
panel with another time step (world.dt) takes the steps that time needs, and each frame shows
it at the step nearest the frame's time.

For a feature switch, one panel with it on, one with it off:
  --panel 'removal on: solver.remove_acceleration_velocity=true'
  --panel 'removal off: solver.remove_acceleration_velocity=false'
A panel can switch solver: --panel 'sequential: world.solver=sequential'

Each panel's scene is: the file, --solver (or the panel's solver), each --set, the panel's
changes, then --steps and --dt. The other options are as for i2d run; the viewer page is
DIR/<scene>/<scene>_compare.html.

exit codes: 0 success, 1 failure while running (a panel became non-finite, unwritable frame
directory, --video without ffmpeg), 2 bad command line, 3 invalid scene.)";

const char* const kAgreeFooter =
    R"(Runs the scene in Box2D and in each of our methods, one step of each in turn, and prints as
Markdown a summary table (time to rest, drift since 1 s, largest differences) and one table per
dynamic body (final height, slide, apex after the first bounce, position and angle difference
from Box2D at the end and at most). Read the position differences against Box2D's 0.01 m
polygon skin (docs/box2d-reference.md): a box on the ground sits 0.015-0.02 m higher in Box2D,
and that is agreement.

exit codes: 0 success, 1 failure while running, 2 bad command line, 3 invalid scene.)";

const char* const kCheckFooter =
    R"(Prints the scene's solver and steps, the [world] settings and the chosen solver's settings
with every value (defaults included), the bodies counted by shape and type, and each body as
the engine sees it (centre of mass, angle, material).
A solver setting that differs from the method as its authors published it is marked
"* published: VALUE"; the method is the run's preset, or the solver's first preset
(micro: lecture, sequential: box2d_lite, soft_step: box2d_v3). The options change the scene as
for i2d run: the settings printed are those the run would use.

exit codes: 0 valid scene, 2 bad command line, 3 invalid scene (one line on stderr:
"error: FILE:LINE:COLUMN: what is wrong").)";

const char* const kPresetsFooter =
    R"(A preset sets the solver's settings to the method as its authors published it; choose one
with [solver] preset = "NAME" in a scene or --preset NAME on the command line.)";

}  // namespace i2d
