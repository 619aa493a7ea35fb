#pragma once
// The one shape of a simulated scene (docs/app.md, "Steps"): every GL-free scene a demo, a test or a benchmark
// drives implements it. The scripted showcases (RaycastScene, CollisionFeatureScene) have no world and no step, so
// they are not scenes in this sense (their demos' World() is nullptr).

#include "Demos/Scenes/Parameters.h"
#include "Physics/PhysicsSystem.h"

class Scene {
public:
    Scene() = default;
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;
    virtual ~Scene() = default;

    /// Rebuilds the world from the current (panel) values: the book's ResetDemo. The step count restarts at 0.
    virtual void Reset() = 0;
    /// One physics step of dt seconds. Returns whether the scene goes on: false once it has stopped (its
    /// stability monitor failed, or the world refused to go on: PhysicsSystem::StopReason) and for a dt it refuses
    /// (<= 0, non-finite), in which case nothing was stepped. A paused scene goes on (true).
    virtual bool Step(float dt) = 0;
    /// The world the scene steps.
    virtual PhysicsSystem& System() = 0;
    virtual const PhysicsSystem& System() const = 0;
    /// Registers the scene's panel values and actions on *set (the one table behind --set, --params and the
    /// panel). The values are bound to where they take effect: the world's settings, or the panel values a Reset
    /// reads.
    virtual void AddParameters(ParameterSet* set) = 0;
    /// The physics step (s) the scene asks its host for; 0 takes the host's (`--dt`). The host runs whole steps
    /// of it (DemoBase::PhysicsStep).
    virtual float PhysicsStep() const = 0;
};
