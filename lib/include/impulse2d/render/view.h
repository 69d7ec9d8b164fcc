// How frames look at a scene, as its file's [render] table says: plain data, read by the scene
// loader and used by the camera. Unset fields are fitted to the bodies.
#pragma once

#include <optional>

#include "impulse2d/math.h"

namespace impulse2d {

/// A scene's view: the image size, and the centre and scale when the file gives them.
struct ViewDef {
  int width = 800;              ///< pixels
  int height = 600;             ///< pixels
  std::optional<Vec2> centre;   ///< m, world point at the image centre
  std::optional<double> scale;  ///< pixels per metre
};

}  // namespace impulse2d
