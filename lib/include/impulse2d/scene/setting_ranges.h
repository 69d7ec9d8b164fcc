// The valid range of every numeric setting a scene file or a --set may give, as each setting's
// declaration states it (settings.h), so a value outside it is refused where it is written. Upper
// bounds on counts (substeps, caps, iterations) keep a run from taking hours or exhausting memory.
#pragma once

#include <optional>
#include <string>

#include "impulse2d/settings.h"

namespace impulse2d {

/// The range of `key` in [world] (scope "world"), the scene's `steps` (scope "world"), or the
/// [solver] table of the solver `scope` names; nullopt for a key without one (booleans, gravity).
std::optional<SettingRange> findSettingRange(const std::string& scope, const std::string& key);

/// The most dynamic bodies times steps a run may take (about minutes of stepping), and the most
/// pixels of one frame (a 16384 × 4096 image of 4 bytes a pixel is 256 MiB).
inline constexpr double kMostBodySteps = 1e8;
inline constexpr long kMostFramePixels = 16384L * 4096L;
inline constexpr int kMostFrameSide = 16384;

/// Empty when the scene's steps times its dynamic bodies times its substeps (the world's times
/// soft step's) fit kMostBodySteps; else the message refusing the run, naming the product and the
/// limit.
std::string checkRunSize(long steps, long dynamicBodies, int substeps);

/// Empty when `panels` frames of width × height side by side fit kMostFramePixels; else the
/// message refusing them, naming width × height and the limit. Checked where the scene and the
/// options are read, before anything is drawn.
std::string checkFramePixels(int width, int height, int panels);

}  // namespace impulse2d
