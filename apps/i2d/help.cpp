// The help texts: everything a student needs to run a scene without opening the docs.
#include "help.h"

namespace i2d {

const char* const kGeneralHelp = R"(i2d - run, draw, compare and check impulse2d scene files

usage:
  i2d run SCENE [options]       run a scene, print a summary; optionally write its trajectory
                                (--csv), PNG frames and a contact sheet (--frames), or one
                                frame per solver event of one step (--trace-step)
  i2d compare SCENE [options]   run the scene once per solver (--solvers) or once per set of
                                settings (--panel) and write the runs side by side as frames
  i2d agree SCENE [options]     print how far each method strays from Box2D, as Markdown
  i2d check SCENE [options]     validate a scene and print what it holds, marking each
                                solver setting that differs from the published method
  i2d presets                   list the presets: each method as its authors published it
  i2d --help                    this text
  i2d COMMAND --help            the options of one command

SCENE is a TOML scene file (docs/scene-format.md); demos/scenes/ holds one per lecture concept,
and an installed i2d runs those by name: i2d run resting_box.
The solvers are micro, sequential, soft_step, reference and box2d (Box2D 2.4, the behaviour
reference). Our default of a method is the published method plus refinements; a preset runs
the method as published ([solver] preset = "NAME" in a scene, --preset NAME on the command
line; i2d presets says what each is):
  micro        lecture       the micro-collision resolver as the lecture states it
  sequential   box2d_lite    Catto's Box2D-Lite
  sequential   box2d_2_4     Box2D 2.4.1's contact solver, 8 + 3 iterations
  soft_step    box2d_v3      Box2D v3's soft step

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

errors are one line on stderr: "error: FILE:LINE:COLUMN: what is wrong" for a scene.
)";

const char* const kRunHelp = R"(usage: i2d run SCENE [options]

Runs the scene for its [world] steps and prints: steps and simulated time, wall time and
microseconds per step, the contact points at the end and the penetration of the last state, the
kinetic and potential energy at the start and the end, and what it wrote.

options (a value follows the option or '=': --steps 100, --steps=100):
  --solver NAME         run this solver instead of the scene's: micro, sequential, reference,
                        soft_step, box2d; its settings are then the defaults, change them
                        with --set
  --preset NAME         the solver's settings as its authors published them (i2d presets),
                        applied after --solver and before --set
  --steps N             number of steps (N >= 0) instead of [world] steps
  --dt S                time step in seconds (S > 0) instead of [world] dt
  --set SECTION.KEY=VALUE
                        change one setting as a scene file would, SECTION world, solver
                        (the solver's own settings) or render (the view); repeatable,
                        applied in order after --solver, e.g. --set
                        solver.velocity_iterations=20 --set world.gravity=[0,-1.62]
                        --set render.follow=box; a bare word is a string
  --csv FILE            write the trajectory; FILE appears only when complete; - or
                        /dev/stdout is standard output, a device or pipe is written in place
  --contacts FILE       write every contact point's forces per recorded step: bodies, point,
                        normal, impulses and forces, mu, the limit mu N, static or sliding,
                        each body's applied load (header below); FILE appears when complete
  --every K             CSV rows and frames every K-th step (K >= 1), plus step 0 and the last
  --frames DIR          write PNG frames DIR/<scene>/<scene>_00000.png, _00001.png, ... (one
                        per recorded step, numbered without gaps), the contact sheet
                        DIR/<scene>/<scene>_sheet.png and the viewer page
                        DIR/<scene>/index.html (open it in a browser: slider, arrow keys,
                        each frame's figures); DIR's parent must exist
  --format png|svg|pdf  the frames' and sheet's format (default png); svg and pdf are vector
                        drawings with their text as text
  --size WxH            the frames' size in pixels, strips included (default: the scene's
                        [render] width and height); the view is fitted into it
  --theme print         white background and dark lines, for handouts and slides
  --video               also write DIR/<scene>/<scene>.mp4 in real time (needs --frames and
                        ffmpeg on PATH)
  --animation KIND      also write one file of the frames, in real time: gif (always
                        possible, DIR/<scene>/<scene>.gif) or mp4 (needs ffmpeg on PATH)
  --plots DIR           gnuplot PNGs of the run against time: DIR/<scene>_kinetic.png,
                        _potential.png, _total.png (energy), _contacts.png (contact points),
                        _penetration.png (largest); with --trace-step, the velocity error each
                        solver event of the step removes, DIR/<scene>_stepNNNNN_velocity_error.png
  --trace-step N        with --frames: run to step N (1 to the run's steps) and draw one frame
                        per solver event of that step, DIR/<scene>/<scene>_stepNNNNN_00000.png,
                        ..., and its sheet <scene>_stepNNNNN_sheet.png; box2d cannot be traced
  --error-vs-reference FILE
                        at every step also solve the method's pre-solve state exactly (the
                        global reference) and write solve,t,points,impulse_error,violation to
                        FILE: ||λ - λ*||/||λ*|| and the worst violated contact condition; the
                        summary gives their median and largest (docs/global-reference.md)
  --no-overlays         frames show the bodies in their state colours only
  --hide LIST           turn these overlays off, LIST a comma-separated list of
                        rotation_marks, contact_points, contact_normals, normal_impulses,
                        friction_impulses, loads, weights, sliding_velocities, velocities,
                        heads_up, friction_gauges, legend, or all
  --show LIST           turn these overlays on (contact_normals, weights and velocities are
                        off by default); the switches
                        apply in the order given: --no-overlays --show normal_impulses

frames: each frame's legend strip says what its colours and arrows mean. Body colours: grey
static, sky blue flying, green resting, purple touching (rolling, bouncing), orange sliding.
Everything that acts is an arrow at one force scale, shown in the legend: black applied loads
with their value, blue normal forces (impulse / dt), violet friction that held (static) and
vermilion friction on its limit (dynamic), each friction arrow crossed at its limit mu N. The bar
under each contact is its friction gauge, |friction| / (mu normal), vermilion when full.

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
3 invalid scene.
)";

const char* const kCompareHelp =
    R"(usage: i2d compare SCENE (--solvers LIST | --panel SPEC...) --frames DIR [options]

Runs the scene once per panel, all panels in lockstep, and writes their frames side by side,
each under a bar with its label, all drawn with one camera:
  DIR/<scene>/<scene>_compare_00000.png, ...   and   DIR/<scene>/<scene>_compare_sheet.png
then prints each panel's energies at the end. The panels run for the first panel's time; a
panel with another time step (world.dt) takes the steps that time needs, and each frame shows
it at the step nearest the frame's time.

panels (one of the two):
  --solvers LIST        one panel per solver, labelled with its name, LIST comma-separated:
                        micro,sequential,reference,soft_step,box2d; SOLVER:PRESET runs a
                        preset: --solvers sequential,sequential:box2d_2_4 shows Box2D 2.4.1's
                        method beside our default
  --panel 'LABEL: SECTION.KEY=VALUE; SECTION.KEY=VALUE'
                        one panel, repeatable: the scene with these --set changes, labelled
                        LABEL; the changes after ':' are separated by ';' and may be left
                        out. For a feature switch, one panel with it on, one with it off:
                          --panel 'removal on: solver.remove_acceleration_velocity=true'
                          --panel 'removal off: solver.remove_acceleration_velocity=false'
                        A panel can switch solver: --panel 'sequential: world.solver=sequential'

options (a value follows the option or '=': --steps 100, --steps=100):
  --frames DIR          where the frames go (required)
  --every K             a frame every K-th step (K >= 1), plus step 0 and the last
  --steps N, --dt S     as for i2d run, for every panel
  --solver NAME         the solver of every --panel panel, instead of the scene's
  --preset NAME         the preset of every --panel panel (i2d presets)
  --set SECTION.KEY=VALUE
                        a change for every panel, applied before the panel's own
  --video, --animation KIND, --format, --size, --theme, --no-overlays, --hide LIST,
  --show LIST           as for i2d run; the viewer page is DIR/<scene>/<scene>_compare.html
  --plots DIR           the panels' figures overlaid, one curve per panel:
                        DIR/<scene>_compare_kinetic.png, ... as for i2d run

Each panel's scene is: the file, --solver (or the panel's solver), each --set, the panel's
changes, then --steps and --dt.

exit codes: 0 success, 1 failure while running (a panel became non-finite, unwritable frame
directory, --video without ffmpeg), 2 bad command line, 3 invalid scene.
)";

const char* const kAgreeHelp = R"(usage: i2d agree SCENE [options]

Runs the scene in Box2D and in each of our methods, one step of each in turn, and prints as
Markdown how far each method strays from Box2D: a summary table (time to rest, drift since
1 s, largest differences) and one table per dynamic body (final height, slide, apex after the
first bounce, position and angle difference from Box2D at the end and at most). Read the
position differences against Box2D's 0.01 m polygon skin (docs/box2d-reference.md): a box on
the ground sits 0.015-0.02 m higher in Box2D, and that is agreement.

options (a value follows the option or '=': --steps 100, --steps=100):
  --solvers LIST        the methods to measure, comma-separated (default
                        micro,sequential,reference,soft_step); Box2D is always the reference
  --summary             the summary table only (for scenes of many bodies)
  --steps N, --dt S, --set SECTION.KEY=VALUE
                        as for i2d run

exit codes: 0 success, 1 failure while running, 2 bad command line, 3 invalid scene.
)";

const char* const kCheckHelp = R"(usage: i2d check SCENE [options]

Validates the scene file and prints what it holds: its solver and steps, the [world] settings
and the chosen solver's settings with every value (defaults included), the bodies counted by
shape and type, and each body as the engine sees it (centre of mass, angle, material).
A solver setting that differs from the method as its authors published it is marked
"* published: VALUE"; the method is the run's preset, or the solver's first preset
(micro: lecture, sequential: box2d_lite, soft_step: box2d_v3).

options: --solver NAME, --preset NAME, --set SECTION.KEY=VALUE, --steps N, --dt S, as for
i2d run: the settings printed are those the run would use.

exit codes: 0 valid scene, 2 bad command line, 3 invalid scene (one line on stderr:
"error: FILE:LINE:COLUMN: what is wrong").
)";

const char* const kPresetsHelp = R"(usage: i2d presets

Lists every preset, one line each: its solver, its name and what it is. A preset sets the
solver's settings to the method as its authors published it; choose one with
[solver] preset = "NAME" in a scene or --preset NAME on the command line.
)";

}  // namespace i2d
