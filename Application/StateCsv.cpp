#include "Application/StateCsv.h"

#include <cstdio>

const char* StateCsvHeader() { return "frame,time,body,kind,x,y,z,vx,vy,vz\n"; }

void AppendStateRows(int frame, double time, const std::vector<BodyState>& bodies, std::string* out) {
    char row[512];
    for (const BodyState& b : bodies) {
        const int n = std::snprintf(row, sizeof row, "%d,%.9g,%d,%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", frame, time,
                                    b.body, b.kind, double(b.position.x), double(b.position.y), double(b.position.z),
                                    double(b.velocity.x), double(b.velocity.y), double(b.velocity.z));
        if (n > 0) out->append(row, std::size_t(n) < sizeof row ? std::size_t(n) : sizeof row - 1);
    }
}
