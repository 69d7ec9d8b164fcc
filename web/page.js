// The sandbox page: a scene, the command line's overrides (method, preset, --set), the run, and
// its frames painted from the library's marks (render/marks.h). The address holds the scene and
// the overrides, so a link shows the same run.
"use strict";

const $ = (id) => document.getElementById(id);
const page = {
  module: null,
  runs: [],          // one Sandbox per view: the run, and the side-by-side one
  scene: "",         // the shipped scene's name, or "" for pasted text
  text: "",          // the scene's text
  solver: "",        // the method chosen ("" at first: the scene's own)
  preset: "",
  compare: "",       // the side-by-side method, "" for none
  sets: [],          // "section.key=value", in order, as i2d --set takes them
  playing: false,
  surveying: false,  // a run's survey (Sandbox::survey) has not reached its end yet
  history: [],       // the plots' figures, one per step
  error: "",
  framesDrawn: 0,    // frames painted so far (scripts/web-test --measure counts them)
  plotted: 0,        // when the plots were last drawn (performance.now())
  painter: null,     // the worker painting the views (web/painter.js), where there is one
  painting: 0,       // frames handed to the painter and not yet painted or dropped
};
window.sandboxPage = page;

// The frame's text is measured for its layout (the legend's words repeat every frame).
const measuring = document.createElement("canvas").getContext("2d");
const measured = new Map();
function measureText(text, size) {
  const key = `${size} ${text}`;
  if (!measured.has(key)) {
    if (measured.size > 10000) measured.clear();
    measuring.font = fontOf(size);
    measured.set(key, measuring.measureText(text).width);
  }
  return measured.get(key);
}

// ---- the address --------------------------------------------------------------------------

function encodeText(text) {
  const bytes = new TextEncoder().encode(text);
  let binary = "";
  for (const b of bytes) binary += String.fromCharCode(b);
  return btoa(binary).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
}

function decodeText(coded) {
  const binary = atob(coded.replace(/-/g, "+").replace(/_/g, "/"));
  return new TextDecoder().decode(Uint8Array.from(binary, (c) => c.charCodeAt(0)));
}

function writeAddress() {
  const words = new URLSearchParams();
  if (page.scene) words.set("scene", page.scene);
  else words.set("text", encodeText(page.text));
  if (page.solver) words.set("solver", page.solver);
  if (page.preset) words.set("preset", page.preset);
  if (page.compare) words.set("compare", page.compare);
  for (const set of page.sets) words.append("set", set);
  history.replaceState(null, "", "#" + words.toString());
}

function readAddress() {
  const words = new URLSearchParams(location.hash.slice(1));
  return {
    scene: words.get("scene") || (words.get("text") ? "" : "resting_box"),
    text: words.get("text") ? decodeText(words.get("text")) : "",
    solver: words.get("solver") || "",
    preset: words.get("preset") || "",
    compare: words.get("compare") || "",
    sets: words.getAll("set"),
    painter: words.get("painter") || "",  // "page": paint on the page's thread (web-test --measure)
  };
}

// ---- the command line ---------------------------------------------------------------------

function quoted(word) {
  return /^[A-Za-z0-9_.\/=,:+-]+$/.test(word) ? word : "'" + word.replace(/'/g, "'\\''") + "'";
}

function commandLine(solver, preset, sets) {
  const words = ["build/apps/i2d", "run", page.scene ? `demos/scenes/${page.scene}.toml` : "SCENE.toml"];
  if (solver) words.push("--solver", solver);
  if (preset) words.push("--preset", preset);
  for (const set of sets) words.push("--set", set);
  words.push("--frames", "frames");
  return words.map(quoted).join(" ");
}

// ---- the runs -----------------------------------------------------------------------------

/// The --set assignments the side-by-side method takes: the world's, not the other solver's.
const worldSets = () => page.sets.filter((set) => set.startsWith("world."));

function configure() {
  const first = page.runs[0];
  const source = page.scene ? `${page.scene}.toml` : "pasted.toml";
  page.error = first.configure(page.text, source, page.solver, page.preset, page.sets.join("\n"));
  if (!page.error && page.compare) {
    const [solver, preset] = page.compare.split(":");
    page.error = page.runs[1].configure(page.text, source, solver, preset || "",
                                        worldSets().join("\n"));
  }
  if (!page.error && page.compare) page.runs[1].shareCamera(first);
  $("error").hidden = !page.error;
  $("error").textContent = page.error;
  $("second").hidden = !page.compare || !!page.error;
  page.history = [];
  page.surveying = !page.error && !survey(SURVEY_FIRST);
  if (!page.error) {
    page.solver = first.solver();
    page.preset = first.preset();
    showMethods();
    showSettings();
    $("command").textContent = commandLine(page.solver, page.preset, page.sets) +
      (page.compare ? "\n" + commandLine(page.compare.split(":")[0],
                                         page.compare.split(":")[1] || "", worldSets()) : "");
    record();
    draw();
  }
  writeAddress();
}

const activeRuns = () => (page.compare ? page.runs.slice(0, 2) : page.runs.slice(0, 1));

// The camera frames the whole run, as i2d's frames do: each run's survey steps a copy of it to
// the end first, this long (ms) before the first frame and then this long each animation frame
// (a pyramid40 takes seconds); the view is drawn again when it is done.
const SURVEY_FIRST = 200, SURVEY_EACH = 4;

// While the run plays, the plots and the step count under the controls are drawn again this
// often (ms), not every frame: redrawing the plots costs the pyramid a quarter of its frame
// rate, and a changed count lays out, paints and composites the page again (the frame's own
// heads-up shows each step).
const PLOT_EVERY = 100;

/// Surveys the runs for up to `milliseconds` each; true once all are done, their force scales
/// then fitted through the camera of the whole run (one camera for both, side by side).
function survey(milliseconds) {
  if (!activeRuns().every((run) => run.survey(milliseconds))) return false;
  for (const run of activeRuns()) run.refit();
  return true;
}

function record() {
  page.history.push(page.runs[0].figures());
}

function stepOnce() {
  for (const run of activeRuns()) {
    const failure = run.step(1);
    if (failure) {
      page.playing = false;
      $("error").hidden = false;
      $("error").textContent = failure;
      return false;
    }
  }
  record();
  return true;
}

/// Paints each run's frame in its view: by the painter (web/painter.js) where the browser can
/// hand a canvas to a worker, else here.
function draw() {
  if (page.error) return;
  activeRuns().forEach((run, k) => {
    if (page.painter) {
      const marks = run.frame();
      ++page.painting;
      page.painter.postMessage({ view: k, width: run.width(), height: run.height(), marks },
                               [marks.numbers.buffer, marks.paths.buffer]);
      return;
    }
    const canvas = k === 0 ? $("view") : $("view2");
    if (canvas.width !== run.width() || canvas.height !== run.height()) {
      canvas.width = run.width();
      canvas.height = run.height();
    }
    paintMarks(canvas.getContext("2d"), run.frame());
  });
  const run = page.runs[0];
  // Text set only where it changes: each setting makes the browser lay the page out again.
  const show = (id, text) => {
    if ($(id).textContent !== text) $(id).textContent = text;
  };
  show("view-label", page.solver + (page.preset ? ` (${page.preset})` : ""));
  show("view2-label", page.compare.replace(":", " preset "));
  const now = performance.now();
  if (!page.playing || run.stepCount() >= run.steps() || now - page.plotted >= PLOT_EVERY) {
    show("status", `step ${run.stepCount()} of ${run.steps()}` +
                   (page.surveying ? " (framing the whole run…)" : ""));
    plot();
    page.plotted = now;
  }
  if (!page.painter) ++page.framesDrawn;
}

/// Hands the views' canvases to the painter, where the browser can and the address does not ask
/// for painting on the page (painter=page, which scripts/web-test --measure compares).
function startPainter(where) {
  const views = [$("view"), $("view2")];
  if (!window.OffscreenCanvas || !views[0].transferControlToOffscreen || where === "page") return;
  try {
    page.painter = new Worker("painter.js");
  } catch (error) {
    return;  // the browser refused the worker: the page paints its views itself
  }
  views.forEach((view, k) => {
    const canvas = view.transferControlToOffscreen();
    page.painter.postMessage({ view: k, canvas }, [canvas]);
  });
  page.painter.onmessage = ({ data }) => {
    --page.painting;
    if (data.painted && data.view === 0) ++page.framesDrawn;
  };
}

/// Leaves the views the window's height below their top, less their captions: the whole frame
/// shows without scrolling (web/sandbox.css).
function fitViews() {
  const top = $("views").getBoundingClientRect().top + window.scrollY;
  const caption = $("view-label").offsetHeight;
  const room = Math.max(120, window.innerHeight - top - caption - 8);
  document.documentElement.style.setProperty("--view-room", `${room}px`);
}

// ---- the plots ----------------------------------------------------------------------------

function plotPoints(canvas, points, colour) {
  const context = canvas.getContext("2d");
  const { width, height } = canvas;
  context.clearRect(0, 0, width, height);
  context.strokeStyle = "grey";
  context.strokeRect(40, 10, width - 50, height - 40);
  if (points.length < 2) return;
  const xs = points.map((p) => p[0]), ys = points.map((p) => p[1]);
  const x0 = Math.min(...xs), x1 = Math.max(...xs, x0 + 1e-9);
  let y0 = Math.min(...ys), y1 = Math.max(...ys);
  if (y1 - y0 < 1e-9) { y0 -= 1; y1 += 1; }
  const px = (x) => 40 + (width - 50) * (x - x0) / (x1 - x0);
  const py = (y) => 10 + (height - 40) * (1 - (y - y0) / (y1 - y0));
  context.strokeStyle = colour;
  context.beginPath();
  points.forEach(([x, y], k) => (k ? context.lineTo(px(x), py(y)) : context.moveTo(px(x), py(y))));
  context.stroke();
  context.fillStyle = "black";
  context.font = "11px 'DejaVu Sans'";
  context.fillText(y1.toPrecision(4), 2, 18);
  context.fillText(y0.toPrecision(4), 2, height - 32);
  context.fillText(x0.toPrecision(3), 40, height - 16);
  context.fillText(x1.toPrecision(3), width - 50, height - 16);
}

function plot() {
  plotPoints($("energy-plot"), page.history.map((f) => [f.time, f.kinetic + f.potential]), "#c33");
  const loaded = page.history.length > 0 && page.history[0].loaded;
  $("friction-figure").hidden = !loaded;
  if (loaded) {
    plotPoints($("friction-plot"), page.history.map((f) => [f.appliedForce, f.frictionForce]),
               "#36c");
  }
}

// ---- the controls -------------------------------------------------------------------------

function option(select, value, label) {
  const item = document.createElement("option");
  item.value = value;
  item.textContent = label;
  select.append(item);
}

function showMethods() {
  const solver = $("solver"), preset = $("preset");
  solver.replaceChildren();
  for (const method of page.methods) option(solver, method.solver, method.solver);
  solver.value = page.solver;
  preset.replaceChildren();
  option(preset, "", "our defaults (refined)");
  const method = page.methods.find((m) => m.solver === page.solver);
  for (const p of method ? method.presets : []) option(preset, p.name, `${p.name}: ${p.summary}`);
  preset.value = page.preset;
  const compare = $("compare");
  if (compare.options.length === 1) {
    for (const m of page.methods) {
      option(compare, m.solver, m.solver);
      for (const p of m.presets) option(compare, `${m.solver}:${p.name}`, `${m.solver}, ${p.name}`);
    }
  }
  compare.value = page.compare;
}

function describeRange(field) {
  if (field.lowest === undefined) return "";
  const high = field.highest >= 1e300 ? "∞" : field.highest;
  return `${field.lowestIncluded ? "[" : "("}${field.lowest}, ${high}${field.highest >= 1e300 ? ")" : "]"}`;
}

/// Replaces the --set of this key, or adds one, and runs again.
function setSetting(key, value) {
  page.sets = page.sets.filter((set) => !set.startsWith(key + "="));
  page.sets.push(`${key}=${value}`);
  configure();
}

function showSettings() {
  const box = $("settings");
  box.replaceChildren();
  for (const field of page.runs[0].settings()) {
    const key = `${field.section}.${field.name}`;
    const row = document.createElement("label");
    row.className = "setting";
    const name = document.createElement("span");
    name.textContent = key;
    row.append(name);
    let input;
    if (field.kind === "toggle") {
      input = document.createElement("input");
      input.type = "checkbox";
      input.checked = field.value;
      input.addEventListener("change", () => setSetting(key, input.checked));
    } else if (field.kind === "choice") {
      input = document.createElement("select");
      for (const name of field.names) input.add(new Option(name, name, false, name === field.value));
      input.addEventListener("change", () => setSetting(key, input.value));
    } else if (field.kind === "vector") {
      input = document.createElement("input");
      input.value = field.value;
      input.size = 12;
      input.addEventListener("change", () => setSetting(key, `[${input.value}]`));
    } else {
      input = document.createElement("input");
      input.type = "number";
      input.value = field.value;
      input.step = field.kind === "integer" ? 1 : "any";
      if (field.lowest !== undefined) input.min = field.lowest;
      if (field.highest !== undefined && field.highest < 1e300) input.max = field.highest;
      input.title = describeRange(field);
      input.addEventListener("change", () => setSetting(key, input.value));
      const range = document.createElement("span");
      range.className = "range";
      range.textContent = describeRange(field);
      name.append(" ", range);
    }
    input.dataset.key = key;
    row.append(input);
    box.append(row);
  }
}

async function loadDemo(name) {
  const response = await fetch(`scenes/${name}.toml`);
  page.scene = name;
  page.text = await response.text();
  $("scene-text").value = page.text;
}

function wire() {
  $("demo").addEventListener("change", async () => {
    await loadDemo($("demo").value);
    page.solver = page.preset = "";
    page.sets = [];
    configure();
  });
  $("edit").addEventListener("click", () => { $("editor").hidden = !$("editor").hidden; });
  $("scene-file").addEventListener("change", async () => {
    const file = $("scene-file").files[0];
    if (file) $("scene-text").value = await file.text();
  });
  $("load-text").addEventListener("click", () => {
    page.scene = "";
    page.text = $("scene-text").value;
    page.solver = page.preset = "";
    page.sets = [];
    configure();
  });
  $("solver").addEventListener("change", () => {
    page.solver = $("solver").value;
    page.preset = "";
    page.sets = worldSets();
    configure();
  });
  $("preset").addEventListener("change", () => {
    page.preset = $("preset").value;
    page.sets = worldSets();
    configure();
  });
  $("compare").addEventListener("change", () => {
    page.compare = $("compare").value;
    configure();
  });
  $("play").addEventListener("click", () => {
    page.playing = !page.playing;
    $("play").textContent = page.playing ? "Pause" : "Play";
    if (!page.playing) plot();
  });
  $("step").addEventListener("click", () => { if (!page.error && stepOnce()) draw(); });
  $("restart").addEventListener("click", () => configure());
  $("trace").addEventListener("click", () => {
    if (page.error) return;
    $("trace-text").textContent = page.runs[0].traceStep();
    if (page.compare) page.runs[1].step(1);
    record();
    draw();
  });
}

/// Steps at the chosen speed: speed × 1/dt steps a second of the page's clock.
function animate() {
  let owed = 0, last = performance.now();
  const frame = (now) => {
    const elapsed = Math.min(0.1, (now - last) / 1000);
    last = now;
    const run = page.runs[0];
    if (page.surveying && !page.error) {
      page.surveying = !survey(SURVEY_EACH);
      if (!page.surveying && !page.playing) draw();
    }
    if (page.playing && !page.error && run.stepCount() < run.steps()) {
      owed += elapsed * Number($("speed").value) / run.dt();
      let stepped = false;
      for (; owed >= 1 && run.stepCount() < run.steps(); owed -= 1) {
        if (!stepOnce()) break;
        stepped = true;
      }
      if (stepped) draw();
    }
    requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);
}

async function start() {
  page.module = await Impulse2d({ measureText });
  await document.fonts.load('16px "DejaVu Sans"');
  page.runs = [new page.module.Sandbox(), new page.module.Sandbox()];
  page.methods = page.module.methods();
  const demos = await (await fetch("scenes.json")).json();
  for (const demo of demos) option($("demo"), demo.name, `${demo.name}: ${demo.title}`);
  const wanted = readAddress();
  if (wanted.scene) {
    await loadDemo(wanted.scene);
  } else {
    page.scene = "";
    page.text = wanted.text;
    $("scene-text").value = page.text;
  }
  $("demo").value = page.scene;
  Object.assign(page, { solver: wanted.solver, preset: wanted.preset, compare: wanted.compare,
                        sets: wanted.sets });
  wire();
  startPainter(wanted.painter);
  window.addEventListener("resize", fitViews);
  configure();
  fitViews();
  animate();
  page.ready = true;
}

start();
