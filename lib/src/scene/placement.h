// Placing a body at rest on a named surface ([[body]] on = "ramp"): the scene file says which body
// it rests on instead of a position computed by hand, and the reader places it once every body
// is read.
#pragma once

#include <string>
#include <vector>

#include <toml++/toml.h>

#include "impulse2d/scene/scene.h"

namespace impulse2d::scene_file {

/// One body that rests on another: read from its [[body]] table, placed after all bodies.
struct Placement {
  size_t body = 0;                  ///< index of the placed body in Scene::bodies
  std::string support;              ///< name of the body it rests on
  double offset = 0.0;              ///< m along the support's top face from its middle, +x-ward
  double turn = 0.0;                ///< rad, the body's angle from the face's slope
  toml::source_region where;        ///< the `on` value, for errors
  toml::source_region offsetWhere;  ///< the `offset` value (or the `on` value), for errors
};

/// The top face of a flat-faced body: the face whose outward normal points most nearly up (+y).
struct TopFace {
  Vec2 middle;          ///< m, world frame
  Vec2 along;           ///< unit, along the face with x increasing
  Vec2 normal;          ///< unit, outward (up)
  double length = 0.0;  ///< m
};

/// The top face of a box or polygon placed as `body` says.
TopFace topFace(const BodyDef& body);

/// Places each body on its support's top face, turned to the face's slope (plus its own turn),
/// its lowest point touching the face, its centre over the point `offset` along the face from
/// the face's middle. Supports placed on others are placed first. Throws a located SceneError
/// for an unknown name, a cycle, a circle as support or an offset off the face.
void placeOnSurfaces(Scene& scene, const std::vector<Placement>& placements);

}  // namespace impulse2d::scene_file
