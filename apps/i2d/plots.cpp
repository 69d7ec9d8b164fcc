// Plots through gnuplot: a data file, a script, one PNG per figure.
#include "plots.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>

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

void runGnuplot(const fs::path& script) {
  const std::string command = "gnuplot " + shellQuoted(script.string());
  if (std::system(command.c_str()) != 0) {
    throw RunFailure("gnuplot failed (is it installed? scripts/setup installs it): " + command);
  }
}

/// One block per series (gnuplot's `index`): step, time, kinetic, potential, total, contacts,
/// penetration.
fs::path writeFigureData(const fs::path& path, const std::vector<PlotSeries>& series) {
  std::ofstream data(path);
  data << "# step time_s kinetic_J potential_J total_J contact_points largest_penetration_m\n";
  data.precision(10);
  for (const PlotSeries& run : series) {
    data << "# " << run.label << "\n";
    for (const StepFigures& f : run.figures) {
      data << f.step << ' ' << f.time << ' ' << f.kinetic << ' ' << f.potential << ' '
           << f.kinetic + f.potential << ' ' << f.contacts << ' ' << f.penetration << '\n';
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

}  // namespace

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
