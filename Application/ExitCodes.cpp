#include "Application/ExitCodes.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

int FinishStdout() {
    if (std::fflush(stdout) == 0 && !std::ferror(stdout)) return kExitOk;
    std::fprintf(stderr, "physics-sandbox: cannot write to standard output: %s\n", std::strerror(errno));
    return kExitFailure;
}
