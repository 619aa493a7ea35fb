// physics-sandbox: renders the book's demos headless to PNG frames (docs/app.md).
#include "Application/Runner.h"

int main(int argc, char** argv) { return RunCommandLine(argc, argv); }
