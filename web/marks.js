// Painting a frame's marks (render/marks.h, encoded by web/mark_encoding.h) on a canvas, as
// Cairo paints them for the PNG frames.
"use strict";

// The marks' kinds, in the order of render::Mark::Kind.
const FILL = 0, STROKE = 1, TEXT = 2, SAVE = 3, TRANSLATE = 4, CLIP = 5, RESTORE = 6;

const rgba = (n, i) => `rgba(${n[i]},${n[i + 1]},${n[i + 2]},${n[i + 3] / 255})`;
const fonts = new Map();
const fontOf = (size) => {
  if (!fonts.has(size)) fonts.set(size, `${size}px "DejaVu Sans"`);
  return fonts.get(size);
};

/// Paints the frame's marks (web/mark_encoding.h) as Cairo paints them for the PNGs: each fill
/// or stroke is one Path2D made from its SVG path data (a Path2D built call by call, or a path
/// per outline, costs several times as much for a pyramid's thousands of outlines).
const pathText = new TextDecoder();
// The paths of the last frame painted, by their path data: bodies at rest keep theirs from frame
// to frame. A path repeated at once (a contact point's dots, filled and then outlined) comes as
// "=" and is the last one again.
let parsed = new Map();
function paintMarks(context, marks) {
  const n = marks.numbers, paths = pathText.decode(marks.paths).split("|");
  const kept = parsed;
  parsed = new Map();
  let last = null;
  const pathOf = (data) => {
    if (data === "=") return last;
    last = parsed.get(data) || kept.get(data) || new Path2D(data);
    parsed.set(data, last);
    return last;
  };
  let i = 0, path = 0, text = 0;
  context.lineJoin = "miter";
  context.lineCap = "butt";
  context.textBaseline = "alphabetic";
  while (i < n.length) {
    const kind = n[i++];
    if (kind === FILL) {
      context.fillStyle = rgba(n, i);
      context.fill(pathOf(paths[path++]));
      i += 5;
    } else if (kind === STROKE) {
      context.strokeStyle = rgba(n, i);
      context.lineWidth = n[i + 4];
      context.stroke(pathOf(paths[path++]));
      i += 5;
    } else if (kind === TEXT) {
      context.fillStyle = rgba(n, i);
      context.font = fontOf(n[i + 4]);
      context.fillText(marks.texts[text++], n[i + 5], n[i + 6]);
      i += 7;
    } else if (kind === SAVE) {
      context.save();
    } else if (kind === TRANSLATE) {
      context.translate(n[i], n[i + 1]);
      i += 2;
    } else if (kind === CLIP) {
      context.beginPath();
      context.rect(0, 0, n[i], n[i + 1]);
      context.clip();
      i += 2;
    } else if (kind === RESTORE) {
      context.restore();
    }
  }
}
