// The legend strip under a frame: what the colours and arrows of this frame mean, each kind named
// once and only when it was drawn, and the force scale as a bar of a round force.
#pragma once

#include <string>
#include <vector>

#include "impulse2d/render/camera.h"
#include "impulse2d/render/drawing.h"
#include "impulse2d/render/frame.h"
#include "impulse2d/render/render_settings.h"

namespace impulse2d::render {

/// The 1, 2 or 5 times a power of ten nearest `force` (N, by ratio): the scale bar's force.
double roundForce(double force);

/// The words of the legend's entries for what was drawn, in the order they appear.
std::vector<std::string> legendWords(const DrawnKinds& drawn, const ForceScale& forces,
                                     const Camera& camera, const RenderSettings& settings);

/// The legend strip from pixel row `top` to `bottom`, `width` wide: the entries flowed over two
/// lines, drawn smaller (down to settings.minimumTextSize) when they would not fit.
void drawLegend(Drawing& drawing, double top, int width, int bottom, const DrawnKinds& drawn,
                const ForceScale& forces, const Camera& camera, const RenderSettings& settings);

}  // namespace impulse2d::render
