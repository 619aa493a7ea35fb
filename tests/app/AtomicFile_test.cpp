#include "Platform/Files/AtomicFile.h"

#include <gtest/gtest.h>
#include <limits.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::string TempDir(const std::string& name) {
    const std::string dir = ::testing::TempDir() + "psb_atomic_" + std::to_string(getpid()) + "_" + name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::vector<std::string> Entries(const std::string& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace

TEST(AtomicFile, TemporaryNamesStayWithinNameMaxAndBesideTheTarget) {
    const std::string longest(NAME_MAX, 'n');
    const std::string temp = TemporaryNameFor("dir/sub/" + longest, "abcdef");
    EXPECT_EQ(temp.rfind("dir/sub/.", 0), 0u) << temp;
    EXPECT_LE(temp.size() - std::string("dir/sub/").size(), std::size_t(NAME_MAX));
    EXPECT_EQ(TemporaryNameFor("s.csv", "abcdef"), ".s.csv.abcdef");
}

TEST(AtomicFile, TwoWritersOfOneTargetUseTheirOwnTemporaries) {
    const std::string dir = TempDir("two");
    AtomicFile a, b;
    std::string error;
    ASSERT_TRUE(a.Open(dir + "/t.csv", &error)) << error;
    ASSERT_TRUE(b.Open(dir + "/t.csv", &error)) << error;
    EXPECT_NE(a.TemporaryPath(), b.TemporaryPath());
    ASSERT_TRUE(a.Write("first\n", 6, &error));
    ASSERT_TRUE(b.Write("second\n", 7, &error));
    ASSERT_TRUE(a.Commit(&error)) << error;
    ASSERT_TRUE(b.Commit(&error)) << error;
    std::vector<std::uint8_t> bytes;
    ReadFailure failure;
    ASSERT_TRUE(ReadRegularFile(dir + "/t.csv", 100, &bytes, &failure, &error)) << error;
    EXPECT_EQ(std::string(bytes.begin(), bytes.end()), "second\n");  // the last rename wins, whole
    EXPECT_EQ(Entries(dir), std::vector<std::string>{"t.csv"});
}

TEST(AtomicFile, AbandonAndDestructionLeaveNothing) {
    const std::string dir = TempDir("abandon");
    std::string error;
    {
        AtomicFile f;
        ASSERT_TRUE(f.Open(dir + "/x.csv", &error)) << error;
        ASSERT_TRUE(f.Write("partial", 7, &error));
    }
    EXPECT_TRUE(Entries(dir).empty());
}

TEST(AtomicFile, RefusesToReplaceSymlinksAndSpecialFiles) {
    const std::string dir = TempDir("special");
    fs::create_symlink("/proc/self/fd/1", dir + "/link");
    ASSERT_EQ(mkfifo((dir + "/fifo").c_str(), 0600), 0);
    fs::create_directory(dir + "/dir");
    for (const char* name : {"link", "fifo", "dir"}) {
        std::string error;
        AtomicFile f;
        EXPECT_FALSE(f.Open(dir + "/" + name, &error)) << name;
        EXPECT_NE(error.find("not a regular file"), std::string::npos) << error;
    }
    EXPECT_TRUE(fs::is_symlink(dir + "/link"));
    EXPECT_EQ(Entries(dir), (std::vector<std::string>{"dir", "fifo", "link"}));
}

TEST(AtomicFile, ReadRegularFileRefusesFifosDevicesAndOversizedFiles) {
    const std::string dir = TempDir("read");
    ASSERT_EQ(mkfifo((dir + "/fifo").c_str(), 0600), 0);
    std::vector<std::uint8_t> bytes;
    ReadFailure failure = ReadFailure::None;
    std::string error;
    EXPECT_FALSE(ReadRegularFile(dir + "/fifo", 100, &bytes, &failure, &error));  // returns, does not block
    EXPECT_EQ(failure, ReadFailure::NotRegular);
    EXPECT_FALSE(ReadRegularFile("/dev/zero", 100, &bytes, &failure, &error));
    EXPECT_EQ(failure, ReadFailure::NotRegular);
    EXPECT_FALSE(ReadRegularFile(dir + "/none", 100, &bytes, &failure, &error));
    EXPECT_EQ(failure, ReadFailure::Missing);
    ASSERT_TRUE(WriteFileAtomic(dir + "/big", std::vector<std::uint8_t>(101, 7), &error)) << error;
    EXPECT_FALSE(ReadRegularFile(dir + "/big", 100, &bytes, &failure, &error));
    EXPECT_EQ(failure, ReadFailure::TooLarge);
    EXPECT_TRUE(ReadRegularFile(dir + "/big", 101, &bytes, &failure, &error)) << error;
    EXPECT_EQ(bytes.size(), 101u);
}
