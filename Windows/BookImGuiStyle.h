#pragma once
// The look of the book's panels (ImGui 1.50's default style, docs/book-reference.md §1.7) on Dear ImGui 1.86.

/// StyleColorsClassic(), then the 1.50 default colours and sizes the reference frames show: window
/// background black at 70 %, red-brown buttons, rounded windows (radius 9), no borders. Call once after
/// ImGui::CreateContext().
void ApplyBookImGuiStyle();
