// The camera: world metres (y up) to pixels of the scene area (y down), the part of a frame
// between the heads-up strip above and the legend strip below, so no text ever covers a body.
// It is fitted once per run, from the scene's starting bodies or its [render] table, so frames of
// a run share one view.
#pragma once

#include <vector>

#include "impulse2d/body.h"
#include "impulse2d/render/render_settings.h"
#include "impulse2d/render/view.h"

namespace impulse2d::render {

/// A view of the world: image size, the world point at its centre and the scale.
struct Camera {
  int width = 800;             ///< pixels, of the scene area
  int height = 600;            ///< pixels, of the scene area
  double textSize = 15.0;      ///< pixels: the frame's text size (frameTextSize)
  int headsUpHeight = 0;       ///< pixels: the strip above the scene area
  int legendHeight = 0;        ///< pixels: the strip below it
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

/// The pixel size of a frame's text: settings.textPerFrameHeight of its height, at least
/// settings.minimumTextSize.
double frameTextSize(const RenderSettings& settings, int frameHeight);
/// Height of the heads-up strip (settings.headsUpLines lines; 0 with the overlay off) and of the
/// legend strip (two lines; 0 with it off) of a frame `frameHeight` pixels high.
double headsUpStripHeight(const RenderSettings& settings, int frameHeight);
double legendStripHeight(const RenderSettings& settings, int frameHeight);

/// The camera of a frame `width` × `height` pixels (strips included): the scene area between
/// the strips. A view with centre and scale shows the region its own width and height showed at
/// that scale, fitted into the area; what the view leaves unset is fitted so sceneBounds fills
/// the area inside settings.fitPadding.
Camera fitCamera(const std::vector<Body>& bodies, const ViewDef& view,
                 const RenderSettings& settings, int width, int height);
/// The same at the view's own size.
Camera fitCamera(const std::vector<Body>& bodies, const ViewDef& view,
                 const RenderSettings& settings);

}  // namespace impulse2d::render
