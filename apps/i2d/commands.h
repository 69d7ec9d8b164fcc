// The i2d commands. Each returns the exit code of success and throws on failure (failures.h).
#pragma once

#include "options.h"

namespace i2d {

/// `i2d run`: runs the scene, writes the CSV if asked, prints the summary.
int runCommand(const RunOptions& options);

/// `i2d run --error-vs-reference FILE`: the method watched by the reference
/// (error_vs_reference_run.cpp).
int errorVsReferenceRun(const RunOptions& options);

/// `i2d check`: validates the scene and prints what it holds.
int checkCommand(const CheckOptions& options);

/// `i2d presets`: lists every solver's presets, one line each.
int presetsCommand();

/// `i2d compare`: runs the scene once per panel and writes the panels side by side.
int compareCommand(const CompareOptions& options);

/// `i2d agree`: prints how far each method strays from Box2D on the scene.
int agreeCommand(const AgreeOptions& options);

}  // namespace i2d
