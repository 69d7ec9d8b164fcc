// Fitting the camera to a scene.
#include "impulse2d/render/camera.h"

#include <algorithm>
#include <optional>

#include "impulse2d/render/frame.h"

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

Camera fitCamera(const std::vector<Body>& bodies, const ViewDef& view,
                 const RenderSettings& settings) {
  Camera camera;
  camera.width = view.width;
  camera.height = view.height;
  const Aabb bounds = sceneBounds(bodies, settings);
  // Room for the heads-up lines along the top.
  const double top =
      settings.overlays.headsUp ? settings.headsUpLines * headsUpHeight(settings, view.width) : 0.0;
  const double padding = settings.fitPadding * std::min(view.width, view.height);
  const double usableWidth = std::max(1.0, view.width - 2.0 * padding);
  const double usableHeight = std::max(1.0, view.height - 2.0 * padding - top);
  const Vec2 extent = (bounds.upper - bounds.lower).cwiseMax(1e-6);
  camera.scale = view.scale.value_or(std::min(usableWidth / extent.x(), usableHeight / extent.y()));
  // The fitted centre sits half the heads-up bar above the bounds' centre, so the scene is
  // centred in the part of the image below the bar.
  const Vec2 middle = 0.5 * (bounds.lower + bounds.upper);
  camera.centre = view.centre.value_or(Vec2(middle.x(), middle.y() + 0.5 * top / camera.scale));
  return camera;
}

}  // namespace impulse2d::render
