#pragma once
// The book's numbers that several demos share, each named once. GL-free.

/// The book's fixed physics step in seconds: its loop steps GetFixedFPS() / 1000 = 0.03 s, not 1/30
/// (docs/book-reference.md §1.2, erratum 5.2-16). The default step of every scene and demo.
constexpr float kBookStep = 0.03f;

/// World height in metres below which the particle demos (Chapter 14, Simple Springs, Joint Demo) put a
/// particle back: their Update sets y = -5 on any particle with y < -5 (docs/book-reference.md §2.1).
constexpr float kBookFloorY = -5.0f;
