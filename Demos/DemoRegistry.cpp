#include "DemoRegistry.h"

#include "DemoBase.h"
// Each demo adds its include and one row below, in the book's list order.

const std::vector<DemoInfo>& AllDemos() {
    static const std::vector<DemoInfo> demos = {
        // {"raycast", "Raycast Demo", [] { return std::make_unique<RaycastDemo>(); }},
    };
    return demos;
}

const DemoInfo* FindDemo(const std::string& id) {
    for (const DemoInfo& d : AllDemos())
        if (d.id == id) return &d;
    return nullptr;
}
