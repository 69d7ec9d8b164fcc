// The painter: paints the page's views in a thread of its own (web/page.js hands it each view's
// canvas as an OffscreenCanvas), so that the page's thread steps the runs and makes their marks
// while this one parses the paths and rasterizes them, most of a pyramid's frame. It paints the
// newest frame of each view once per animation frame: each painted frame is one the screen shows,
// and a frame overtaken by a newer one before its turn is dropped unpainted. Messages: {view,
// canvas} once per view, then {view, width, height, marks} per frame, each answered with {view,
// painted}.
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
  if (newest[data.view]) self.postMessage({ view: data.view, painted: false });
  newest[data.view] = data;
  if (!scheduled) {
    scheduled = true;
    fontLoaded.then(() => self.requestAnimationFrame(paintNewest));
  }
};

function paintNewest() {
  scheduled = false;
  newest.forEach((data, view) => {
    if (!data) return;
    newest[view] = null;
    const canvas = canvases[view];
    if (canvas.width !== data.width || canvas.height !== data.height) {
      canvas.width = data.width;
      canvas.height = data.height;
    }
    paintMarks(canvas.getContext("2d"), data.marks);
    self.postMessage({ view, painted: true });
  });
}
