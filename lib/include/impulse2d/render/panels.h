// Comparison panels: frames of the same scene run by different solvers or settings, laid out in
// a grid that fits a 16:9 slide, each under a bar with its label (`i2d compare`).
#pragma once

#include <string>
#include <vector>

#include "impulse2d/render/frame.h"
#include "impulse2d/render/render_settings.h"

namespace impulse2d::render {

/// One panel of a comparison: a frame and its label.
struct Panel {
  const Frame* frame = nullptr;  ///< the frame shown, owned by the caller
  std::string label;             ///< drawn in a bar above the frame, e.g. the solver's name
};

/// Height of the label bar above each panel whose frames use text of `textSize`.
int panelLabelHeight(const RenderSettings& settings, double textSize);

/// Columns of the grid of `count` panels of width × height (label bar included) whose panels
/// cover the most of a settings.slideAspect slide when the grid is scaled to fit it.
int panelColumns(int count, int width, int height, const RenderSettings& settings);

/// The panels in that grid, left to right and top to bottom, settings.spacing apart. All panels
/// are the size of the first. The frame's scene area is the whole grid, so a sheet shows every
/// panel.
Frame composePanels(const std::vector<Panel>& panels, const RenderSettings& settings);

}  // namespace impulse2d::render
