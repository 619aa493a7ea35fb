// CH14 scene benchmark: for 1,000 / 10,000 / 100,000 particles and each integrator, run `steps` fixed steps of
// 0.03 s from the book's spawn (seed 1) `repeats` times; report the median over repeats of the mean wall
// time per step, and how many particles end below the ground's top face (must be 0). Prints a Markdown table.
// A plain executable rather than Google Benchmark: the result is a table over (size x integrator) with a
// correctness column, and each run is a whole deterministic simulation, not a micro-loop to auto-repeat.
//
// Usage: psb-particles-bench [--steps N] [--repeats R] [--sizes a,b,c]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "Demos/Scenes/Ch14Scene.h"

namespace {

struct Options {
    int steps = 300;
    int repeats = 5;
    std::vector<int> sizes = {1000, 10000, 100000};
};

bool ParseArgs(int argc, char** argv, Options* o) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (i + 1 >= argc) return false;
        const char* value = argv[++i];
        if (arg == "--steps") {
            o->steps = std::atoi(value);
        } else if (arg == "--repeats") {
            o->repeats = std::atoi(value);
        } else if (arg == "--sizes") {
            o->sizes.clear();
            for (const char* p = value; *p != '\0';) {
                o->sizes.push_back(std::atoi(p));
                const char* comma = std::strchr(p, ',');
                if (comma == nullptr) break;
                p = comma + 1;
            }
        } else {
            return false;
        }
    }
    if (o->steps < 1 || o->repeats < 1 || o->sizes.empty()) return false;
    for (int s : o->sizes)
        if (s < 1) return false;
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    Options opt;
    if (!ParseArgs(argc, argv, &opt)) {
        std::fprintf(stderr, "usage: %s [--steps N>=1] [--repeats R>=1] [--sizes a,b,c]\n", argv[0]);
        return 2;
    }
    const float groundTop = Ch14Scene::Constraints()[0].position.y + Ch14Scene::Constraints()[0].size.y;
    std::printf("CH14 scene, dt 0.03 s, %d steps (%.1f s simulated), median of %d repeats\n\n", opt.steps,
                opt.steps * 0.03, opt.repeats);
    std::printf("| particles | integrator | ms/step (median) | min | max | below ground |\n");
    std::printf("|---:|---|---:|---:|---:|---:|\n");
    int failures = 0;
    for (int size : opt.sizes) {
        for (Integrator integrator : kAllIntegrators) {
            Ch14Params params;
            params.particleCount = size;
            params.integrator = integrator;
            std::vector<double> msPerStep;
            int below = 0;
            for (int r = 0; r < opt.repeats; ++r) {
                Ch14Scene scene(params);
                const auto start = std::chrono::steady_clock::now();
                for (int s = 0; s < opt.steps; ++s) scene.Step(scene.Params().dt);
                const auto end = std::chrono::steady_clock::now();
                msPerStep.push_back(std::chrono::duration<double, std::milli>(end - start).count() / opt.steps);
                below = 0;
                for (const Particle& p : scene.Particles())
                    if (!(p.GetPosition().y >= groundTop)) ++below;  // NaN counts as below
            }
            std::vector<double> sorted = msPerStep;
            std::sort(sorted.begin(), sorted.end());
            const double median = sorted.size() % 2 ? sorted[sorted.size() / 2]
                                                    : 0.5 * (sorted[sorted.size() / 2 - 1] + sorted[sorted.size() / 2]);
            std::printf("| %d | %s | %.4f | %.4f | %.4f | %d |\n", size, ToString(integrator), median, sorted.front(),
                        sorted.back(), below);
            std::fflush(stdout);
            if (below != 0) ++failures;
        }
    }
    return failures == 0 ? 0 : 1;
}
