// FindDuplicateKey: the first key given twice in one JSON object, with its object's path and the offset of its
// second occurrence; keys repeated across objects are not duplicates.
#include "Demos/Scenes/DuplicateKeys.h"

#include <gtest/gtest.h>

#include <string>

TEST(DuplicateKeys, NoneInAnObjectWithUniqueKeys) {
    DuplicateKey d;
    EXPECT_FALSE(FindDuplicateKey(R"({"a": 1, "b": {"a": 2}, "c": [{"a": 1}, {"a": 2}]})", &d));
    EXPECT_FALSE(FindDuplicateKey("[1, 2, 3]", &d));
    EXPECT_FALSE(FindDuplicateKey("{}", &d));
}

TEST(DuplicateKeys, TopLevelKeyWithItsOffset) {
    const std::string text = R"({"a": 1, "b": 2, "a": 3})";
    DuplicateKey d;
    ASSERT_TRUE(FindDuplicateKey(text, &d));
    EXPECT_EQ(d.objectPath, "");
    EXPECT_EQ(d.key, "a");
    EXPECT_EQ(d.offset, text.rfind("\"a\""));
}

TEST(DuplicateKeys, NestedObjectsAndArraysGiveTheirPath) {
    const std::string text = R"({"x": [0, {"y": [{}, {"k": 1, "k": 2}]}]})";
    DuplicateKey d;
    ASSERT_TRUE(FindDuplicateKey(text, &d));
    EXPECT_EQ(d.objectPath, "x[1].y[1]");
    EXPECT_EQ(d.key, "k");
    EXPECT_EQ(d.offset, text.rfind("\"k\""));
}

TEST(DuplicateKeys, TheFirstInDocumentOrderIsReported) {
    DuplicateKey d;
    ASSERT_TRUE(FindDuplicateKey(R"({"w": {"p": 1, "q": 1, "p": 2}, "w": {}})", &d));
    EXPECT_EQ(d.objectPath, "w");
    EXPECT_EQ(d.key, "p");
}

TEST(DuplicateKeys, EscapedKeysAreComparedAsWrittenAndLocatedAtTheirOpeningQuote) {
    // "\u0061" is "a": the same key in JSON.
    const std::string text = "{\"a\": 1,\n \"\\u0061\": 2}";
    DuplicateKey d;
    ASSERT_TRUE(FindDuplicateKey(text, &d));
    EXPECT_EQ(d.key, "a");
    EXPECT_EQ(d.offset, text.find("\"\\u0061\""));
    // A quote escaped inside a key does not move the reported start.
    const std::string quoted = R"({"q\"": 1, "q\"": 2})";
    ASSERT_TRUE(FindDuplicateKey(quoted, &d));
    EXPECT_EQ(d.key, "q\"");
    EXPECT_EQ(d.offset, quoted.rfind("\"q\\\"\""));
}

// The path is built only when a duplicate is reported, from every open level: deep inside arrays and objects it is
// the same path the scene-file messages use.
TEST(DuplicateKeys, DeepPathsAreBuiltFromEveryOpenLevel) {
    std::string text, path;
    for (int level = 0; level < 30; ++level) {
        text += R"({"x": 1, "a": [0, )";
        path += std::string(level ? "." : "") + "a[1]";
    }
    text += R"({"k": 1, "k": 2})";
    for (int level = 0; level < 30; ++level) text += "]}";
    DuplicateKey d;
    ASSERT_TRUE(FindDuplicateKey(text, &d));
    EXPECT_EQ(d.objectPath, path);
    EXPECT_EQ(d.key, "k");
    EXPECT_EQ(d.offset, text.rfind("\"k\""));
}
