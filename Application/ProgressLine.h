#pragma once
// The headless run's progress on stderr (docs/app.md "Command line": a \r line on a terminal, about ten lines in a
// log for long runs, --progress N to force it) and the notes printed between its lines.

#include <string>

#include "Application/CommandLine.h"

class ProgressLine {
public:
    explicit ProgressLine(const Options& o);
    /// After `done` frames: a line every `every` frames (none for the last: the summary follows), with the physics
    /// time reached (s) and the wall time so far (s).
    void Frame(int done, double simulated, double wall);
    /// Ends a pending \r line.
    void End();
    /// A line between progress lines (the auto model's switches): on its own line, quiet under --quiet.
    void Note(const std::string& text);

private:
    int total;
    bool tty;
    bool quiet;
    int every = 0;
    bool pending = false;
};
