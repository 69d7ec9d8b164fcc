// Every colour, threshold and size the frames use, with its documented default, in one place.
// Sizes are in pixels unless the comment says metres; thresholds are in SI units.
#pragma once

#include "impulse2d/render/canvas.h"

namespace impulse2d::render {

/// Body colours by state (see BodyState in frame.h) and the colours of the overlays. The body
/// colours are the Okabe-Ito palette, which stays distinguishable under colour blindness.
struct Palette {
  /// behind the scene
  Color background{250, 250, 247, 255};
  Color staticBody{160, 160, 160, 255};    ///< grey: never moves
  Color flyingBody{86, 180, 233, 255};     ///< sky blue: no contact points
  Color restingBody{0, 158, 115, 255};     ///< bluish green: in contact and slow
  Color touchingBody{204, 121, 167, 255};  ///< reddish purple: in contact, moving, not sliding
  Color slidingBody{230, 159, 0, 255};     ///< orange: a contact point slides
  Color sleepingBody{200, 205, 215, 255};  ///< pale grey-blue: asleep
  /// bodies' edges
  Color outline{40, 40, 40, 255};
  /// the line showing a body's turn
  Color rotationMark{20, 20, 20, 255};
  Color contactPoint{255, 255, 255, 255};  ///< a white dot ringed in the outline colour
  /// contact normals
  Color contactNormal{60, 60, 60, 255};
  /// normal force arrows
  Color normalImpulse{0, 90, 178, 255};
  Color staticFriction{120, 40, 160, 255};  ///< friction impulse inside the cone (sticking)
  Color dynamicFriction{220, 20, 60, 255};  ///< friction impulse on the cone (sliding)
  /// velocity arrows
  Color velocity{20, 20, 20, 255};
  Color highlight{255, 0, 200, 255};  ///< the contact a trace frame is resolving
  /// all text
  Color text{20, 20, 20, 255};
  Color labelBackground{255, 255, 255, 200};  ///< behind the heads-up line and labels
  Color sheetBackground{70, 70, 70, 255};     ///< between thumbnails and panels
  Color sheetLabel{240, 240, 236, 255};       ///< the bars of step numbers and panel labels
  Color gaugeBackground{255, 255, 255, 255};  ///< the empty part of a friction gauge
  /// the legend strip
  Color legendBackground{236, 236, 230, 255};
};

/// What a frame shows besides the bodies; each can be turned off.
struct Overlays {
  bool rotationMarks = true;     ///< a line from a moving body's centre along its x axis
  bool contactPoints = true;     ///< a dot at each contact point
  bool contactNormals = true;    ///< a short line along each contact's normal, from A to B
  bool normalImpulses = true;    ///< the step's normal impulse at each point, as an arrow
  bool frictionImpulses = true;  ///< the step's friction impulse, coloured static or dynamic
  bool velocities = false;       ///< each dynamic body's velocity (always on in trace frames)
  bool headsUp = true;           ///< scene, solver, step, time and energy along the top
  bool frictionGauges = true;    ///< at each contact, how close friction is to its limit μ λn
  bool legend = true;  ///< a strip under the scene: the colours and arrows used, the force scale
};

/// Every tunable number of the frames, with its default; sizes in pixels unless a unit is given.
struct RenderSettings {
  /// what is drawn in which colour
  Palette colours;
  /// what is drawn besides the bodies
  Overlays overlays;

  /// m/s. A body in contact whose centre moves slower than this (and turns slower than
  /// restingAngularSpeed) counts as resting: about 1 mm per step at 60 Hz.
  double restingSpeed = 0.05;
  /// rad/s. The turning rate under which a body in contact can count as resting.
  double restingAngularSpeed = 0.1;
  /// m/s. A contact point whose surfaces slip past each other faster than this is sliding.
  double slidingSpeed = 0.02;

  /// m per N. Length of a force arrow: contact impulses λ are drawn as the forces λ/dt they
  /// stand for. 0 fits the scale per run (fitForceScale in frame.h) so the largest resting
  /// contact force is restingForceLength of the frame's height; the legend says the scale.
  double forceScale = 0.0;
  /// Fraction of the frame's height the largest resting contact force is drawn when the force
  /// scale is fitted: 0.15 of a 600-pixel frame is 90 pixels, 27 on a 240-pixel thumbnail.
  double restingForceLength = 0.15;
  /// m per N s. Length of the impulse arrow of one solver event in a trace frame. One event
  /// applies a fraction of a step's impulse (0.02 N s is typical for a 1 kg box): 0.4 m.
  double traceImpulseScale = 20.0;
  /// m per m/s. Length of a velocity arrow: a body falling at 10 m/s gets a 1 m arrow.
  double velocityScale = 0.1;
  /// Arrows longer than this are cut to it, so one large impulse cannot cover the frame.
  double maxArrowLength = 150.0;
  /// Arrows shorter than this are not drawn: they would be only a head.
  double minArrowLength = 2.0;
  /// Arrow sizes at textScale; a frame whose text is drawn larger (frameTextPerPixel) draws its
  /// arrows thicker in proportion: 1.8 times in an 800-pixel frame.
  double arrowWidth = 2.0;
  /// pixels, at textScale
  double arrowHeadLength = 7.0;
  /// pixels, at textScale
  double arrowHeadWidth = 6.0;

  /// pixels: bodies' edges
  double outlineWidth = 1.0;
  /// in pixels
  double rotationMarkWidth = 1.5;
  /// in pixels
  double contactPointRadius = 3.0;
  /// in pixels
  double contactNormalLength = 10.0;
  /// in pixels
  double contactNormalWidth = 1.0;
  /// Radius of the ring round the contact a trace frame is resolving.
  double highlightRadius = 9.0;
  /// pixels: the line width of the ring round the resolved contact
  double highlightWidth = 2.5;

  /// Font pixels per canvas pixel for labels on sheets and panels (stb_easy_font is ~7 px tall),
  /// and the least a frame's heads-up line and legend use.
  double textScale = 2.0;
  /// Font pixels per pixel of frame width for the heads-up lines and the legend, so text shrinks
  /// with the frame and a 240-pixel thumbnail of an 800-pixel frame still shows 7-pixel letters:
  /// 800 / 220 = 3.6 font pixels, 7 · 3.6 · 240 / 800 = 7.6 thumbnail pixels.
  double frameTextPerPixel = 1.0 / 220.0;

  /// Friction gauge: a bar of this length and thickness (pixels per font pixel of the frame's
  /// text, so it shrinks with the frame like the text), just under the middle of each contact,
  /// filled to |Σλt| / (μ Σλn). 8 × 3.6 ≈ 29 pixels long in an 800-pixel frame.
  double gaugeLength = 8.0;
  /// pixels per font pixel
  double gaugeThickness = 2.0;
  /// A gauge at or above 1 − this is on the limit (dynamic friction) and drawn in its colour.
  double gaugeLimitTolerance = 1e-3;
  /// Contacts with a normal force below this (N) have no gauge: the ratio means nothing there.
  double gaugeMinimumNormalForce = 1e-6;
  /// Space between text and the edge of its background.
  double textMargin = 4.0;

  /// Fraction of the image left empty on each side when the camera fits the scene.
  double fitPadding = 0.04;
  /// Heads-up lines the fitted view leaves room for: a run's frame has two, a traced step's
  /// frame three (the solver event under them).
  int headsUpLines = 2;
  /// How far a static body may stretch the fitted view beyond the dynamic bodies, as a fraction
  /// of their extent: a 1 km ground under a 20 m pyramid shows as the pyramid's floor.
  double staticFitReach = 0.25;

  /// Contact sheet: this many thumbnails, evenly spaced over the run, first and last included.
  int sheetThumbnails = 12;
  /// thumbnails per row
  int sheetColumns = 4;
  /// in pixels
  int sheetThumbnailWidth = 240;
  /// Thumbnails are at least this fraction of the frame's width, so the text of a wide frame (a
  /// comparison's panels side by side) reads as well as an 800-pixel frame's at 240 pixels; the
  /// sheet then has fewer columns, keeping its width near sheetColumns × sheetThumbnailWidth.
  double sheetThumbnailScale = 0.3;
  /// Gap between thumbnails, and between panels of a comparison.
  int spacing = 4;
};

}  // namespace impulse2d::render
