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

/// The numbers each mark kind carries after its kind (web/mark_encoding.h).
const CARRIES = [5, 5, 7, 0, 2, 2, 0];
const BAR = 124, REPEAT = 61;  // '|', which ends each path's data; '=', the last path again

/// The marks in two layers, for two painters (web/painter.js), or null where the frame has no
/// place to split. The lower layer ends where its share of the path data (what parsing and
/// rasterizing cost) comes nearest half, at a mark outside any Save and not before a repeated
/// path ("=", which needs the last one). The translations before the split are undone at the
/// lower layer's end and made again at the upper's start, so each paints as the whole frame does.
function splitMarks(marks) {
  const n = marks.numbers, bytes = marks.paths;
  // Where a split may come: [mark's number, path byte, text, x, y].
  const places = [];
  let i = 0, at = 0, text = 0, depth = 0, x = 0, y = 0;
  while (i < n.length) {
    const kind = n[i];
    if (kind === FILL || kind === STROKE) {
      const before = places[places.length - 1];
      if (bytes[at] === REPEAT && before && before[1] === at) places.pop();
      at = bytes.indexOf(BAR, at) + 1;
    } else if (kind === TEXT) {
      ++text;
    } else if (kind === SAVE) {
      ++depth;
    } else if (kind === RESTORE) {
      --depth;
    } else if (kind === TRANSLATE && depth === 0) {
      x += n[i + 1];
      y += n[i + 2];
    }
    i += 1 + CARRIES[kind];
    if (depth === 0 && i < n.length) places.push([i, at, text, x, y]);
  }
  if (!places.length) return null;
  const nearest = (best, place) =>
    Math.abs(2 * place[1] - bytes.length) < Math.abs(2 * best[1] - bytes.length) ? place : best;
  const [number, byte, texts, dx, dy] = places.reduce(nearest);
  const lowerNumbers = new Float64Array(number + 3);
  lowerNumbers.set(n.subarray(0, number));
  lowerNumbers.set([TRANSLATE, -dx, -dy], number);
  const upperNumbers = new Float64Array(n.length - number + 3);
  upperNumbers.set([TRANSLATE, dx, dy]);
  upperNumbers.set(n.subarray(number), 3);
  return {
    lower: { numbers: lowerNumbers, paths: bytes.slice(0, byte),
             texts: marks.texts.slice(0, texts) },
    upper: { numbers: upperNumbers, paths: bytes.slice(byte), texts: marks.texts.slice(texts) },
  };
}
