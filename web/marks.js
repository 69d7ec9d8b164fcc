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
// Per canvas, the paths of the pieces of path data in the last frame painted there, by their path
// data: the pieces of bodies and contact points that did not move keep theirs from frame to frame,
// and a mark's path is its pieces' paths added together. A path repeated at once (a contact
// point's dots, filled and then outlined) comes as "=" and is the last one again.
const parsedOn = new WeakMap();
function paintMarks(context, marks) {
  const n = marks.numbers, paths = pathText.decode(marks.paths).split("|");
  const kept = parsedOn.get(context) || new Map(), parsed = new Map();
  parsedOn.set(context, parsed);
  const pieceOf = (data) => {
    const path = parsed.get(data) || kept.get(data) || new Path2D(data);
    parsed.set(data, path);
    return path;
  };
  let last = null;
  const pathOf = (data) => {
    if (data === "=") return last;
    if (!data.includes(";")) return (last = pieceOf(data));
    last = new Path2D();
    for (const piece of data.split(";")) last.addPath(pieceOf(piece));
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
