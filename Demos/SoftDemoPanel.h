#pragma once
// Shared by the chapter 16 demos (SimpleSprings, CH16Demo, JointDemo): the light, the panel frame with the
// book's size, and the stability report in place of garbage.

#include <vector>

#include "Demos/DemoBase.h"
#include "Physics/Geometry/Geometry3D.h"
#include "Physics/Integrator.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/StabilityMonitor.h"

/// Light of the chapter 16 demos' Render: (0, 1, 0, 0), straight down (docs/book-reference.md §1.5).
constexpr vec3 kSoftDemoLight{0.0f, 1.0f, 0.0f};

/// Opens the demo panel at (400,10), width 370, height 75 as the book; one text row taller for each of:
/// a non-book integrator or dt, an instability report.
void BeginSoftPanel(const char* title, Integrator integrator, float dt, const StabilityMonitor& monitor);
/// Writes those extra rows (read-only; they are set with --set integrator=... dt=...) and ends the panel.
void EndSoftPanel(const ParameterSet& params, const StabilityMonitor& monitor);
/// Prints the monitor's report to stderr the first time it fails (*reported latches).
void ReportOnce(const StabilityMonitor& monitor, const char* demo, bool* reported);
/// Draws the whole system while monitor is stable; once the scene has blown up, only its constraints
/// (constraint 0 blue, the rest green): no garbage, the report is on the panel.
void RenderSystemOrConstraints(const PhysicsSystem& system, const StabilityMonitor& monitor);
