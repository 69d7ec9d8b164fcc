// One file of a run's frames to drop into slides: an animated GIF (giflib), looping, at the run's
// own pace. MP4 is video.h's job (ffmpeg, where installed).
#pragma once

#include <filesystem>
#include <vector>

#include "impulse2d/render/frame_writer.h"
#include "impulse2d/render/image.h"

namespace impulse2d::render {

/// The GIF palette: 6 levels of red, 7 of green, 6 of blue (252 colours) and 4 greys.
std::vector<Color> gifPalette();
/// Index of the palette colour nearest `colour` (squared RGB distance).
int nearestPaletteIndex(const std::vector<Color>& palette, Color colour);

/// Writes directory()/PREFIX.gif from the writer's frames (rasterised from their pictures), each
/// shown 1 / framesPerSecond s (GIF counts in hundredths, at least 2), looping forever. Returns its
/// path. Throws RenderError when there are no frames or the file cannot be written.
std::filesystem::path writeGif(const FrameWriter& writer, double framesPerSecond);

}  // namespace impulse2d::render
