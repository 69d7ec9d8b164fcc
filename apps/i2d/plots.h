// --plots DIR: gnuplot PNGs of a run's figures against time (kinetic, potential and total energy,
// contact points, largest penetration), one curve per panel for `compare`; and for a traced step
// the velocity error each solver event removes. The data and the gnuplot script stay beside the
// PNGs, so a plot can be redrawn by hand.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "impulse2d/render/viewer.h"
#include "run_figures.h"

namespace i2d {

/// One curve's worth of figures: a run, or one panel of a comparison.
struct PlotSeries {
  std::string label;
  std::vector<StepFigures> figures;
};

/// Creates DIR (its parent must exist) and checks it is writable; throws RunFailure naming the
/// directory before a run when it is not.
void preparePlotDirectory(const std::string& directory);

/// DIR/NAME_{kinetic,potential,total,contacts,penetration}.png; returns the summary lines.
std::vector<std::string> writeRunPlots(const std::string& directory, const std::string& name,
                                       const std::vector<PlotSeries>& series);

/// The viewer page's plots, gnuplot SVGs beside the frames: DIR/PREFIX_energy.svg (kinetic,
/// potential and total energy; for a comparison each panel's total) and, when `withForces`,
/// DIR/PREFIX_forces.svg (the applied force against the friction force that answers it). Their
/// axes span fixed parts of the image, given in each ViewerPlot for the page's cursor.
std::vector<impulse2d::render::ViewerPlot> writeViewerPlots(const std::filesystem::path& directory,
                                                            const std::string& prefix,
                                                            const std::vector<PlotSeries>& series,
                                                            bool withForces);

/// DIR/NAME_stepNNNNN_velocity_error.png: |Δv wanted| at each velocity event of the step,
/// against the event's number, marked by iteration; returns the summary line.
std::string writeTracePlot(const std::string& directory, const std::string& name, long step,
                           const EventLog& events);

}  // namespace i2d
