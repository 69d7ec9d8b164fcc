// The contact sheet: a grid of thumbnails of a run (or of a traced step's events), each with a
// caption sized for the thumbnail, so a whole run can be judged from one image.
#pragma once

#include <vector>

#include "impulse2d/render/frame.h"
#include "impulse2d/render/render_settings.h"

namespace impulse2d::render {

/// Where a contact sheet puts its thumbnails: a grid of cells, each a thumbnail over its label.
struct SheetLayout {
  /// Indices of the frames shown, in order.
  std::vector<int> frames;
  /// thumbnails per row
  int columns = 0;
  /// rows of thumbnails
  int rows = 0;
  /// in pixels
  int thumbnailWidth = 0;
  /// in pixels
  int thumbnailHeight = 0;
  int labelHeight = 0;  ///< the caption's bar, under each thumbnail
  int spacing = 0;      ///< between cells and around the sheet
  int width = 0;        ///< of the whole sheet
  /// pixels, of the whole sheet
  int height = 0;

  /// Top left pixel of thumbnail k (its caption bar lies under it).
  int thumbnailX(int k) const { return spacing + (k % columns) * (thumbnailWidth + spacing); }
  /// Top pixel row of thumbnail k.
  int thumbnailY(int k) const {
    return spacing + (k / columns) * (thumbnailHeight + labelHeight + spacing);
  }
};

/// The indices of `count` frames evenly spaced over frameCount frames, first and last included
/// (all frames when there are no more than `count`).
std::vector<int> evenlySpaced(int frameCount, int count);

/// The frames a sheet shows, at most `count`, in order: every preferred frame first (evenly
/// spaced among them when there are more), the rest of the places evenly over the others. A
/// traced step prefers its velocity events.
std::vector<int> chooseFrames(const std::vector<bool>& preferred, int count);

/// The layout of a sheet of `shown` frames whose thumbnails show pictures of sceneWidth ×
/// sceneHeight pixels.
SheetLayout contactSheetLayout(const std::vector<int>& shown, int sceneWidth, int sceneHeight,
                               const RenderSettings& settings);

/// The sheet: frames[layout.frames[k]]'s scene as thumbnail k, its caption under it.
Picture drawContactSheet(const SheetLayout& layout, const std::vector<Frame>& frames,
                         const RenderSettings& settings);

}  // namespace impulse2d::render
