// The camera: world metres (y up) to image pixels (y down). It is fitted once per run, from the
// scene's starting bodies or its [render] table, so frames of a run share one view.
#pragma once

#include <vector>

#include "impulse2d/body.h"
#include "impulse2d/render/render_settings.h"
#include "impulse2d/render/view.h"

namespace impulse2d::render {

/// A view of the world: image size, the world point at its centre and the scale.
struct Camera {
  int width = 800;             ///< pixels
  int height = 600;            ///< pixels
  Vec2 centre = Vec2::Zero();  ///< m, world point at the image centre
  double scale = 50.0;         ///< pixels per metre

  /// World point (m) -> pixel coordinates (continuous; pixel (i, j) has centre (i + ½, j + ½)).
  Vec2 toPixels(const Vec2& world) const {
    return Vec2(0.5 * width + scale * (world.x() - centre.x()),
                0.5 * height - scale * (world.y() - centre.y()));
  }
  /// A world direction or displacement (m) -> pixels; y flips.
  Vec2 toPixelVector(const Vec2& world) const {
    return Vec2(scale * world.x(), -scale * world.y());
  }
  /// Pixel coordinates -> world point (m).
  Vec2 toWorld(const Vec2& pixels) const {
    return Vec2(centre.x() + (pixels.x() - 0.5 * width) / scale,
                centre.y() - (pixels.y() - 0.5 * height) / scale);
  }
};

/// The region a fitted camera shows: the dynamic bodies' bounds, grown to take in the static
/// bodies within settings.staticFitReach of them (all bodies' bounds when none is dynamic).
Aabb sceneBounds(const std::vector<Body>& bodies, const RenderSettings& settings);

/// The camera of a view: its size, and its centre and scale where the view gives them; what it
/// leaves unset is fitted so sceneBounds fills the image inside settings.fitPadding, below the
/// heads-up line when that overlay is on.
Camera fitCamera(const std::vector<Body>& bodies, const ViewDef& view,
                 const RenderSettings& settings);

}  // namespace impulse2d::render
