// The contact sheet: a run (or a traced step, or a comparison) on one page for a slide or an A4
// page. A title strip names the scene; a grid of cells, each frame's scene drawn again at the
// cell's size so its text and arrows stay readable, its caption under it; a legend strip with the
// force scale once for the whole sheet.
#pragma once

#include <vector>

#include "impulse2d/render/frame.h"
#include "impulse2d/render/render_settings.h"

namespace impulse2d::render {

/// Where a contact sheet puts its cells. A cell is a thumbnail of one frame's scene over its
/// caption; a comparison's cell holds its panels side by side, each under its label.
struct SheetLayout {
  /// Indices of the frames shown, in order.
  std::vector<int> frames;
  /// cells per row
  int columns = 0;
  /// rows of cells
  int rows = 0;
  /// scenes side by side in a cell: a comparison's panels, else 1
  int panels = 1;
  /// in pixels, of one scene (one panel of a comparison's cell)
  int thumbnailWidth = 0;
  /// in pixels, of one scene
  int thumbnailHeight = 0;
  int panelLabelHeight = 0;  ///< the label bar over each panel (0 without panels)
  int labelHeight = 0;       ///< the caption's bar, under each cell
  int titleHeight = 0;       ///< the strip above the grid naming the scene
  int legendHeight = 0;      ///< the strip under the grid: legend and force scale
  int spacing = 0;           ///< between cells and around the sheet
  int width = 0;             ///< of the whole sheet
  /// pixels, of the whole sheet
  int height = 0;

  /// Width of a cell: its panels side by side.
  int cellWidth() const { return panels * thumbnailWidth + (panels - 1) * spacing; }
  /// Height of a cell: panel labels, scene and caption.
  int cellHeight() const { return panelLabelHeight + thumbnailHeight + labelHeight; }
  /// Left pixel of cell k (of its first panel).
  int thumbnailX(int k) const { return spacing + (k % columns) * (cellWidth() + spacing); }
  /// Top pixel row of cell k's scenes (under the panel labels).
  int thumbnailY(int k) const {
    return titleHeight + spacing + (k / columns) * (cellHeight() + spacing) + panelLabelHeight;
  }
};

/// The indices of at most `count` frames of frameCount, evenly spaced, first and last included
/// (all frames when there are no more than `count`): the most, down to half `count` and one,
/// whose steps split the run exactly, else `count` steps apart as evenly as rounding allows.
std::vector<int> evenlySpaced(int frameCount, int count);

/// The frames a sheet shows, at most `count`, in order: every preferred frame first (evenly
/// spaced among them when there are more), the rest of the places evenly over the others. A
/// traced step prefers its velocity events.
std::vector<int> chooseFrames(const std::vector<bool>& preferred, int count);

/// How many frames a sheet of frames of `panels` panels each shows: settings.sheetThumbnails
/// panels in all, and at least two frames.
int sheetFrameCount(int panels, const RenderSettings& settings);

/// The layout of a sheet of `shown` frames of `panels` panels each, whose scenes are sceneWidth ×
/// sceneHeight pixels: each drawn settings.sheetCellWidth wide, in the grid whose sheet is
/// nearest a settings.slideAspect slide.
SheetLayout contactSheetLayout(const std::vector<int>& shown, int sceneWidth, int sceneHeight,
                               const RenderSettings& settings, int panels = 1);

/// The sheet: frames[layout.frames[k]]'s scene in cell k, its caption under it; the first
/// frame's title above the grid, and one legend for every kind drawn on the sheet under it.
Picture drawContactSheet(const SheetLayout& layout, const std::vector<Frame>& frames,
                         const RenderSettings& settings);

}  // namespace impulse2d::render
