// Fitting the camera to a scene, between the frame's text strips.
#include "impulse2d/render/camera.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "impulse2d/render/marks.h"

namespace impulse2d::render {

namespace {

/// The part of `box` inside `limit`; `limit` itself when they do not overlap.
Aabb clipped(const Aabb& box, const Aabb& limit) {
  if (!box.overlaps(limit)) return limit;
  return Aabb{box.lower.cwiseMax(limit.lower), box.upper.cwiseMin(limit.upper)};
}

/// The world region the frame must show: the view's window, or its own width and height at its
/// scale, or else the bounds (around the view's centre when it gives one).
Aabb shownRegion(const Aabb& bounds, const ViewDef& view) {
  if (view.window) return *view.window;
  const Vec2 middle = view.centre.value_or(0.5 * (bounds.lower + bounds.upper));
  Vec2 half = 0.5 * (bounds.upper - bounds.lower);
  if (view.centre) half = (bounds.upper - *view.centre).cwiseMax(*view.centre - bounds.lower);
  if (view.scale) half = 0.5 * Vec2(view.width, view.height) / *view.scale;
  return Aabb{middle - half, middle + half};
}

}  // namespace

Aabb merged(const Aabb& a, const Aabb& b) {
  return Aabb{a.lower.cwiseMin(b.lower), a.upper.cwiseMax(b.upper)};
}

Camera Camera::resized(double factor, double newTextSize) const {
  Camera camera = *this;
  camera.width = std::max(1, int(std::lround(factor * width)));
  camera.height = std::max(1, int(std::lround(factor * height)));
  camera.scale = factor * scale;
  camera.textSize = newTextSize;
  camera.headsUpHeight = 0;
  camera.legendHeight = 0;
  return camera;
}

Aabb sceneBounds(const std::vector<Body>& bodies, const RenderSettings& settings,
                 const std::optional<Aabb>& dynamicExtent) {
  if (bodies.empty() && !dynamicExtent) return Aabb{Vec2(-1.0, -1.0), Vec2(1.0, 1.0)};
  const bool anyDynamic =
      dynamicExtent ||
      std::any_of(bodies.begin(), bodies.end(), [](const Body& body) { return !body.isStatic(); });
  std::optional<Aabb> core = dynamicExtent;
  for (const Body& body : bodies) {
    if (dynamicExtent || (anyDynamic && body.isStatic())) continue;
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

RunCamera::RunCamera(const ViewDef& view, const RenderSettings& settings, int width, int height)
    : view_(view), settings_(settings), width_(width), height_(height) {}

void RunCamera::add(const std::vector<Body>& bodies) {
  if (first_.empty()) {
    first_ = bodies;
    if (view_.follow) {
      const auto found = std::find_if(bodies.begin(), bodies.end(),
                                      [&](const Body& body) { return body.name == *view_.follow; });
      if (found == bodies.end()) {
        throw std::invalid_argument("the view follows body '" + *view_.follow +
                                    "', which the scene does not have");
      }
      followed_ = int(found - bodies.begin());
    }
  }
  for (const Body& body : bodies) {
    if (!body.isStatic()) swept_ = swept_ ? merged(*swept_, body.bounds) : body.bounds;
  }
  if (followed_ >= 0 && std::size_t(followed_) < bodies.size()) {
    const Vec2& centre = bodies[std::size_t(followed_)].position;
    const Aabb point{centre, centre};
    followedCentres_ = followedCentres_ ? merged(*followedCentres_, point) : point;
  }
}

Camera RunCamera::fitted() const {
  Camera camera;
  camera.textSize = frameTextSize(settings_, height_);
  camera.width = width_;
  camera.headsUpHeight = int(headsUpStripHeight(settings_, height_));
  camera.legendHeight = int(legendStripHeight(settings_, height_));
  camera.height = std::max(1, height_ - camera.headsUpHeight - camera.legendHeight);
  // A followed body sets the scale by where the run starts, not by how far it goes.
  const Aabb bounds =
      sceneBounds(first_, settings_, followed_ >= 0 ? std::optional<Aabb>() : swept_);
  const Aabb region = shownRegion(bounds, view_);
  const double padding =
      view_.fixed() ? 0.0 : settings_.fitPadding * std::min(width_, camera.height);
  const double usableWidth = std::max(1.0, camera.width - 2.0 * padding);
  const double usableHeight = std::max(1.0, camera.height - 2.0 * padding);
  const Vec2 extent = (region.upper - region.lower).cwiseMax(1e-6);
  camera.scale = view_.zoom * std::min(usableWidth / extent.x(), usableHeight / extent.y());
  camera.centre = 0.5 * (region.lower + region.upper);
  return camera;
}

Camera RunCamera::cameraFor(const std::vector<Body>& bodies) const {
  Camera camera = fitted();
  if (followed_ >= 0 && std::size_t(followed_) < bodies.size()) {
    camera.centre = bodies[std::size_t(followed_)].position;
  }
  return camera;
}

Aabb RunCamera::shown() const {
  const Aabb one = fitted().shown();
  if (!followedCentres_) return one;
  const Vec2 half = 0.5 * (one.upper - one.lower);
  return Aabb{followedCentres_->lower - half, followedCentres_->upper + half};
}

Camera fitCamera(const std::vector<Body>& bodies, const ViewDef& view,
                 const RenderSettings& settings, int width, int height) {
  RunCamera run(view, settings, width, height);
  run.add(bodies);
  return run.cameraFor(bodies);
}

Camera fitCamera(const std::vector<Body>& bodies, const ViewDef& view,
                 const RenderSettings& settings) {
  return fitCamera(bodies, view, settings, view.width, view.height);
}

}  // namespace impulse2d::render
