// The command line of each i2d command, parsed into plain options (options.cpp declares each
// option once on CLI11). Options take their value as the next argument or after '='
// (--steps 100, --steps=100); switches (--video) take none; a bad command line throws UsageError.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "impulse2d/render/drawing.h"
#include "impulse2d/render/render_settings.h"

namespace i2d {

/// What changes the scene before it runs: applied as --solver, --preset, each --set, --steps,
/// --dt.
struct SceneOptions {
  std::string scenePath;
  std::optional<std::string> solver;  ///< --solver: replaces the scene's solver
  std::optional<std::string> preset;  ///< --preset: the solver's settings as published
  std::optional<int> steps;           ///< --steps: replaces [world] steps
  std::optional<double> dt;           ///< --dt: replaces [world] dt (s)
  std::vector<std::string> settings;  ///< --set section.key=value, applied in order
};

/// A frame's size in pixels, from --size WxH.
struct FrameSize {
  int width = 0;
  int height = 0;
};

/// Where frames go, in which format and size, and what they show.
struct FrameOptions {
  std::optional<std::string> directory;  ///< --frames: frames go to DIRECTORY/<scene>/
  impulse2d::render::ImageFormat format = impulse2d::render::ImageFormat::Png;  ///< --format
  std::optional<FrameSize> size;         ///< --size: replaces the scene's [render] width and height
  bool printTheme = false;               ///< --theme print: white background, dark lines
  bool video = false;                    ///< --video: an MP4 of the frames through ffmpeg
  std::optional<std::string> animation;  ///< --animation gif|mp4: one file of the frames
  impulse2d::render::Overlays overlays;  ///< --no-overlays, --hide, --show
};

struct RunOptions {
  SceneOptions scene;
  FrameOptions frames;
  std::optional<std::string> csvPath;       ///< --csv: the trajectory file
  std::optional<std::string> contactsPath;  ///< --contacts: every contact point's forces, CSV
  int every = 1;                            ///< --every: CSV rows and frames every K-th step
  std::optional<int> traceStep;             ///< --trace-step: one frame per solver event of step N
  /// --error-vs-reference: each step's error against the exact answer goes to this CSV.
  std::optional<std::string> errorVsReferencePath;
  std::optional<std::string> plots;  ///< --plots: gnuplot PNGs of the run's figures go here
};

struct CheckOptions {
  SceneOptions scene;
};

/// One panel of `i2d compare`: a label and the scene changes that make it differ.
struct PanelOption {
  std::string label;
  std::optional<std::string> solver;  ///< from --solvers
  std::optional<std::string> preset;  ///< from --solvers SOLVER:PRESET
  std::vector<std::string> settings;  ///< from --panel 'LABEL: section.key=value; ...'
};

struct CompareOptions {
  SceneOptions scene;
  FrameOptions frames;
  std::vector<PanelOption> panels;   ///< from --solvers or each --panel, left to right
  int every = 1;                     ///< --every: a frame every K-th step
  std::optional<std::string> plots;  ///< --plots: the panels' figures overlaid, one PNG each
};

struct AgreeOptions {
  SceneOptions scene;
  std::vector<std::string> solvers;  ///< --solvers: the methods measured against Box2D
  bool summaryOnly = false;          ///< --summary: the summary table without the body tables
};

/// The i2d commands; Help stands for any --help, whose text the command line holds.
enum class Command { Help, Run, Check, Compare, Agree, Presets };

/// A parsed command line: the command and the options of it (the others stay default).
struct CommandLine {
  Command command = Command::Help;
  std::string help;  ///< what --help prints, for Command::Help
  RunOptions run;
  CheckOptions check;
  CompareOptions compare;
  AgreeOptions agree;
};

/// Reads `i2d COMMAND ...` (the arguments after the program's name); throws UsageError.
CommandLine parseCommandLine(const std::vector<std::string>& arguments);

}  // namespace i2d
