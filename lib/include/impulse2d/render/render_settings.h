// Every colour, threshold and size the frames use, with its documented default, in one place.
// Sizes are in pixels unless the comment says metres; thresholds are in SI units.
#pragma once

#include "impulse2d/render/image.h"

namespace impulse2d::render {

/// Body colours by state (see BodyState in frame.h) and the colours of the overlays. Bodies and
/// arrows take the Okabe-Ito palette, whose eight colours stay distinguishable under the common
/// colour blindnesses; each arrow kind has a colour no body state has.
struct Palette {
  Color background{250, 250, 247, 255};       ///< the scene area
  Color staticBody{170, 170, 170, 255};       ///< grey: never moves
  Color flyingBody{86, 180, 233, 255};        ///< sky blue: no contact points
  Color restingBody{0, 158, 115, 255};        ///< bluish green: in contact and slow
  Color touchingBody{204, 121, 167, 255};     ///< reddish purple: in contact, moving, not sliding
  Color slidingBody{230, 159, 0, 255};        ///< orange: a contact point slides
  Color sleepingBody{200, 205, 215, 255};     ///< pale grey-blue: asleep
  Color outline{40, 40, 40, 255};             ///< bodies' and swatches' outlines
  Color rotationMark{20, 20, 20, 255};        ///< the line showing a body's turn
  Color contactPoint{255, 255, 255, 255};     ///< a white dot ringed in the outline colour
  Color contactNormal{60, 60, 60, 255};       ///< the line along a contact's normal
  Color normalForce{0, 114, 178, 255};        ///< Okabe-Ito blue
  Color staticFriction{100, 40, 150, 255};    ///< dark violet: friction inside the cone (sticking)
  Color dynamicFriction{213, 94, 0, 255};     ///< Okabe-Ito vermilion: friction on the cone
  Color frictionLimit{20, 20, 20, 255};       ///< the μN mark across a friction arrow
  Color load{0, 0, 0, 255};                   ///< applied loads (and weights), black
  Color velocity{90, 90, 90, 255};            ///< body and sliding velocities, dark grey
  Color arrowHalo{255, 255, 255, 200};        ///< under loads and velocities, to show over bodies
  Color highlight{204, 0, 153, 255};          ///< the contact a trace frame is resolving
  Color text{20, 20, 20, 255};                ///< all text
  Color stripBackground{236, 236, 230, 255};  ///< the heads-up and legend strips
  Color sheetBackground{70, 70, 70, 255};     ///< between thumbnails and panels
  Color sheetLabel{240, 240, 236, 255};       ///< the captions of thumbnails and panels
  Color gaugeBackground{255, 255, 255, 255};  ///< the empty part of a friction gauge
};

/// For handouts and slides: a white page, dark lines, the same state and arrow colours.
Palette printPalette();

/// What a frame shows besides the bodies; each can be turned off.
struct Overlays {
  bool rotationMarks = true;      ///< a line from a moving body's centre along its x axis
  bool contactPoints = true;      ///< a dot at each contact point
  bool contactNormals = false;    ///< a short line along each contact's normal, from A to B
  bool normalImpulses = true;     ///< the step's normal force at each point, as an arrow
  bool frictionImpulses = true;   ///< the friction force, static or dynamic, its limit μN marked
  bool loads = true;              ///< each applied load at its point, with its value
  bool weights = false;           ///< each dynamic body's weight m g at its centre
  bool slidingVelocities = true;  ///< where a contact slides, how fast its surfaces slip
  bool velocities = false;        ///< each dynamic body's velocity (always on in trace frames)
  bool headsUp = true;            ///< scene, solver, step, time and energy, in a strip on top
  bool frictionGauges = true;     ///< at each contact, how close friction is to its limit μ λn
  bool legend = true;  ///< a strip under the scene: the colours and arrows used, the force scale
};

/// How frames look: colours, overlays, thresholds and sizes.
struct RenderSettings {
  Palette colours;    ///< every colour
  Overlays overlays;  ///< what is drawn besides the bodies

  /// m/s. A body in contact whose centre moves slower than this (and turns slower than
  /// restingAngularSpeed) counts as resting: about 1 mm per step at 60 Hz.
  double restingSpeed = 0.05;
  /// rad/s. The turning rate under which a body in contact can count as resting.
  double restingAngularSpeed = 0.1;
  /// m/s. A contact point whose surfaces slip past each other faster than this is sliding.
  double slidingSpeed = 0.02;

  /// m per N. Length of a force arrow: contact impulses λ are drawn as the forces λ/dt they
  /// stand for, and loads and weights at the same scale. 0 fits the scale per run
  /// (fitForceScale in frame.h) so the largest resting contact force is restingForceLength of
  /// the scene's height; the legend's scale bar says the scale.
  double forceScale = 0.0;
  /// Fraction of the scene's height the largest resting contact force is drawn when the force
  /// scale is fitted: 0.15 of a 500-pixel scene is 75 pixels.
  double restingForceLength = 0.15;
  /// When the force scale is fitted, a dynamic body another rests on has its column's weight,
  /// shared by two contact points, drawn at most this fraction of its height: the arrows of its
  /// bottom contact end short of its top contact's, however tall the stack.
  double contactArrowRoom = 0.9;
  /// m per m/s. Length of a velocity arrow: a body falling at 10 m/s gets a 1 m arrow.
  double velocityScale = 0.1;
  /// Arrows longer than this fraction of the scene's height are cut to it, so one large impulse
  /// cannot cover the frame.
  double maxArrowLength = 0.3;
  /// Arrows shorter than this are not drawn: they would be only a head.
  double minArrowLength = 2.0;
  /// Arrow sizes per pixel of text size (textSize), so arrows thicken with the text.
  double arrowWidth = 0.16;
  double arrowHeadLength = 0.6;  ///< per text size
  double arrowHeadWidth = 0.5;   ///< per text size
  /// Contact force arrows start this many text sizes to the outside of their contact's middle
  /// along its tangent, so on a stack a box's normal arrows stand beside its edges, not on them.
  double contactArrowOffset = 0.25;
  /// Length of the μN mark across a friction arrow, per text size.
  double limitMarkLength = 0.9;

  /// Bodies' outlines, per text size (1.5 pixels in a 600-pixel frame, 2.7 in 1080), drawn over
  /// every body's fill so that touching bodies each keep their edge.
  double outlineWidth = 0.1;
  double swatchOutlineWidth = 1.0;  ///< pixels, of the legend's swatches and gauges' rims
  double rotationMarkWidth = 1.5;   ///< pixels
  /// The rotation mark runs from the centre towards the body's edge, at most this many text
  /// sizes long.
  double rotationMarkLength = 1.5;
  double contactPointRadius = 3.0;    ///< pixels
  double contactNormalLength = 10.0;  ///< pixels
  double contactNormalWidth = 1.0;    ///< pixels
  /// Radius of the ring round the contact a trace frame is resolving.
  double highlightRadius = 9.0;
  double highlightWidth = 2.5;  ///< pixels, of the ring

  /// Pixels. No text is drawn smaller than this font size (the em): DejaVu Sans at 12 px has
  /// 9-pixel capitals, readable on a projector and in print at 150 dpi.
  double minimumTextSize = 12.0;
  /// Text size per pixel of the frame's height: 15 px in a 600-pixel frame, 27 px in 1080.
  double textPerFrameHeight = 1.0 / 40.0;

  /// Friction gauge: a bar of this length (at most 0.8 of the contact's width) and thickness
  /// per text size, just under the middle of each contact, filled to |Σλt| / (μ Σλn).
  double gaugeLength = 2.0;
  double gaugeThickness = 0.45;  ///< per text size
  /// A gauge at or above 1 − this is on the limit (dynamic friction) and drawn in its colour.
  double gaugeLimitTolerance = 1e-3;
  /// Contacts with a normal force below this (N) have no gauge: the ratio means nothing there.
  double gaugeMinimumNormalForce = 1e-6;
  /// Space between text and the edge of its background, per text size.
  double textMargin = 0.3;

  /// m. Before the first step a world has no contacts yet; bodies whose surfaces are this close
  /// are drawn as touching (a box set down at rest is resting at step 0, not flying).
  double startingContactMargin = 1e-3;

  /// Fraction of the scene area left empty on each side when the camera fits the scene.
  double fitPadding = 0.04;
  /// Heads-up lines in the strip above the scene: a run's frame has two (scene and solver; step,
  /// time and energy).
  int headsUpLines = 2;
  /// A traced step's frame has six: those two, then the event and why it was chosen, its
  /// closing speeds, its impulse and its friction (trace.h).
  int traceHeadsUpLines = 6;
  /// How far a static body may stretch the fitted view beyond the dynamic bodies, as a fraction
  /// of their extent: a 1 km ground under a 20 m pyramid shows as the pyramid's floor.
  double staticFitReach = 0.25;

  /// Contact sheet: at most this many cells, first and last frame included, evenly spaced: as
  /// many as space them exactly, down to half this and one. A comparison's cell holds all its
  /// panels side by side, so its sheet has this many panels, in fewer cells.
  int sheetThumbnails = 12;
  /// Width of a sheet's scene (pixels): a cell, or one panel of a comparison's cell. The scene is
  /// drawn again at this size, not shrunk, so its text and arrows keep sheetTextSize.
  int sheetCellWidth = 480;
  /// Font size (pixels) of a sheet's captions, title, legend and scenes: readable at full size on
  /// a slide and on an A4 page.
  double sheetTextSize = 14.0;
  /// Comparison panels are laid out in the grid whose whole image is nearest this aspect ratio
  /// (a 16:9 slide).
  double slideAspect = 16.0 / 9.0;
  /// Gap between thumbnails, and between panels of a comparison.
  int spacing = 4;
};

}  // namespace impulse2d::render
