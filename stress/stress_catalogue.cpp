// stress_catalogue: finds every method's breaking point on every stress scene and writes, per
// scene, its Markdown table, its chart data and the contact sheet of each failure. scripts/
// stability runs it and assembles docs/stability.md.
//   stress_catalogue --out DIR [--frames DIR] [--scenes a,b,...]
//   stress_catalogue --summary-header       the header of the summary table
#include <chrono>
#include <cmath>
#include <cstdio>
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
                              const Method& method, double knob) {
  const Scene scene = sceneFor(stress, method, knob);
  const render::RenderSettings settings;
  const render::Camera camera = render::fitCamera(buildBodies(scene), ViewDef{}, settings);
  render::FrameRenderer renderer(camera, stress.name + " (" + method.label + ")", settings);
  const int every = std::max(1, scene.steps / (kFramesPerFailure - 1));
  render::FrameWriter writer(root, stress.name, every, stress.name + "_" + slug(method.label),
                             settings);
  runStress(stress, method, knob, [&](const Simulation& simulation) {
    if (writer.wants(simulation.stepCount()))
      writer.write(simulation.stepCount(), renderer.draw(simulation));
  });
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

std::string methodRow(const StressScene& stress, const Method& method, const BreakingPoint& point,
                      const std::string& sheet) {
  const Knob& knob = stress.knob;
  std::string held =
      point.verdict == Verdict::FailsAtEasiest ? "—" : formatKnob(knob, point.lastHeld);
  std::string failed = point.verdict == Verdict::HoldsThroughout
                           ? "none to " + formatKnob(knob, point.hardest)
                           : formatKnob(knob, point.firstFailed);
  std::string figure = "—";
  for (const Sample& sample : point.samples) {
    if (point.verdict != Verdict::HoldsThroughout && sample.knob == point.firstFailed) {
      figure = sample.outcome.stopped.empty() ? formatNumber(sample.outcome.measure) : "stopped";
    }
  }
  const std::string note = failureNote(point);
  return "| " + method.label + " | " + held + " | " + failed + " | " + figure + " | " +
         std::to_string(point.samples.size()) + " | " + (sheet.empty() ? "—" : "`" + sheet + "`") +
         (note.empty() ? "" : " — " + note) + " |\n";
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
        << stress.criterion.byEye << ".\n\n";
  for (const Intervention& intervention : stress.interventions) {
    table << "**Mid-run:** at step " << intervention.step << ", " << intervention.description
          << ".\n\n";
  }
  for (const auto& [solver, hardest] : stress.hardestFor) {
    table << "**" << solver << "** is searched only to " << formatKnob(knob, hardest)
          << ": beyond, its runs cost more than the catalogue's time budget.\n\n";
  }
  table << "| method | holds at | first fails at | figure there | runs | contact sheet |\n"
        << "| --- | --- | --- | --- | --- | --- |\n";
  row << "| " << stress.name << " (" << stress.knob.name << ") |";
  std::map<std::string, std::string> cells;
  for (const Method& method : methodsOf(stress)) {
    const auto begin = std::chrono::steady_clock::now();
    const BreakingPoint point = findBreakingPoint(stress, method);
    std::string sheet;
    if (!options.frames.empty() && point.verdict != Verdict::HoldsThroughout) {
      sheet = writeFailureSheet(options.frames, stress, method, point.firstFailed);
    }
    table << methodRow(stress, method, point, sheet);
    writeChartBlock(data, stress, method, point);
    writeSampleRows(csv, stress, method, point);
    cells[method.label] = summaryCell(stress, point);
    std::cerr << stress.name << " / " << method.label << ": " << summaryCell(stress, point) << " ("
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count()
              << " s)\n";
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

int main(int argc, char** argv) {
  try {
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
