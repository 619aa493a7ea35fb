#include "Application/StateCsv.h"

#include <cstdio>

const char* StateCsvHeader(bool errorEstimate) {
    return errorEstimate ? "frame,time,body,kind,x,y,z,vx,vy,vz,error_estimate\n"
                         : "frame,time,body,kind,x,y,z,vx,vy,vz\n";
}

void AppendStateRows(int frame, double time, const std::vector<BodyState>& bodies, std::string* out,
                     const double* errorEstimate) {
    char row[512];
    char estimate[40] = "";
    if (errorEstimate != nullptr) std::snprintf(estimate, sizeof estimate, ",%.9g", *errorEstimate);
    for (const BodyState& b : bodies) {
        const int n = std::snprintf(row, sizeof row, "%d,%.9g,%d,%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g%s\n", frame, time,
                                    b.body, b.kind, double(b.position.x), double(b.position.y), double(b.position.z),
                                    double(b.velocity.x), double(b.velocity.y), double(b.velocity.z), estimate);
        if (n > 0) out->append(row, std::size_t(n) < sizeof row ? std::size_t(n) : sizeof row - 1);
    }
}
