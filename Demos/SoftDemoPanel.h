#pragma once
// Shared by the chapter 16 demos (Demos/ParticleSceneDemo.h: SimpleSprings, CH16Demo, JointDemo): the light, the panel
// with the book's size, and the stability report in place of garbage.

#include <vector>

#include "Demos/DemoBase.h"
#include "Physics/Geometry/Geometry3D.h"
#include "Physics/Integrator.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/StabilityMonitor.h"

/// Light of the chapter 16 demos' Render: (0, 1, 0, 0), straight down (docs/book-reference.md §1.5).
constexpr vec3 kSoftDemoLight{0.0f, 1.0f, 0.0f};

/// The demo panel at (400, 10), 370 wide and 75 high as the book, drawn from the table `params`; one text
/// row taller for each of: a non-book integrator or dt (read-only here; set with --set integrator=... dt=...),
/// an instability report (in red); `extraHeight` (px) more for rows of the table the book does not have (the
/// auto model's, DemoBase::AutoModelRowHeight).
void DrawSoftDemoPanel(const char* title, const ParameterSet& params, Integrator integrator, float dt,
                       const StabilityMonitor& monitor, float extraHeight = 0.0f);
/// Prints the monitor's report to stderr the first time it fails (*reported latches until the monitor is
/// stable again, i.e. after a reset).
void ReportOnce(const StabilityMonitor& monitor, const char* demo, bool* reported);
/// Draws the whole system while monitor is stable; once the scene has blown up, only its constraints
/// (constraint 0 blue, the rest green): no garbage, the report is on the panel.
void RenderSystemOrConstraints(const PhysicsSystem& system, const StabilityMonitor& monitor);
