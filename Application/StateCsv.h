#pragma once
// The --state CSV: one row per body per frame, header first. Floats are printed with 9 significant digits,
// which round-trips every float exactly, so two identical runs give identical files.

#include <string>
#include <vector>

#include "Demos/DemoBase.h"

/// "frame,time,body,kind,x,y,z,vx,vy,vz\n"; with `errorEstimate` one more column, ",error_estimate" (an auto
/// model's running estimate, docs/model-choice.md).
const char* StateCsvHeader(bool errorEstimate = false);
/// Appends the rows of one frame to *out. time is the simulated time of the frame in seconds. With an
/// errorEstimate (the auto model's running estimate, in its budget's unit) every row ends with it.
void AppendStateRows(int frame, double time, const std::vector<BodyState>& bodies, std::string* out,
                     const double* errorEstimate = nullptr);
