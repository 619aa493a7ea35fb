#include "Demos/DemoRegistry.h"

#include "Demos/CH14Demo.h"
#include "Demos/CH15Demo.h"
#include "Demos/CollisionFeature.h"
#include "Demos/ConservationOfMomentum.h"
#include "Demos/DemoBase.h"
#include "Demos/LinearImpulse.h"
#include "Demos/ParticleSceneDemo.h"
#include "Demos/RaycastDemo.h"
// Each demo adds its include and one row below, in the book's list order.

const std::vector<DemoInfo>& AllDemos() {
    static const std::vector<DemoInfo> demos = {
        {"raycast", "Raycast Demo", [] { return std::make_unique<RaycastDemo>(); }},
        {"ch14", "Chapter 14", [] { return std::make_unique<CH14Demo>(); }},
        {"collision-features", "Collision Features", [] { return std::make_unique<CollisionFeature>(); }},
        {"linear-impulse", "Linear Impulse", [] { return std::make_unique<LinearImpulse>(); }},
        {"momentum", "Conservation Of Momentum", [] { return std::make_unique<ConservationOfMomentum>(); }},
        {"ch15", "Chapter 15", [] { return std::make_unique<CH15Demo>(); }},
        {"springs", "Simple Springs", [] { return std::make_unique<SimpleSprings>(); }},
        {"ch16", "Chapter 16", [] { return std::make_unique<CH16Demo>(); }},
        {"joints", "Joint Demo", [] { return std::make_unique<JointDemo>(); }},
    };
    return demos;
}

const DemoInfo* FindDemo(const std::string& id) {
    for (const DemoInfo& d : AllDemos())
        if (d.id == id) return &d;
    return nullptr;
}
