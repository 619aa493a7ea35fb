#pragma once
// The demo panels, drawn from each demo's parameter table (Demos/Scenes/Parameters.h): the book's panel
// geometry, named once, and the one function that turns table entries into ImGui widgets.

#include "Demos/Scenes/Parameters.h"

/// The book's panel geometry in pixels (docs/book-reference.md §1.7): every panel is 370 wide; the
/// "Physics Demo" panel sits at (10, 10), a demo's panel at (400, 10), its help window at (400, 90).
namespace BookPanel {
constexpr float kWidth = 370.0f;
constexpr float kHeight = 75.0f;       ///< most panels, and "Physics Demo" with its three chapter buttons
constexpr float kTallHeight = 100.0f;  ///< Linear Impulse, Conservation Demo and the help window
constexpr float kListHeight = 145.0f;  ///< "Physics Demo" with the list box of every demo (select_all)
constexpr float kRowHeight = 21.0f;    ///< one text row the book does not have (a non-book model, a report)
/// Chapter 15's contact-solver row: 20 px since it was written, one less than kRowHeight; unifying them would
/// change the `--set solver=accumulated` frames by a pixel row.
constexpr float kSolverRowHeight = 20.0f;
constexpr float kMainX = 10.0f;   ///< "Physics Demo"
constexpr float kDemoX = 400.0f;  ///< the demo's panel and its help window
constexpr float kTop = 10.0f;
constexpr float kHelpTop = 90.0f;
constexpr float kListWidth = 350.0f;  ///< the demo list box's item width
}  // namespace BookPanel

/// Whether a demo panel may show ImGui's vertical scrollbar.
enum class PanelScrollbar { Hidden, Auto };

/// Begins a book-style demo panel (docs/book-reference.md §1.7): at (kDemoX, kTop) on its first frame,
/// kWidth wide and `height` px tall every frame, not resizable. Hidden drops the scrollbar ImGui 1.86 adds
/// when two framed rows fill the book's 75 px (1.50 showed none); the panels that never had the flag
/// (Chapter 14, the chapter 16 demos) keep Auto. Always pair with ImGui::End().
void BeginDemoPanel(const char* title, float height, PanelScrollbar scrollbar);

/// Draws the entries of `params` that have a widget, in table order, into the current ImGui window:
/// SameLine and the caption first, then the widget with its item width (consecutive widgets of one width
/// share one PushItemWidth, always popped: erratum 5.2-26). A slider or checkbox edit changes the value and
/// runs onChange only for appliesAtOnce widgets (the book's other widgets take effect on Reset); a button
/// runs its action; InputInt is clamped to the entry's range; a text row whose text() is "" is skipped.
void DrawParameterPanel(const ParameterSet& params);
