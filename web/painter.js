// The painter: paints the page's views in a thread of its own (web/page.js hands it each view's
// canvas as an OffscreenCanvas), so that the page's thread steps the runs and makes their marks
// while this one parses the paths and rasterizes them, most of a pyramid's frame. It paints the
// newest frame of each view once per animation frame: each painted frame is one the screen shows,
// and a frame overtaken by a newer one before its turn is dropped unpainted. Where the page has
// two painters, each paints one layer of every frame on a canvas of its own, the upper layer's
// stacked on the lower's and cleared before each frame. Messages: {view, canvas} once per view,
// then {view, frame, width, height, marks, clear} per frame, each answered with {view, frame,
// painted, at}: at, the animation frame's time (ms since the epoch) it was painted in.
"use strict";
importScripts("marks.js");

const canvases = [];
const newest = [];  // per view: the newest frame not yet painted
let scheduled = false;
const font = new FontFace("DejaVu Sans", "url(DejaVuSans.ttf)");
self.fonts.add(font);
const fontLoaded = font.load();

self.onmessage = ({ data }) => {
  if (data.canvas) {
    canvases[data.view] = data.canvas;
    return;
  }
  const old = newest[data.view];
  if (old) self.postMessage({ view: old.view, frame: old.frame, painted: false });
  newest[data.view] = data;
  if (!scheduled) {
    scheduled = true;
    fontLoaded.then(() => self.requestAnimationFrame(paintNewest));
  }
};

function paintNewest(now) {
  scheduled = false;
  newest.forEach((data, view) => {
    if (!data) return;
    newest[view] = null;
    const canvas = canvases[view];
    if (canvas.width !== data.width || canvas.height !== data.height) {
      canvas.width = data.width;
      canvas.height = data.height;
    }
    const context = canvas.getContext("2d");
    if (data.clear) context.clearRect(0, 0, canvas.width, canvas.height);
    paintMarks(context, data.marks);
    self.postMessage({ view, frame: data.frame, painted: true, at: performance.timeOrigin + now });
  });
}
