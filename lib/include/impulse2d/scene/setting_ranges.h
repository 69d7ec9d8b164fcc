// The valid range of every numeric setting a scene file or a --set may give: one table, read when
// a value is set, so a value outside it is refused where it is written. Upper bounds on counts
// (substeps, caps, iterations) keep a run from taking hours or exhausting memory.
#pragma once

#include <optional>
#include <string>

namespace impulse2d {

/// The values a setting may take: from lowest to highest, each end included or not.
struct SettingRange {
  double lowest = 0.0;         ///< the lower end
  bool lowestIncluded = true;  ///< [lowest, ...] or (lowest, ...]
  double highest = 0.0;        ///< the upper end
  /// Why the upper bound is there, for keys that would make a run unbounded; empty otherwise.
  std::string bound;
};

/// The range of `key` in [world] (scope "world"), the scene's `steps` (scope "world"), or the
/// [solver] table of the solver `scope` names; nullopt for a key without one (booleans, gravity).
std::optional<SettingRange> findSettingRange(const std::string& scope, const std::string& key);

/// Whether `value` lies in `range`.
bool inSettingRange(double value, const SettingRange& range);

/// "must be an integer in [1, 1000]" or "must be in (0, 1]", with the bound's reason when the
/// value is above it.
std::string describeSettingRange(const SettingRange& range, bool integer, double value);

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
