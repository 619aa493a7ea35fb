// Runs a fuzz target's LLVMFuzzerTestOneInput once on each file named on the command line (a directory stands
// for the regular files in it, in name order), so the normal build replays the committed corpus and
// regressions without libFuzzer. A crash, sanitizer report or failed check in the target fails the run;
// so does finding no input at all. docs/testing.md "Fuzzing".

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

std::vector<std::string> InputFiles(const std::string& arg) {
    namespace fs = std::filesystem;
    std::vector<std::string> files;
    if (!fs::is_directory(arg)) return {arg};
    for (const fs::directory_entry& e : fs::directory_iterator(arg))
        if (e.is_regular_file()) files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

int main(int argc, char** argv) {
    int replayed = 0;
    for (int i = 1; i < argc; ++i) {
        for (const std::string& path : InputFiles(argv[i])) {
            std::ifstream in(path, std::ios::binary);
            if (!in) {
                std::fprintf(stderr, "replay: cannot read %s\n", path.c_str());
                return 1;
            }
            const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                                  std::istreambuf_iterator<char>());
            std::fprintf(stderr, "replay: %s (%zu bytes)\n", path.c_str(), bytes.size());
            LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
            ++replayed;
        }
    }
    std::printf("replay: %d inputs, no failure\n", replayed);
    return replayed > 0 ? 0 : 1;
}
