// Where i2d finds the SCENE it is given: a scene file by its path, or one of the shipped lecture
// scenes by its name (`i2d run resting_box`), from the scene directory installed beside i2d.
#pragma once

#include <string>

namespace i2d {

/// The path to read for SCENE: SCENE itself when it names a file or holds a '/', otherwise
/// SCENE or SCENE.toml in the installed scene directory when there is one, otherwise SCENE (so
/// reading it reports the missing file by the name given).
std::string findScene(const std::string& scene);

}  // namespace i2d
