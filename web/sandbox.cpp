// The browser sandbox's entry: the library's scene loader, world and frame drawing behind one
// embind class. The page (web/page.js) gives it a scene's text and the command line's
// overrides, steps it, and paints the frame's marks (render/marks.h) on its canvas.
#include <emscripten.h>
#include <emscripten/bind.h>

#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "impulse2d/presets.h"
#include "impulse2d/render/camera.h"
#include "impulse2d/render/event_story.h"
#include "impulse2d/render/frame.h"
#include "impulse2d/render/marks.h"
#include "impulse2d/scene/scene_file.h"
#include "impulse2d/scene/setting_ranges.h"
#include "mark_encoding.h"
#include "run_figures.h"
#include "scene_setup.h"

using emscripten::val;
namespace render = impulse2d::render;

// The page measures text with its canvas, in the font the frames use (DejaVu Sans, shipped with
// the page), so the legend and heads-up are laid out as Cairo lays them out.
EM_JS(double, measureText, (const char* text, double size),
      { return Module.measureText(UTF8ToString(text), size); });

namespace {

/// Text that reads back as exactly this double. `i2d run --csv` writes the shortest such text
/// (std::to_chars), which emscripten's C++ library lacks; the test compares the values read back.
void appendNumber(std::string& line, double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  line += buffer;
}

/// A copy of `values` as a new JavaScript typed array (`type`: "Float64Array", "Uint8Array").
template <typename T>
val typedArray(const char* type, const T* values, std::size_t count) {
  return val::global(type).new_(val(emscripten::typed_memory_view(count, values)));
}

/// The marks as the page's paintMarks takes them (mark_encoding.h); the path data goes as bytes,
/// which the page decodes in one call (embind's own string conversion reads them one by one).
val marksForPage(const std::vector<render::Mark>& marks) {
  const sandbox::EncodedMarks encoded = sandbox::encodeMarks(marks);
  val texts = val::array();
  for (std::size_t k = 0; k < encoded.texts.size(); ++k) texts.set(k, encoded.texts[k]);
  val result = val::object();
  result.set("numbers", typedArray("Float64Array", encoded.numbers.data(), encoded.numbers.size()));
  result.set("paths",
             typedArray("Uint8Array", reinterpret_cast<const unsigned char*>(encoded.paths.data()),
                        encoded.paths.size()));
  result.set("texts", texts);
  return result;
}

/// Tells the events of the step being taken, one paragraph each.
class TraceText : public impulse2d::SolverObserver {
 public:
  TraceText(const impulse2d::Simulation& simulation)
      : simulation_(simulation), teller_(simulation.bodies()) {}
  void onSolverEvent(const impulse2d::SolverEvent& event,
                     const std::vector<impulse2d::Body>& bodies,
                     const std::vector<impulse2d::Manifold>& manifolds) override {
    const render::EventStory story =
        teller_.tell(event, bodies, manifolds, simulation_.solverName(), simulation_.settings().dt);
    text_ += story.label + "\n";
    for (const std::string& line : story.lines) text_ += "  " + line + "\n";
  }
  void onVelocitiesChanged(const std::vector<impulse2d::Body>& bodies) override {
    teller_.restart(bodies);
  }
  const std::string& text() const { return text_; }

 private:
  const impulse2d::Simulation& simulation_;
  render::EventTeller teller_;
  std::string text_;
};

/// One field of the settings, its value and its range, for the page's controls.
val describeField(const std::string& scope, const std::string& section,
                  const impulse2d::SettingField& field) {
  val entry = val::object();
  entry.set("section", section);
  entry.set("name", field.name);
  if (const auto* value = std::get_if<double*>(&field.value)) {
    entry.set("kind", "number");
    entry.set("value", **value);
  } else if (const auto* value = std::get_if<int*>(&field.value)) {
    entry.set("kind", "integer");
    entry.set("value", **value);
  } else if (const auto* value = std::get_if<bool*>(&field.value)) {
    entry.set("kind", "toggle");
    entry.set("value", **value);
  } else if (const auto* value = std::get_if<impulse2d::Vec2*>(&field.value)) {
    entry.set("kind", "vector");
    char text[64];
    std::snprintf(text, sizeof text, "%g, %g", (*value)->x(), (*value)->y());
    entry.set("value", std::string(text));
  } else if (const auto* choice = std::get_if<impulse2d::SettingChoice>(&field.value)) {
    entry.set("kind", "choice");
    entry.set("value", choice->current());
    val names = val::array();
    for (size_t i = 0; i < choice->names.size(); ++i) names.set(int(i), choice->names[i]);
    entry.set("names", names);
  }
  if (const std::optional<impulse2d::SettingRange> range =
          impulse2d::findSettingRange(scope, field.name)) {
    entry.set("lowest", range->lowest);
    entry.set("lowestIncluded", range->lowestIncluded);
    entry.set("highest", range->highest);
  }
  return entry;
}

}  // namespace

/// One scene running in the page: the scene as `i2d run SCENE --solver S --preset P --set ...`
/// would load it, its world, and the camera and renderer of its frames.
class Sandbox {
 public:
  /// Loads scene text (named `source` in errors) with the command line's overrides, one --set
  /// assignment per line of `assignments`; returns "" or the error as i2d prints it.
  std::string configure(const std::string& text, const std::string& source,
                        const std::string& solver, const std::string& preset,
                        const std::string& assignments) {
    try {
      i2d::SceneOptions options;
      options.scenePath = source;
      if (!solver.empty()) options.solver = solver;
      if (!preset.empty()) options.preset = preset;
      std::istringstream lines(assignments);
      for (std::string line; std::getline(lines, line);) {
        if (!line.empty()) options.settings.push_back(line);
      }
      impulse2d::SceneFile scene = impulse2d::parseScene(text, source);
      i2d::applyOverrides(options, scene);
      impulse2d::checkSceneSize(scene, source);
      if (scene.solver == "box2d") {
        throw std::invalid_argument("the browser runs impulse2d's solvers; box2d needs i2d");
      }
      scene_ = std::move(scene);
      restart();
      return "";
    } catch (const std::exception& error) {
      return std::string("error: ") + error.what();
    }
  }

  /// Back to step 0 of the scene. The camera starts fitted to step 0; survey() fits it to the
  /// whole run.
  void restart() {
    simulation_ = impulse2d::buildWorld(scene_);
    survey_ = impulse2d::buildWorld(scene_);
    first_ = render::captureFrame(*simulation_, scene_.name, settings_);
    camera_ = std::make_shared<render::RunCamera>(scene_.view, settings_, scene_.view.width,
                                                  scene_.view.height);
    camera_->add(survey_->bodies());
    fitRenderer();
  }

  /// Runs a second copy of the run ahead for up to `milliseconds`, adding each of its states to
  /// the camera, as `i2d run` adds every state it records before its frames are drawn; true once
  /// it has reached the last step (or a step that fails, where i2d's run stops too). The camera
  /// is then that of i2d's frames, and refit() fits the force scale through it.
  bool survey(double milliseconds) {
    if (!survey_) return true;
    const double end = emscripten_get_now() + milliseconds;
    bool failed = false;
    try {
      while (survey_->stepCount() < scene_.steps && emscripten_get_now() < end) {
        survey_->step();
        camera_->add(survey_->bodies());
      }
    } catch (const std::exception&) {
      failed = true;
    }
    if (!failed && survey_->stepCount() < scene_.steps) return false;
    survey_.reset();
    return true;
  }

  /// Fits the force scale through the camera as it stands, as i2d fits it to the run's first
  /// state through the camera of the whole run.
  void refit() { fitRenderer(); }

  /// Frames the run with `other`'s camera, as `i2d compare` frames its panels with one: both
  /// surveys then add to it. Call it before either has surveyed a step.
  void shareCamera(Sandbox& other) {
    camera_ = other.camera_;
    if (survey_) camera_->add(survey_->bodies());
    fitRenderer();
    other.fitRenderer();
  }

  /// Takes `count` steps; returns "" or the error that stopped the run.
  std::string step(int count) {
    try {
      for (int k = 0; k < count; ++k) simulation_->step();
      return "";
    } catch (const std::exception& error) {
      return std::string("error: ") + error.what();
    }
  }

  /// Takes one step, telling each solver event in the lecture's words (i2d run --trace-step).
  std::string traceStep() {
    TraceText trace(*simulation_);
    simulation_->setObserver(&trace);
    const std::string failure = step(1);
    simulation_->setObserver(nullptr);
    if (!failure.empty()) return failure;
    if (trace.text().empty()) {
      return "step " + std::to_string(simulation_->stepCount()) +
             " resolved no contacts: no solver events";
    }
    return "step " + std::to_string(simulation_->stepCount()) + "\n" + trace.text();
  }

  double stepCount() const { return double(simulation_->stepCount()); }
  int steps() const { return scene_.steps; }
  double dt() const { return scene_.world.dt; }
  std::string solver() const { return scene_.solver; }
  std::string preset() const { return scene_.preset; }
  int width() const { return scene_.view.width; }
  int height() const { return renderer_->frameHeight(); }

  /// The world rectangle the frames show, [x0, x1, y0, y1] (m): the view line of i2d run's
  /// summary, once survey() is done.
  val shown() const {
    const impulse2d::Aabb region = camera_->shown();
    val corners = val::array();
    for (const double value :
         {region.lower.x(), region.upper.x(), region.lower.y(), region.upper.y()}) {
      corners.call<void>("push", value);
    }
    return corners;
  }

  /// The dynamic bodies' rows of `i2d run --csv` at this step, header excluded.
  std::string state() const {
    std::string rows;
    const double time = double(simulation_->stepCount()) * scene_.world.dt;
    for (const impulse2d::Body& body : simulation_->bodies()) {
      if (body.isStatic()) continue;
      rows += std::to_string(simulation_->stepCount()) + ',';
      appendNumber(rows, time);
      rows += ',' + body.name;
      for (double value : {body.position.x(), body.position.y(), body.angle, body.velocity.x(),
                           body.velocity.y(), body.angularVelocity}) {
        rows += ',';
        appendNumber(rows, value);
      }
      rows += '\n';
    }
    return rows;
  }

  /// The plots' figures of this step (i2d run --plots): time, energies, load and friction.
  val figures() const {
    const i2d::StepFigures figures = i2d::measureStep(*simulation_);
    val result = val::object();
    result.set("time", figures.time);
    result.set("kinetic", figures.kinetic);
    result.set("potential", figures.potential);
    result.set("appliedForce", figures.appliedForce);
    result.set("frictionForce", figures.frictionForce);
    result.set("loaded", i2d::hasLoads(*simulation_));
    return result;
  }

  /// The frame as it stands, as marks: what `i2d run --frames` draws.
  val frame() {
    renderer_->setCamera(camera_->cameraFor(simulation_->bodies()));
    render::MarkList marks(
        [](const std::string& text, double size) { return measureText(text.c_str(), size); });
    {
      render::Drawing drawing(marks);
      renderer_->drawOnto(drawing, render::captureFrame(*simulation_, scene_.name, settings_));
    }
    return marksForPage(marks.marks());
  }

  /// The settings of [world] and of the solver's [solver] table, each with its range.
  val settings() {
    val fields = val::array();
    int count = 0;
    for (const impulse2d::SettingField& field : impulse2d::describe(scene_.world)) {
      fields.set(count++, describeField("world", "world", field));
    }
    for (const impulse2d::SettingField& field :
         impulse2d::solverSettingFields(scene_.solverSettings, scene_.solver)) {
      fields.set(count++, describeField(scene_.solver, "solver", field));
    }
    return fields;
  }

 private:
  /// A renderer of the camera as it stands, with the force scale fitted to the run's first state
  /// through it.
  void fitRenderer() {
    renderer_ = std::make_unique<render::FrameRenderer>(camera_->cameraFor(first_.bodies),
                                                        scene_.name, settings_);
    renderer_->fitForces(first_);
  }

  impulse2d::SceneFile scene_;
  render::RenderSettings settings_;
  std::unique_ptr<impulse2d::Simulation> simulation_;
  /// Fitted to the states surveyed so far; shared with the side-by-side run's.
  std::shared_ptr<render::RunCamera> camera_;
  std::unique_ptr<render::FrameRenderer> renderer_;
  std::unique_ptr<impulse2d::Simulation> survey_;  ///< the run ahead; empty once it is done
  render::FrameState first_;                       ///< step 0, which sets the force scale
};

/// The solvers the page offers and each one's presets: [{solver, presets: [{name, summary}]}].
val methods() {
  val list = val::array();
  int count = 0;
  for (const std::string& solver : impulse2d::solverNames()) {
    val entry = val::object();
    entry.set("solver", solver);
    val presets = val::array();
    int presetCount = 0;
    for (const impulse2d::Preset& preset : impulse2d::presets()) {
      if (preset.solver != solver) continue;
      val item = val::object();
      item.set("name", preset.name);
      item.set("summary", preset.summary);
      presets.set(presetCount++, item);
    }
    entry.set("presets", presets);
    list.set(count++, entry);
  }
  return list;
}

EMSCRIPTEN_BINDINGS(impulse2d_sandbox) {
  emscripten::function("methods", &methods);
  emscripten::class_<Sandbox>("Sandbox")
      .constructor<>()
      .function("configure", &Sandbox::configure)
      .function("restart", &Sandbox::restart)
      .function("survey", &Sandbox::survey)
      .function("refit", &Sandbox::refit)
      .function("shareCamera", &Sandbox::shareCamera)
      .function("shown", &Sandbox::shown)
      .function("step", &Sandbox::step)
      .function("traceStep", &Sandbox::traceStep)
      .function("stepCount", &Sandbox::stepCount)
      .function("steps", &Sandbox::steps)
      .function("dt", &Sandbox::dt)
      .function("solver", &Sandbox::solver)
      .function("preset", &Sandbox::preset)
      .function("width", &Sandbox::width)
      .function("height", &Sandbox::height)
      .function("state", &Sandbox::state)
      .function("figures", &Sandbox::figures)
      .function("frame", &Sandbox::frame)
      .function("settings", &Sandbox::settings);
}
