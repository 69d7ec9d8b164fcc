// How frames look at a scene, as its file's [render] table says: plain data, read by the scene
// loader and used by the camera. Unset fields are fitted to the bodies over the whole run.
#pragma once

#include <optional>
#include <string>

#include "impulse2d/math.h"

namespace impulse2d {

/// A scene's view: the image size, and what the file fixes of the camera. With none of centre,
/// scale, window and follow the camera fits every dynamic body over the whole run.
struct ViewDef {
  int width = 800;              ///< pixels
  int height = 600;             ///< pixels
  std::optional<Vec2> centre;   ///< m, world point at the image centre
  std::optional<double> scale;  ///< pixels per metre
  /// m: the world rectangle shown ([render] view = [[x0, y0], [x1, y1]]), fitted into the frame
  /// whole; it replaces centre and scale.
  std::optional<Aabb> window;
  /// The name of the body the view's centre follows, frame by frame, at one scale for the run.
  std::optional<std::string> follow;
  /// The fitted (or given) scale times this: 2 shows half the width, about the same centre.
  double zoom = 1.0;

  /// True when the scene fixes what is shown (a window, or centre and scale): the camera does
  /// not fit the run, and a body may leave the picture.
  bool fixed() const { return window.has_value() || (centre && scale); }
};

}  // namespace impulse2d
