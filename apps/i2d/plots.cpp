// Plots through gnuplot: a data file, a script, one PNG per figure.
#include "plots.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>

#include "failures.h"

namespace i2d {
namespace {

namespace fs = std::filesystem;

std::string shellQuoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

/// Text inside a gnuplot double-quoted string.
std::string gnuplotText(const std::string& text) {
  std::string escaped;
  for (char c : text)
    escaped += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return escaped;
}

void writeOrFail(std::ofstream& file, const fs::path& path) {
  file.close();
  if (!file) throw RunFailure("cannot write '" + path.string() + "'");
}

/// Runs gnuplot on the script. Its messages go to SCRIPT.log: a plot of a run too short to have
/// a range draws with a warning, which is no concern of the user's, so the log is kept and its
/// first line shown only when gnuplot fails.
void runGnuplot(const fs::path& script) {
  const fs::path log = script.string() + ".log";
  const std::string command =
      "gnuplot " + shellQuoted(script.string()) + " 2>" + shellQuoted(log.string());
  if (std::system(command.c_str()) != 0) {
    std::ifstream messages(log);
    std::string first;
    std::getline(messages, first);
    throw RunFailure("gnuplot failed (is it installed? scripts/setup installs it): " + command +
                     (first.empty() ? "" : ": " + first));
  }
  std::error_code error;
  fs::remove(log, error);
}

/// One block per series (gnuplot's `index`): step, time, kinetic, potential, total, contacts,
/// penetration.
fs::path writeFigureData(const fs::path& path, const std::vector<PlotSeries>& series) {
  std::ofstream data(path);
  data << "# step time_s kinetic_J potential_J total_J contact_points largest_penetration_m "
          "applied_force_N friction_force_N\n";
  data.precision(10);
  for (const PlotSeries& run : series) {
    data << "# " << run.label << "\n";
    for (const StepFigures& f : run.figures) {
      data << f.step << ' ' << f.time << ' ' << f.kinetic << ' ' << f.potential << ' '
           << f.kinetic + f.potential << ' ' << f.contacts << ' ' << f.penetration << ' '
           << f.appliedForce << ' ' << f.frictionForce << '\n';
    }
    data << "\n\n";
  }
  writeOrFail(data, path);
  return path;
}

struct Figure {
  const char* file;
  const char* title;
  const char* axis;
  int column;
};

const Figure kFigures[] = {
    {"kinetic", "kinetic energy", "kinetic energy (J)", 3},
    {"potential", "potential energy", "potential energy (J)", 4},
    {"total", "total energy (kinetic + potential)", "total energy (J)", 5},
    {"contacts", "contact points", "contact points", 6},
    {"penetration", "largest penetration", "largest penetration (m)", 7},
};

/// Where the viewer plots' axes lie, as fractions of the image (gnuplot's "screen" coordinates):
/// the page's cursor runs from kPlotLeft to kPlotRight, and from kPlotTop down to kPlotBottom.
constexpr double kPlotLeft = 0.12;
constexpr double kPlotRight = 0.96;
constexpr double kPlotTop = 0.90;
constexpr double kPlotBottom = 0.12;

/// One viewer plot's script: the SVG terminal, fixed margins, time from 0 to the last step.
void startViewerPlot(std::ofstream& script, const fs::path& svg, double timeMax,
                     const std::string& title, const std::string& axis) {
  script << "set output \"" << gnuplotText(svg.string()) << "\"\nset title \"" << gnuplotText(title)
         << "\"\nset ylabel \"" << gnuplotText(axis) << "\"\nset xrange [0:" << timeMax
         << "]\nplot ";
}

}  // namespace

std::vector<impulse2d::render::ViewerPlot> writeViewerPlots(const fs::path& directory,
                                                            const std::string& prefix,
                                                            const std::vector<PlotSeries>& series,
                                                            bool withForces) {
  const fs::path data = writeFigureData(directory / (prefix + "_plots.dat"), series);
  const fs::path scriptPath = directory / (prefix + "_plots.gp");
  double timeMax = 0.0;
  for (const PlotSeries& run : series) {
    if (!run.figures.empty()) timeMax = std::max(timeMax, run.figures.back().time);
  }
  if (!(timeMax > 0.0)) timeMax = 1.0;
  std::ofstream script(scriptPath);
  script << "set terminal svg noenhanced size 640,300 font \"DejaVu Sans,11\"\nset grid\n"
         << "set key top left\nset xlabel \"time (s)\"\n"
         << "set lmargin at screen " << kPlotLeft << "\nset rmargin at screen " << kPlotRight
         << "\nset tmargin at screen " << kPlotTop << "\nset bmargin at screen " << kPlotBottom
         << "\n";
  std::vector<impulse2d::render::ViewerPlot> plots;
  const auto add = [&](const std::string& file) {
    plots.push_back({file, 0.0, timeMax, kPlotLeft, kPlotRight});
  };
  const std::string dataText = "\"" + gnuplotText(data.string()) + "\"";
  startViewerPlot(script, directory / (prefix + "_energy.svg"), timeMax, prefix + ": energy",
                  "energy (J)");
  if (series.size() == 1) {
    script << dataText << " using 2:3 with lines lw 2 title \"kinetic\", " << dataText
           << " using 2:4 with lines lw 2 title \"potential\", " << dataText
           << " using 2:5 with lines lw 2 title \"total\"\n";
  } else {
    for (std::size_t i = 0; i < series.size(); ++i) {
      script << (i ? ", " : "") << dataText << " index " << i
             << " using 2:5 with lines lw 2 title \"" << gnuplotText(series[i].label + ": total")
             << "\"";
    }
    script << "\n";
  }
  add(prefix + "_energy.svg");
  if (withForces) {
    startViewerPlot(script, directory / (prefix + "_forces.svg"), timeMax,
                    prefix + ": applied force and the friction that answers it", "force (N)");
    script << dataText << " index 0 using 2:8 with lines lw 2 title \"applied force\", " << dataText
           << " index 0 using 2:9 with lines lw 2 title \"friction force\"\n";
    add(prefix + "_forces.svg");
  }
  writeOrFail(script, scriptPath);
  runGnuplot(scriptPath);
  return plots;
}

void preparePlotDirectory(const std::string& directory) {
  const fs::path path(directory);
  const fs::path parent =
      path.has_filename() ? path.parent_path() : path.parent_path().parent_path();
  if (!parent.empty() && !fs::is_directory(parent)) {
    throw RunFailure("cannot create plot directory '" + directory + "': '" + parent.string() +
                     "' is not an existing directory");
  }
  std::error_code error;
  fs::create_directories(path, error);
  const fs::path probe = path / ".plots.probe.tmp";
  if (error || !std::ofstream(probe)) {
    throw RunFailure("cannot write plots to '" + directory + "': the directory is not writable");
  }
  fs::remove(probe, error);
}

std::vector<std::string> writeRunPlots(const std::string& directory, const std::string& name,
                                       const std::vector<PlotSeries>& series) {
  const fs::path root(directory);
  const fs::path data = writeFigureData(root / (name + "_figures.dat"), series);
  const fs::path scriptPath = root / (name + "_plots.gp");
  std::ofstream script(scriptPath);
  script << "# Redraw with: gnuplot " << scriptPath.filename().string() << " (from " << directory
         << ")\nset terminal pngcairo noenhanced size 800,480 font \"sans,11\"\nset grid\n"
         << "set key outside bottom center horizontal\nset xlabel \"time (s)\"\n";
  std::vector<std::string> lines;
  for (const Figure& figure : kFigures) {
    const fs::path png = root / (name + "_" + figure.file + ".png");
    script << "set output \"" << gnuplotText(png.string()) << "\"\nset title \""
           << gnuplotText(name + ": " + figure.title) << "\"\nset ylabel \"" << figure.axis
           << "\"\nplot ";
    for (std::size_t i = 0; i < series.size(); ++i) {
      script << (i ? ", " : "") << "\"" << gnuplotText(data.string()) << "\" index " << i
             << " using 2:" << figure.column << " with lines lw 2 title \""
             << gnuplotText(series[i].label) << "\"";
    }
    script << "\n";
    lines.push_back("plot         " + png.string());
  }
  writeOrFail(script, scriptPath);
  runGnuplot(scriptPath);
  return lines;
}

std::string writeTracePlot(const std::string& directory, const std::string& name, long step,
                           const EventLog& events) {
  char stem[64];
  std::snprintf(stem, sizeof stem, "_step%05ld_velocity_error", step);
  const fs::path root(directory);
  const fs::path data = root / (name + stem + ".dat");
  std::ofstream table(data);
  table << "# event iteration velocity_error_m_per_s\n";
  table.precision(10);
  for (std::size_t i = 0; i < events.velocityErrors().size(); ++i) {
    table << i << ' ' << events.iterations()[i] << ' ' << events.velocityErrors()[i] << '\n';
  }
  writeOrFail(table, data);
  const fs::path png = root / (name + stem + ".png");
  const fs::path scriptPath = root / (name + stem + ".gp");
  std::ofstream script(scriptPath);
  script
      << "set terminal pngcairo noenhanced size 800,480 font \"sans,11\"\nset grid\nset output \""
      << gnuplotText(png.string()) << "\"\nset title \""
      << gnuplotText(name + ": step " + std::to_string(step) +
                     ", velocity error each solver event removes")
      << "\"\nset xlabel \"solver event (colour: iteration)\"\n"
      << "set ylabel \"|velocity change wanted| (m/s)\"\nset logscale y\nunset colorbox\n"
      << "plot \"" << gnuplotText(data.string())
      << "\" using 1:($3 > 0 ? $3 : 1/0):2 with linespoints pt 7 ps 0.8 lc palette notitle\n";
  writeOrFail(script, scriptPath);
  runGnuplot(scriptPath);
  return "plot         " + png.string();
}

}  // namespace i2d
