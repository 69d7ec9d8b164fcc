// The contact sheet: a grid of evenly spaced thumbnails of a run, each labelled with its step, so
// a whole run can be judged from one image.
#pragma once

#include <vector>

#include "impulse2d/render/canvas.h"
#include "impulse2d/render/render_settings.h"

namespace impulse2d::render {

/// Where a contact sheet puts its thumbnails: a grid of cells, each a thumbnail over its label.
struct SheetLayout {
  /// Indices of the frames shown, in order: evenly spaced, the first and last frame included.
  std::vector<int> frames;
  /// thumbnails per row
  int columns = 0;
  /// rows of thumbnails
  int rows = 0;
  /// in pixels
  int thumbnailWidth = 0;
  /// in pixels
  int thumbnailHeight = 0;
  int labelHeight = 0;  ///< the step label's bar, under each thumbnail
  int spacing = 0;      ///< between cells and around the sheet
  int width = 0;        ///< of the whole sheet
  /// pixels, of the whole sheet
  int height = 0;

  /// Top left pixel of thumbnail k (its label bar lies under it).
  int thumbnailX(int k) const { return spacing + (k % columns) * (thumbnailWidth + spacing); }
  /// Top pixel row of thumbnail k.
  int thumbnailY(int k) const {
    return spacing + (k / columns) * (thumbnailHeight + labelHeight + spacing);
  }
};

/// The indices of `count` frames evenly spaced over frameCount frames, first and last included
/// (all frames when there are no more than `count`).
std::vector<int> evenlySpaced(int frameCount, int count);

/// The layout of a sheet of frameCount frames of frameWidth × frameHeight pixels.
SheetLayout contactSheetLayout(int frameCount, int frameWidth, int frameHeight,
                               const RenderSettings& settings);

/// The sheet: thumbnails[k] is the full-size frame layout.frames[k], labelled "step steps[k]".
Canvas drawContactSheet(const SheetLayout& layout, const std::vector<Canvas>& thumbnails,
                        const std::vector<long>& steps, const RenderSettings& settings);

}  // namespace impulse2d::render
