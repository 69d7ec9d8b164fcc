// Side-by-side panels: frames of the same scene run by different solvers, composed into one image
// with each panel labelled (`i2d compare`).
#pragma once

#include <string>
#include <vector>

#include "impulse2d/render/canvas.h"
#include "impulse2d/render/render_settings.h"

namespace impulse2d::render {

/// One labelled frame of a side-by-side comparison.
struct Panel {
  /// the frame shown, owned by the caller
  const Canvas* frame = nullptr;
  std::string label;  ///< drawn in a bar above the frame, e.g. the solver's name
};

/// Height of the label bar above each panel.
int panelLabelHeight(const RenderSettings& settings);

/// The panels left to right, settings.spacing apart, each under its label bar; panels of
/// different heights are top-aligned.
Canvas composePanels(const std::vector<Panel>& panels, const RenderSettings& settings);

}  // namespace impulse2d::render
