#pragma once
// The one table of demos. The headless runner, the app tests and the benchmarks find a demo here by id.

#include <functional>
#include <memory>
#include <string>
#include <vector>

class DemoBase;

struct DemoInfo {
    std::string id;     ///< command-line id, e.g. "ch14"
    std::string title;  ///< the book's list title, e.g. "Chapter 14"
    std::function<std::unique_ptr<DemoBase>()> create;
};

/// Every demo, in the book's list order (raycast, ch14, collision-features, linear-impulse, momentum, ch15,
/// springs, ch16, joints).
const std::vector<DemoInfo>& AllDemos();
/// nullptr if no demo has that id.
const DemoInfo* FindDemo(const std::string& id);
