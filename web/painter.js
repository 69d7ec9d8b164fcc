// The painters: paint the page's views in threads of their own, so that the page's thread steps the
// runs and makes their marks while they parse the paths and rasterize them, most of a pyramid's
// frame. Where the browser gives the page two workers, each frame's marks are split in two layers
// (splitMarks, web/marks.js), one painter to each:
// - the *layer painter* paints the lower layer into a canvas of its own as soon as it can and
//   hands its picture (an ImageBitmap) to the other;
// - the *shown painter* holds the views' canvases (web/page.js hands each over as an
//   OffscreenCanvas) and, once per animation frame, paints the newest frame of each view whose
//   lower layer has come: that picture, then the upper layer's marks on it.
// The two rasterize at once, on the machine's two cores, and a view always shows both layers of
// one frame. With one worker, the shown painter paints whole frames. A frame overtaken by a newer
// one before its turn is dropped unpainted.
// Messages from the page: {view, canvas} once per view to the shown painter, {port} once to each
// (the channel between them, where there are two), then per frame {view, frame, width, height,
// marks, layered} to the shown painter (layered: the lower layer comes by the port) and {view,
// frame, width, height, marks} to the layer painter. The shown painter answers each frame with
// {view, painted}.
"use strict";
importScripts("marks.js");

const font = new FontFace("DejaVu Sans", "url(DejaVuSans.ttf)");
self.fonts.add(font);
const fontLoaded = font.load();

let port = null;         // to the other painter
const canvases = [];     // shown painter: the views' canvases
const waiting = [];      // shown painter, per view: the frames not yet painted, oldest first
const lowers = [];       // shown painter, per view: the newest lower layer's picture
const newest = [];       // layer painter, per view: the newest frame not yet painted
const layers = [];       // layer painter, per view: its canvas
let scheduled = false;

self.onmessage = ({ data }) => {
  if (data.port) {
    port = data.port;
    port.onmessage = ({ data: lower }) => takeLower(lower);
  } else if (data.canvas) {
    canvases[data.view] = data.canvas;
  } else if (canvases.length) {
    takeFrame(data);
  } else {
    layerFrame(data);
  }
};

// ---- the layer painter ----------------------------------------------------------------------

/// Keeps the newest frame of the view and paints it once the messages already waiting are read.
function layerFrame(data) {
  const pending = newest.some((frame) => frame);
  newest[data.view] = data;
  if (!pending) fontLoaded.then(() => setTimeout(paintLayers));
}

function paintLayers() {
  newest.forEach((data, view) => {
    if (!data) return;
    newest[view] = null;
    if (!layers[view]) layers[view] = new OffscreenCanvas(data.width, data.height);
    const canvas = layers[view];
    if (canvas.width !== data.width || canvas.height !== data.height) {
      canvas.width = data.width;
      canvas.height = data.height;
    }
    paintMarks(canvas.getContext("2d", { alpha: false }), data.marks);
    const bitmap = canvas.transferToImageBitmap();
    port.postMessage({ view, frame: data.frame, bitmap }, [bitmap]);
  });
}

// ---- the shown painter ----------------------------------------------------------------------

/// Drops the view's frames older than `frame`, unpainted.
function dropBefore(view, frame) {
  while (waiting[view].length && waiting[view][0].frame < frame) {
    waiting[view].shift();
    self.postMessage({ view, painted: false });
  }
}

function takeFrame(data) {
  waiting[data.view] = waiting[data.view] || [];
  waiting[data.view].push(data);
  schedule();
}

/// A lower layer: the frames before it will get none (the layer painter skipped theirs for a
/// newer one).
function takeLower(lower) {
  if (lowers[lower.view]) lowers[lower.view].bitmap.close();
  lowers[lower.view] = lower;
  dropBefore(lower.view, lower.frame);
  schedule();
}

/// The view's newest frame that can be painted: whole, or its lower layer come.
function ready(view) {
  const frames = waiting[view] || [];
  for (let k = frames.length - 1; k >= 0; --k) {
    const data = frames[k];
    if (!data.layered || (lowers[view] && lowers[view].frame === data.frame)) return data;
  }
  return null;
}

function schedule() {
  if (scheduled || !waiting.some((frames, view) => ready(view))) return;
  scheduled = true;
  fontLoaded.then(() => self.requestAnimationFrame(paintNewest));
}

function paintNewest() {
  scheduled = false;
  waiting.forEach((frames, view) => {
    const data = ready(view);
    if (!data) return;
    dropBefore(view, data.frame);
    frames.shift();
    const canvas = canvases[view];
    if (canvas.width !== data.width || canvas.height !== data.height) {
      canvas.width = data.width;
      canvas.height = data.height;
    }
    const context = canvas.getContext("2d");
    if (data.layered) {
      context.drawImage(lowers[view].bitmap, 0, 0);
      lowers[view].bitmap.close();
      lowers[view] = null;
    }
    paintMarks(context, data.marks);
    self.postMessage({ view, painted: true });
  });
  schedule();
}
