// physics-sandbox: renders the book's demos headless to PNG frames (docs/app.md).
#include "Application/Program.h"

int main(int argc, char** argv) { return RunCommandLine(argc, argv); }
