// Fitting the camera to a scene, between the frame's text strips.
#include "impulse2d/render/camera.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "impulse2d/render/drawing.h"

namespace impulse2d::render {

namespace {

Aabb merged(const Aabb& a, const Aabb& b) {
  return Aabb{a.lower.cwiseMin(b.lower), a.upper.cwiseMax(b.upper)};
}

/// The part of `box` inside `limit`; `limit` itself when they do not overlap.
Aabb clipped(const Aabb& box, const Aabb& limit) {
  if (!box.overlaps(limit)) return limit;
  return Aabb{box.lower.cwiseMax(limit.lower), box.upper.cwiseMin(limit.upper)};
}

/// The world region the frame must show: the view's own window when it gives centre and scale,
/// else the scene's bounds (around the view's centre when it gives one).
Aabb shownRegion(const std::vector<Body>& bodies, const ViewDef& view,
                 const RenderSettings& settings) {
  const Aabb bounds = sceneBounds(bodies, settings);
  const Vec2 middle = view.centre.value_or(0.5 * (bounds.lower + bounds.upper));
  Vec2 half = 0.5 * (bounds.upper - bounds.lower);
  if (view.centre) half = (bounds.upper - *view.centre).cwiseMax(*view.centre - bounds.lower);
  if (view.scale) half = 0.5 * Vec2(view.width, view.height) / *view.scale;
  return Aabb{middle - half, middle + half};
}

}  // namespace

Aabb sceneBounds(const std::vector<Body>& bodies, const RenderSettings& settings) {
  if (bodies.empty()) return Aabb{Vec2(-1.0, -1.0), Vec2(1.0, 1.0)};
  const bool anyDynamic =
      std::any_of(bodies.begin(), bodies.end(), [](const Body& body) { return !body.isStatic(); });
  std::optional<Aabb> core;
  for (const Body& body : bodies) {
    if (anyDynamic && body.isStatic()) continue;
    core = core ? merged(*core, body.bounds) : body.bounds;
  }
  const Vec2 reach = settings.staticFitReach * (core->upper - core->lower).cwiseMax(1.0);
  const Aabb limit{core->lower - reach, core->upper + reach};
  Aabb bounds = *core;
  for (const Body& body : bodies) {
    if (body.isStatic() && body.bounds.overlaps(limit)) {
      bounds = merged(bounds, clipped(body.bounds, limit));
    }
  }
  return bounds;
}

double frameTextSize(const RenderSettings& settings, int frameHeight) {
  return std::max(settings.minimumTextSize, settings.textPerFrameHeight * frameHeight);
}

double headsUpStripHeight(const RenderSettings& settings, int frameHeight) {
  if (!settings.overlays.headsUp) return 0.0;
  const double size = frameTextSize(settings, frameHeight);
  return std::ceil(settings.headsUpLines * lineHeight(size) + 2.0 * settings.textMargin * size);
}

double legendStripHeight(const RenderSettings& settings, int frameHeight) {
  if (!settings.overlays.legend) return 0.0;
  const double size = frameTextSize(settings, frameHeight);
  return std::ceil(2.0 * lineHeight(size) + 3.0 * settings.textMargin * size);
}

Camera fitCamera(const std::vector<Body>& bodies, const ViewDef& view,
                 const RenderSettings& settings, int width, int height) {
  Camera camera;
  camera.textSize = frameTextSize(settings, height);
  camera.width = width;
  camera.headsUpHeight = int(headsUpStripHeight(settings, height));
  camera.legendHeight = int(legendStripHeight(settings, height));
  camera.height = std::max(1, height - camera.headsUpHeight - camera.legendHeight);
  const Aabb region = shownRegion(bodies, view, settings);
  const bool fixedWindow = view.centre && view.scale;
  const double padding = fixedWindow ? 0.0 : settings.fitPadding * std::min(width, camera.height);
  const double usableWidth = std::max(1.0, camera.width - 2.0 * padding);
  const double usableHeight = std::max(1.0, camera.height - 2.0 * padding);
  const Vec2 extent = (region.upper - region.lower).cwiseMax(1e-6);
  camera.scale = std::min(usableWidth / extent.x(), usableHeight / extent.y());
  camera.centre = 0.5 * (region.lower + region.upper);
  return camera;
}

Camera fitCamera(const std::vector<Body>& bodies, const ViewDef& view,
                 const RenderSettings& settings) {
  return fitCamera(bodies, view, settings, view.width, view.height);
}

}  // namespace impulse2d::render
