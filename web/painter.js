// The painter: paints the page's views in a thread of its own (web/page.js hands it each view's
// canvas as an OffscreenCanvas), so that the page's thread steps the runs and makes their marks
// while this one parses the paths and rasterizes them, most of a pyramid's frame. Messages:
// {view, canvas} once per view, then {view, width, height, marks} per frame, each answered with
// {view} once painted.
"use strict";
importScripts("marks.js");

const canvases = [];
const font = new FontFace("DejaVu Sans", "url(DejaVuSans.ttf)");
self.fonts.add(font);
const fontLoaded = font.load();

self.onmessage = async ({ data }) => {
  if (data.canvas) {
    canvases[data.view] = data.canvas;
    return;
  }
  await fontLoaded;
  const canvas = canvases[data.view];
  if (canvas.width !== data.width || canvas.height !== data.height) {
    canvas.width = data.width;
    canvas.height = data.height;
  }
  paintMarks(canvas.getContext("2d"), data.marks);
  self.postMessage({ view: data.view });
};
