// stress_catalogue: finds every method's breaking point on every stress scene and writes, per
// scene, its Markdown table, its chart data and the contact sheet of each failure. scripts/
// stability runs it and assembles docs/stability.md.
//   stress_catalogue --out DIR [--frames DIR] [--scenes a,b,...]
//   stress_catalogue --summary-header       the header of the summary table
//   stress_catalogue --run SCENE METHOD KNOB [KEY=VALUE...]
//                                           one run to its collapse, its figures on stdout; the
//                                           settings (as i2d --set) are added to the method's
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "breaking_points.h"
#include "impulse2d/render/camera.h"
#include "impulse2d/render/frame.h"
#include "impulse2d/render/frame_writer.h"

using namespace impulse2d;
using namespace impulse2d::stress;

namespace {

/// Frames kept per failure run, first and last step included: enough for its contact sheet.
constexpr int kFramesPerFailure = 12;
/// A run that stopped early (non-finite, solver error) is charted at this multiple of the limit.
constexpr double kChartStoppedFactor = 100.0;
/// Log charts cannot show zero: figures below this are drawn at it.
constexpr double kChartFloor = 1e-6;

struct Options {
  std::string out;
  std::string frames;
  std::vector<std::string> scenes;
};

std::vector<std::string> splitCommas(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, ',');) parts.push_back(part);
  return parts;
}

std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

/// A knob value as the tables print it: time steps as 1/N s.
std::string formatKnob(const Knob& knob, double value) {
  if (knob.unit == "s") return "1/" + formatNumber(1.0 / value);
  return formatNumber(value);
}

std::string summaryCell(const StressScene& stress, const BreakingPoint& point) {
  switch (point.verdict) {
    case Verdict::FailsAtEasiest:
      return "fails at " + formatKnob(stress.knob, point.firstFailed);
    case Verdict::HoldsThroughout:
      return "holds to " + formatKnob(stress.knob, point.lastHeld);
    case Verdict::Breaks:
      break;
  }
  return "**" + formatKnob(stress.knob, point.firstFailed) + "**";
}

std::string failureNote(const BreakingPoint& point) {
  for (const Sample& sample : point.samples) {
    if (!sample.outcome.stopped.empty()) return sample.outcome.stopped;
  }
  return "";
}

std::vector<Method> methodsOf(const StressScene& stress) {
  std::vector<Method> methods;
  for (const Method& method : baseMethods()) {
    if (canRun(stress, method)) methods.push_back(method);
  }
  for (const std::string& fix : stress.extraMethods) methods.push_back(findMethod(fix));
  return methods;
}

/// The run at the first failing knob value, as frames and a contact sheet; returns the sheet.
std::string writeFailureSheet(const std::string& root, const StressScene& stress,
                              const Method& method, const Sample& failure) {
  const double knob = failure.knob;
  const Scene scene = sceneFor(stress, method, knob);
  // A run that stopped (non-finite) has no duration: it is drawn over the scene's steps.
  const long steps = failure.outcome.seconds > 0.0
                         ? std::lround(failure.outcome.seconds / scene.world.dt)
                         : long(scene.steps);
  const render::RenderSettings settings;
  const render::Camera camera = render::fitCamera(buildBodies(scene), ViewDef{}, settings);
  render::FrameRenderer renderer(camera, stress.name + " (" + method.label + ")", settings);
  const int every = int(std::max(1L, steps / (kFramesPerFailure - 1)));
  render::FrameWriter writer(root, stress.name, every, stress.name + "_" + slug(method.label),
                             settings);
  runStress(
      stress, method, knob,
      [&](const Simulation& simulation) {
        if (writer.wants(simulation.stepCount()))
          writer.write(simulation.stepCount(), renderer.draw(simulation));
      },
      failure.knob == hardestFor(stress, method) ? RunLength::UntilCollapsed
                                                 : RunLength::UntilFailed);
  return writer.writeContactSheet().string();
}

double chartValue(const StressScene& stress, const Outcome& outcome) {
  const double ceiling =
      stress.criterion.limit > 0.0 ? kChartStoppedFactor * stress.criterion.limit : 1.0;
  const double value = std::isfinite(outcome.measure) ? outcome.measure : ceiling;
  return stress.criterion.logarithmicChart ? std::max(value, kChartFloor) : value;
}

/// One gnuplot data block per method: its title, then (knob, figure) sorted by knob.
void writeChartBlock(std::ostream& data, const StressScene& stress, const Method& method,
                     const BreakingPoint& point) {
  std::map<double, double> byKnob;
  for (const Sample& sample : point.samples)
    byKnob[sample.knob] = chartValue(stress, sample.outcome);
  data << '"' << method.label << "\"\n";
  for (const auto& [knob, value] : byKnob) data << knob << ' ' << value << '\n';
  data << "\n\n";
}

void writeSampleRows(std::ostream& csv, const StressScene& stress, const Method& method,
                     const BreakingPoint& point) {
  for (const Sample& sample : point.samples) {
    csv << stress.name << ',' << method.label << ',' << sample.knob << ',' << sample.outcome.measure
        << ',' << (sample.outcome.failed ? 1 : 0) << ",\"" << sample.outcome.stopped << "\"\n";
  }
}

/// How a structure's run failed: "limit at 12.3 s", "sink at 0.4 s", "creep to 40 s".
std::string failedBy(const Outcome& outcome) {
  if (!outcome.stopped.empty()) return "stopped";
  if (outcome.ended == "creep") return "creep to " + formatNumber(outcome.seconds) + " s";
  return outcome.ended + " at " + formatNumber(outcome.failedAt) + " s";
}

/// A structure's slow figures on a run: sway, sink, creep and how the run ended.
std::string slowFigures(const Outcome& outcome) {
  if (!outcome.stopped.empty()) return "stopped";
  const StructureFigures& figures = outcome.structure;
  const bool failed = outcome.ended != "bounded" && outcome.ended != "unbounded";
  std::string end = failed ? failedBy(outcome) + ", " : "";
  end += figures.bounded ? "bounded at " : "ran ";
  return formatNumber(figures.sway) + " · " + formatNumber(figures.sink) + " · " +
         formatNumber(1e3 * figures.creep) + " · " + end + formatNumber(outcome.seconds) + " s";
}

const Sample* sampleAt(const BreakingPoint& point, double knob) {
  for (const Sample& sample : point.samples) {
    if (sample.knob == knob) return &sample;
  }
  return nullptr;
}

std::string methodRow(const StressScene& stress, const Method& method, const BreakingPoint& point,
                      const std::string& sheet) {
  const Knob& knob = stress.knob;
  const bool structure = stress.horizon.least > 0;
  std::string held =
      point.verdict == Verdict::FailsAtEasiest ? "—" : formatKnob(knob, point.lastHeld);
  std::string failed = point.verdict == Verdict::HoldsThroughout
                           ? "none to " + formatKnob(knob, point.hardest)
                           : formatKnob(knob, point.firstFailed);
  std::string figure = "—", how = "—", hardest = "—";
  const Sample* first = sampleAt(point, point.firstFailed);
  if (point.verdict != Verdict::HoldsThroughout && first != nullptr) {
    figure = first->outcome.stopped.empty() ? formatNumber(first->outcome.measure) : "stopped";
    how = failedBy(first->outcome);
  }
  if (const Sample* last = sampleAt(point, point.hardest)) hardest = slowFigures(last->outcome);
  const std::string note = failureNote(point);
  return "| " + method.label + " | " + held + " | " + failed + " | " + figure + " | " +
         (structure ? how + " | " + hardest + " | " : "") + std::to_string(point.samples.size()) +
         " | " + (sheet.empty() ? "—" : "`" + sheet + "`") + (note.empty() ? "" : " — " + note) +
         " |\n";
}

/// The per-scene table's header; a structure's adds how it failed and its slow figures.
std::string tableHeader(const StressScene& stress) {
  if (stress.horizon.least == 0) {
    return "| method | holds at | first fails at | figure there | runs | contact sheet |\n"
           "| --- | --- | --- | --- | --- | --- |\n";
  }
  return "| method | holds at | first fails at | figure there | failed by | at " +
         formatKnob(stress.knob, stress.knob.hard) +
         ": sway (m) · sink (m) · creep (mm/s) · end | runs | contact sheet |\n"
         "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
}

/// What a structure's horizon is and how its sink is judged, for its table's preamble.
std::string horizonNote(const StressScene& stress) {
  const Horizon& horizon = stress.horizon;
  if (horizon.least == 0) return "";
  const double dt = stress.build(stress.knob.easy).world.dt;
  const Knob& knob = stress.knob;
  return "**Watched** at least " + formatNumber(horizon.least * dt) + " s, then in windows of " +
         formatNumber(horizon.window * dt) + " s until its motion is bounded, " +
         formatNumber(horizon.most * dt) + " s at most.\n**Also fails** when the top body sinks " +
         "more than " + formatNumber(horizon.sinkLimit(knob.easy)) + " m at " +
         formatKnob(knob, knob.easy) + ", " + formatNumber(horizon.sinkLimit(knob.hard)) +
         " m at " + formatKnob(knob, knob.hard) + ", or creeps towards the limit at the end.\n\n";
}

void writeChartSettings(const std::string& path, const StressScene& stress) {
  std::ofstream meta(path);
  const Knob& knob = stress.knob;
  meta << "title = \"" << stress.title << "\"\n"
       << "xlabel = \"" << knob.name << (knob.unit.empty() ? "" : " (" + knob.unit + ")") << "\"\n"
       << "ylabel = \"" << stress.criterion.measure << "\"\n"
       << "limit = " << stress.criterion.limit << "\n"
       << "logx = " << (knob.scale == KnobScale::Logarithmic ? 1 : 0) << "\n"
       << "logy = " << (stress.criterion.logarithmicChart ? 1 : 0) << "\n";
}

/// Searches every method on the scene and writes its files into options.out.
void catalogueScene(const StressScene& stress, const Options& options) {
  const std::string base = options.out + "/" + stress.name;
  std::ofstream table(base + ".md"), data(base + ".dat"), csv(base + ".csv"), row(base + ".row");
  const Knob& knob = stress.knob;
  table << "**Knob:** " << knob.name << (knob.unit.empty() ? "" : " (" + knob.unit + ")")
        << ", searched from " << formatKnob(knob, knob.easy) << " to "
        << formatKnob(knob, knob.hard) << ".\n**Fails when** the " << stress.criterion.measure
        << " exceeds " << formatNumber(stress.criterion.limit) << ".\n**By eye:** "
        << stress.criterion.byEye << ".\n\n"
        << horizonNote(stress);
  for (const Intervention& intervention : stress.interventions) {
    table << "**Mid-run:** at step " << intervention.step << ", " << intervention.description
          << ".\n\n";
  }
  for (const auto& [name, hardest] : stress.hardestFor) {
    table << "**" << name << "** is searched only to " << formatKnob(knob, hardest)
          << ": beyond, its runs cost more than the catalogue's time budget.\n\n";
  }
  table << tableHeader(stress);
  row << "| " << stress.name << " (" << stress.knob.name << ") |";
  std::map<std::string, std::string> cells;
  for (const Method& method : methodsOf(stress)) {
    const auto begin = std::chrono::steady_clock::now();
    const std::clock_t cpuBegin = std::clock();
    const BreakingPoint point = findBreakingPoint(stress, method);
    std::string sheet;
    if (!options.frames.empty() && point.verdict != Verdict::HoldsThroughout) {
      sheet =
          writeFailureSheet(options.frames, stress, method, *sampleAt(point, point.firstFailed));
    }
    table << methodRow(stress, method, point, sheet);
    writeChartBlock(data, stress, method, point);
    writeSampleRows(csv, stress, method, point);
    cells[method.label] = summaryCell(stress, point);
    std::cerr << stress.name << " / " << method.label << ": " << summaryCell(stress, point) << " ("
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count()
              << " s, " << double(std::clock() - cpuBegin) / CLOCKS_PER_SEC << " s of CPU)\n";
  }
  for (const Method& method : baseMethods()) {
    row << ' ' << (cells.count(method.label) ? cells[method.label] : "—") << " |";
  }
  row << '\n';
  writeChartSettings(base + ".gp", stress);
}

std::string summaryHeader() {
  std::string header = "| scene (knob) |", rule = "| --- |";
  for (const Method& method : baseMethods()) {
    header += " " + method.label + " |";
    rule += " --- |";
  }
  return header + "\n" + rule + "\n";
}

Options parseOptions(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (i + 1 >= argc) throw std::invalid_argument("missing value after " + argument);
    if (argument == "--out") {
      options.out = argv[++i];
    } else if (argument == "--frames") {
      options.frames = argv[++i];
    } else if (argument == "--scenes") {
      options.scenes = splitCommas(argv[++i]);
    } else {
      throw std::invalid_argument("unknown option " + argument);
    }
  }
  if (options.out.empty()) throw std::invalid_argument("--out DIR is required");
  if (options.scenes.empty()) {
    for (const StressScene& stress : catalogue()) options.scenes.push_back(stress.name);
  }
  return options;
}

}  // namespace

/// One run, watched to its collapse as the hardest value of a search is, its figures printed.
void printRun(const std::string& scene, const std::string& label, double knob,
              const std::vector<std::string>& settings) {
  const auto begin = std::chrono::steady_clock::now();
  Method method = findMethod(label);
  std::string changes;
  for (const std::string& setting : settings) {
    method.settings.push_back(setting);
    changes += " " + setting;
  }
  const Outcome outcome =
      runStress(findStressScene(scene), method, knob, {}, RunLength::UntilCollapsed);
  const StructureFigures& figures = outcome.structure;
  std::cout << scene << " / " << label << changes << " at " << knob << ": figure "
            << outcome.measure << (outcome.failed ? " (failed)" : " (held)") << ", ended "
            << outcome.ended << outcome.stopped << " at " << outcome.seconds << " s (failed at "
            << outcome.failedAt << " s); sway " << figures.sway << " m, sink " << figures.sink
            << " m, creep " << figures.creep << " m/s; "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count()
            << " s to run\n";
}

int main(int argc, char** argv) {
  try {
    if (argc >= 5 && std::string(argv[1]) == "--run") {
      printRun(argv[2], argv[3], std::stod(argv[4]),
               std::vector<std::string>(argv + 5, argv + argc));
      return 0;
    }
    if (argc == 2 && std::string(argv[1]) == "--summary-header") {
      std::cout << summaryHeader();
      return 0;
    }
    const Options options = parseOptions(argc, argv);
    for (const std::string& name : options.scenes) catalogueScene(findStressScene(name), options);
    return 0;
  } catch (const std::exception& error) {
    std::cerr << "error: " << error.what() << "\n";
    return 2;
  }
}
