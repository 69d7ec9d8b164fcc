// The self-contained viewer page: HTML, CSS and a little JavaScript in one file, the frames
// referenced by their file names, the figures embedded as a JSON array.
#include "impulse2d/render/viewer.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace impulse2d::render {

namespace {

/// A JSON string a script can hold: quotes and backslashes escaped, control characters (a line
/// break in a file name) as \u00XX, and "<" as \u003c, so "</script>" never ends the script.
std::string jsonString(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || c == '<') {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", byte);
      quoted += escaped;
      continue;
    }
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

std::string jsonNumber(double value) {
  if (!std::isfinite(value)) return "null";
  std::ostringstream text;
  text.precision(9);
  text << value;
  return text.str();
}

std::string framesJson(const FrameWriter& writer) {
  std::string json = "[";
  for (int i = 0; i < writer.frameCount(); ++i) {
    json += (i ? "," : "") + jsonString(writer.framePath(i).filename().string());
  }
  return json + "]";
}

std::string stepsJson(const FrameWriter& writer) {
  std::string json = "[";
  for (int i = 0; i < writer.frameCount(); ++i) {
    json += (i ? "," : "") + std::to_string(writer.steps()[std::size_t(i)]);
  }
  return json + "]";
}

std::string figuresJson(const FigureTable& figures) {
  std::string json = "{\"columns\":[";
  for (std::size_t i = 0; i < figures.columns.size(); ++i) {
    json += (i ? "," : "") + jsonString(figures.columns[i]);
  }
  json += "],\"rows\":[";
  for (std::size_t r = 0; r < figures.rows.size(); ++r) {
    json += r ? ",[" : "[";
    for (std::size_t c = 0; c < figures.rows[r].size(); ++c) {
      json += (c ? "," : "") + jsonNumber(figures.rows[r][c]);
    }
    json += "]";
  }
  return json + "]}";
}

std::string plotsJson(const std::vector<ViewerPlot>& plots) {
  std::string json = "[";
  for (std::size_t i = 0; i < plots.size(); ++i) {
    const ViewerPlot& plot = plots[i];
    json += (i ? ",{" : "{") + std::string("\"file\":") + jsonString(plot.file) +
            ",\"timeMin\":" + jsonNumber(plot.timeMin) +
            ",\"timeMax\":" + jsonNumber(plot.timeMax) + ",\"left\":" + jsonNumber(plot.left) +
            ",\"right\":" + jsonNumber(plot.right) + "}";
  }
  return json + "]";
}

// The frame sits at the page's top left corner at its own size, so a screenshot of the page
// shows the frame's pixels unchanged there (scripts/viewer-test compares them).
const char* const kPageHead = R"(<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>impulse2d viewer</title>
<style>
body { margin: 0; font: 14px sans-serif; background: #fafaf7; }
#frame { display: block; image-rendering: pixelated; }
#controls, #figures { margin: 8px; }
#slider { width: 60%; vertical-align: middle; }
table { border-collapse: collapse; } td { padding: 1px 10px 1px 0; }
.plot { position: relative; display: inline-block; margin: 8px; }
.plot img { display: block; width: 640px; }
.cursor { position: absolute; top: 10%; bottom: 12%; width: 2px; background: #cc0099; }
</style></head><body>
<img id="frame" alt="frame">
<div id="controls"><button id="play">play</button>
<input id="slider" type="range" min="0" value="0"> <span id="label"></span></div>
<div id="plots"></div>
<table id="figures"></table>
<p style="margin:8px">Left and right arrow keys step one frame; space plays. Add #frame=N to the
address to open at frame N. The colours and arrows are explained in each frame's legend.</p>
<script>
)";

const char* const kPageScript = R"(
const slider = document.getElementById("slider");
const image = document.getElementById("frame");
slider.max = frames.length - 1;
// File names are the scene's and may hold any character: each becomes one encoded path segment,
// and elements are built, never parsed from text.
plots.forEach((plot, i) => {
  const box = document.createElement("div");
  box.className = "plot";
  const picture = document.createElement("img");
  picture.src = encodeURIComponent(plot.file);
  picture.alt = "plot";
  const cursor = document.createElement("div");
  cursor.className = "cursor";
  cursor.id = "cursor-" + i;
  box.append(picture, cursor);
  document.getElementById("plots").append(box);
});
// The cursor of each plot at the frame's time, as a percentage of the plot's width.
function moveCursors(index) {
  const time = steps[index] * secondsPerStep;
  plots.forEach((plot, i) => {
    const along = (time - plot.timeMin) / (plot.timeMax - plot.timeMin);
    const x = 100 * (plot.left + Math.max(0, Math.min(1, along)) * (plot.right - plot.left));
    document.getElementById("cursor-" + i).style.left = x.toFixed(2) + "%";
  });
}
function show(index) {
  index = Math.max(0, Math.min(frames.length - 1, index));
  slider.value = index;
  image.src = encodeURIComponent(frames[index]);
  document.getElementById("label").textContent =
      "frame " + index + " of " + (frames.length - 1) + ", step " + steps[index];
  const row = figures.rows[index] || [];
  let html = "";
  figures.columns.forEach((name, i) => {
    const v = row[i];
    const value = v === undefined || v === null ? "" : Number.isInteger(v) ? v : v.toPrecision(6);
    html += "<tr><td>" + name + "</td><td>" + value + "</td></tr>";
  });
  document.getElementById("figures").innerHTML = html;
  moveCursors(index);
  history.replaceState(null, "", "#frame=" + index);
}
function fromAddress() {
  const match = /frame=(\d+)/.exec(location.hash);
  return match ? parseInt(match[1], 10) : 0;
}
let timer = null;
function play() {
  if (timer) { clearInterval(timer); timer = null; return; }
  timer = setInterval(() => show((Number(slider.value) + 1) % frames.length), 1000 / fps);
}
slider.addEventListener("input", () => show(Number(slider.value)));
document.getElementById("play").addEventListener("click", play);
document.addEventListener("keydown", (event) => {
  if (event.key === "ArrowRight") show(Number(slider.value) + 1);
  else if (event.key === "ArrowLeft") show(Number(slider.value) - 1);
  else if (event.key === " ") { play(); event.preventDefault(); }
});
window.addEventListener("hashchange", () => show(fromAddress()));
show(fromAddress());
</script></body></html>
)";

}  // namespace

std::string viewerName(const FrameWriter& writer, const std::string& scene) {
  return writer.prefix() == scene ? "index.html" : writer.prefix() + ".html";
}

std::filesystem::path writeViewer(const FrameWriter& writer, const std::string& scene,
                                  const FigureTable& figures, double framesPerSecond,
                                  const std::vector<ViewerPlot>& plots, double secondsPerStep) {
  const std::filesystem::path path = writer.directory() / viewerName(writer, scene);
  std::ofstream page(path);
  page << kPageHead << "const frames = " << framesJson(writer) << ";\n"
       << "const steps = " << stepsJson(writer) << ";\n"
       << "const figures = " << figuresJson(figures) << ";\n"
       << "const fps = " << jsonNumber(framesPerSecond) << ";\n"
       << "const plots = " << plotsJson(plots) << ";\n"
       << "const secondsPerStep = " << jsonNumber(secondsPerStep) << ";\n"
       << kPageScript;
  page.close();
  if (!page) throw RenderError("cannot write the viewer '" + path.string() + "'");
  return path;
}

}  // namespace impulse2d::render
