// The legend strip under a frame: what the colours and arrows of this frame mean, in words, and
// how long a force arrow is per newton. Two lines: the body states shown; then the arrow kinds
// shown, the friction gauge, and a sample arrow of a round force.
#pragma once

#include "impulse2d/render/camera.h"
#include "impulse2d/render/canvas.h"
#include "impulse2d/render/frame.h"
#include "impulse2d/render/render_settings.h"

namespace impulse2d::render {

/// Height in pixels of the legend strip of a frame `frameWidth` pixels wide: two text lines.
int legendHeight(const RenderSettings& settings, int frameWidth);

/// The 1, 2 or 5 times a power of ten nearest `force` (N, by ratio): the sample arrow's force.
double roundForce(double force);

/// The legend strip from pixel row `top` to the bottom of the canvas.
void drawLegend(Canvas& canvas, int top, const DrawnKinds& drawn, const ForceScale& forces,
                const Camera& camera, const RenderSettings& settings);

}  // namespace impulse2d::render
