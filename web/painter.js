// The painter: paints the page's views in a thread of their own, so that the page's thread only
// steps the runs and makes their marks while this one turns the marks into pixels (parsing the
// paths and rasterizing them, most of a pyramid's frame). The page hands each view's canvas over
// once ({view, canvas}), then each frame ({view, width, height, marks}); each painted frame is
// answered with {view}.
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
