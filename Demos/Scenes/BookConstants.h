#pragma once
// The book's numbers that several demos share, each named once. GL-free.

// The book's fixed physics step, kBookStep (0.03 s, not 1/30: erratum 5.2-16), is the engine's: the per-step
// factors it defines are converted from it (Physics/WorldSettings.h). It is the default step of every scene.
#include "Physics/WorldSettings.h"

/// World height in metres below which the particle demos (Chapter 14, Simple Springs, Joint Demo) put a
/// particle back: their Update sets y = -5 on any particle with y < -5 (docs/book-reference.md §2.1).
constexpr float kBookFloorY = -5.0f;
