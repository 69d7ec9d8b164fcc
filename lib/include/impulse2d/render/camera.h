// The camera: world metres (y up) to pixels of the scene area (y down), the part of a frame
// between the heads-up strip above and the legend strip below, so no text ever covers a body.
// It is fitted once per run (RunCamera): to every dynamic body over all the states a run records,
// or as the scene's [render] table fixes it, so the frames of a run share one scale.
#pragma once

#include <optional>
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
  /// The world rectangle (m) the scene area shows.
  Aabb shown() const {
    const Vec2 half(0.5 * width / scale, 0.5 * height / scale);
    return Aabb{centre - half, centre + half};
  }
  /// The same view drawn `factor` times as large (a sheet's cell), with text of `newTextSize`.
  Camera resized(double factor, double newTextSize) const;
};

/// The smallest box holding both.
Aabb merged(const Aabb& a, const Aabb& b);

/// The region a fitted camera shows: the dynamic bodies' bounds (or `dynamicExtent`, the region
/// they sweep over a run, when given), grown to take in the static bodies within
/// settings.staticFitReach of them (all bodies' bounds when none is dynamic).
Aabb sceneBounds(const std::vector<Body>& bodies, const RenderSettings& settings,
                 const std::optional<Aabb>& dynamicExtent = std::nullopt);

/// The pixel size of a frame's text: settings.textPerFrameHeight of its height, at least
/// settings.minimumTextSize.
double frameTextSize(const RenderSettings& settings, int frameHeight);
/// Height of the heads-up strip (settings.headsUpLines lines; 0 with the overlay off) and of the
/// legend strip (two lines; 0 with it off) of a frame `frameHeight` pixels high.
double headsUpStripHeight(const RenderSettings& settings, int frameHeight);
double legendStripHeight(const RenderSettings& settings, int frameHeight);

/// The cameras of a run's frames, `width` × `height` pixels each (strips included), one scale
/// for the run. Every state the run records is added first; then each frame asks for its camera.
/// What the view leaves unset is fitted so the region the dynamic bodies sweep over the states
/// (with the static bodies they touch, sceneBounds) fills the scene area inside
/// settings.fitPadding. A view with centre and scale shows the region its own width and height
/// showed at that scale; a window shows that rectangle; a followed body is at the centre of every
/// frame, at the scale that fits the first state; zoom multiplies the scale.
class RunCamera {
 public:
  /// A camera for frames `width` × `height` pixels that shows `view`; no state added yet.
  RunCamera(const ViewDef& view, const RenderSettings& settings, int width, int height);
  /// Takes in one recorded state's bodies (the first gives the static bodies). Throws
  /// std::invalid_argument when the view follows a body these bodies lack.
  void add(const std::vector<Body>& bodies);
  /// The camera of the frame of `bodies`, a state added before.
  Camera cameraFor(const std::vector<Body>& bodies) const;
  /// The union of the world rectangles the frames show (m).
  Aabb shown() const;
  /// The view it fits.
  const ViewDef& view() const { return view_; }

 private:
  Camera fitted() const;

  ViewDef view_;
  RenderSettings settings_;
  int width_;
  int height_;
  int followed_ = -1;                    ///< index of the followed body
  std::vector<Body> first_;              ///< the first state's bodies
  std::optional<Aabb> swept_;            ///< the dynamic bodies' bounds over every state
  std::optional<Aabb> followedCentres_;  ///< where the followed body's centre went
};

/// The camera of a frame of these bodies alone, `width` × `height` pixels (a RunCamera of one
/// state).
Camera fitCamera(const std::vector<Body>& bodies, const ViewDef& view,
                 const RenderSettings& settings, int width, int height);
/// The same at the view's own size.
Camera fitCamera(const std::vector<Body>& bodies, const ViewDef& view,
                 const RenderSettings& settings);

}  // namespace impulse2d::render
