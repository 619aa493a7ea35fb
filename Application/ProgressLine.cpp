#include "Application/ProgressLine.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

ProgressLine::ProgressLine(const Options& o) : total(o.frames), tty(isatty(STDERR_FILENO) != 0), quiet(o.quiet) {
    if (o.quiet) return;
    if (o.progressEvery > 0)
        every = o.progressEvery;
    else if (tty)
        every = 10;  // cheap \r updates
    else if (o.frames >= 300)
        every = std::max(100, o.frames / 10);  // a long run in a log: about ten lines
}

void ProgressLine::Frame(int done, double simulated, double wall) {
    if (every == 0 || done % every != 0 || done == total) return;
    std::fprintf(stderr, "%sframe %d/%d  simulated %.2f s  wall %.1f s  %.1f fps%s", tty ? "\r" : "", done, total,
                 simulated, wall, wall > 0 ? done / wall : 0.0, tty ? "" : "\n");
    std::fflush(stderr);
    pending = tty;
}

void ProgressLine::End() {
    if (pending) std::fputc('\n', stderr);
    pending = false;
}

void ProgressLine::Note(const std::string& text) {
    if (quiet) return;
    End();
    std::fprintf(stderr, "physics-sandbox: %s\n", text.c_str());
    std::fflush(stderr);
}
