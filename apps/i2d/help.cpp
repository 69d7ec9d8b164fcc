// The help texts: everything a student needs to run a scene without opening the docs.
#include "help.h"

namespace i2d {

const char* const kGeneralHelp = R"(i2d - run and check impulse2d scene files

usage:
  i2d run SCENE [options]   run a scene, print a summary, optionally write its trajectory
  i2d check SCENE           validate a scene and print what it holds
  i2d --help                this text
  i2d COMMAND --help        the options of one command

SCENE is a TOML scene file (docs/scene-format.md); demos/scenes/ holds one per lecture concept:
  i2d run demos/scenes/bouncing_ball.toml --csv ball.csv

exit codes:
  0  success
  1  failure while running: a body became non-finite, a file could not be written, or the
     chosen solver or option is not built yet
  2  bad command line: unknown command or option, missing or malformed value, bad --set
  3  invalid scene: unreadable file, TOML syntax error, unknown key, wrong type, missing key,
     number out of range, degenerate or non-convex polygon, unknown solver or shape, empty file

errors are one line on stderr: "error: FILE:LINE:COLUMN: what is wrong" for a scene.
)";

const char* const kRunHelp = R"(usage: i2d run SCENE [options]

Runs the scene for its [world] steps and prints: steps and simulated time, wall time and
microseconds per step, contact points and the largest penetration at the end, and the kinetic
and potential energy at the start and the end.

options (a value follows the option or '=': --steps 100, --steps=100):
  --solver NAME         run this solver instead of the scene's: micro, sequential, reference,
                        box2d; its settings are then the defaults, change them with --set
  --steps N             number of steps (N >= 0) instead of [world] steps
  --dt S                time step in seconds (S > 0) instead of [world] dt
  --set SECTION.KEY=VALUE
                        change one setting as a scene file would, SECTION world or solver
                        (the solver's own settings); repeatable, applied in order after
                        --solver, e.g. --set solver.velocity_iterations=20
                        --set world.gravity=[0,-1.62]; a bare word is a string
  --csv FILE            write the trajectory; FILE appears only when complete
  --every K             record every K-th step in the CSV (K >= 1), plus step 0 and the last
  --frames DIR          write PNG frames into DIR (not built yet)

CSV: the header is exactly
  step,t,body,x,y,angle_rad,vx,vy,omega_rad_s
then one row per dynamic body per recorded step; step 0 is the initial state, t = step * dt in
seconds, body is the body's name, x and y are its centre of mass in m (for a polygon this is
its centroid, not the origin its vertices were given in), vx and vy in m/s, the angle in rad and
omega in rad/s, counter-clockwise.

If a body's state becomes non-finite the run stops with
  error: body NAME became non-finite at step N
and exit code 1, keeping the CSV rows of the steps before.

exit codes: 0 success, 1 failure while running, 2 bad command line, 3 invalid scene.
)";

const char* const kCheckHelp = R"(usage: i2d check SCENE

Validates the scene file and prints what it holds: its solver and steps, the [world] settings
and the chosen solver's settings with every value (defaults included), the bodies counted by
shape and type, and each body as the engine sees it (centre of mass, angle, material).

exit codes: 0 valid scene, 2 bad command line, 3 invalid scene (one line on stderr:
"error: FILE:LINE:COLUMN: what is wrong").
)";

}  // namespace i2d
