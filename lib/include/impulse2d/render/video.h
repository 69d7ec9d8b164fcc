// An MP4 of a run's frames, made by ffmpeg when it is on the machine. Optional: nothing in the
// library or its tests needs it.
#pragma once

#include <filesystem>
#include <optional>

#include "impulse2d/render/frame_writer.h"

namespace impulse2d::render {

/// The ffmpeg executable on PATH, if there is one.
std::optional<std::filesystem::path> findFfmpeg();

/// Runs ffmpeg over the writer's frames (PREFIX_%05d.png) at framesPerSecond and writes
/// directory()/PREFIX.mp4 (H.264, yuv420p, odd sizes padded to even). Returns its path. Throws
/// RenderError when ffmpeg is not on PATH (saying how to make the video by hand), when there
/// are no frames, or when ffmpeg fails.
std::filesystem::path writeVideo(const FrameWriter& writer, double framesPerSecond);

}  // namespace impulse2d::render
