#include "EncodeQueue.h"

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

TEST(EncodeQueue, RunsJobsInOrderOnTheWorker) {
    for (bool threaded : {false, true}) {
        std::vector<int> order;  // touched by the worker only, read after Finish
        EncodeQueue queue(2, threaded);
        for (int i = 0; i < 50; ++i)
            ASSERT_TRUE(queue.Push([i, &order](std::string*) {
                order.push_back(i);
                return true;
            }));
        std::string error;
        ASSERT_TRUE(queue.Finish(&error));
        ASSERT_EQ(order.size(), 50u);
        for (int i = 0; i < 50; ++i) EXPECT_EQ(order[i], i);
    }
}

TEST(EncodeQueue, FirstFailureIsReportedAndLaterJobsAreDropped) {
    for (bool threaded : {false, true}) {
        std::atomic<int> ran{0};
        EncodeQueue queue(1, threaded);
        bool accepted = true;
        for (int i = 0; i < 20 && accepted; ++i)
            accepted = queue.Push([i, &ran](std::string* error) {
                ++ran;
                if (i == 3) {
                    *error = "job 3 failed";
                    return false;
                }
                if (i == 4) *error = "job 4 must not report";
                return i != 4;
            });
        std::string error;
        EXPECT_FALSE(queue.Finish(&error));
        EXPECT_EQ(error, "job 3 failed");
        EXPECT_LE(ran.load(), 5);  // at most the failing job plus one queued behind it (capacity 1)
        EXPECT_FALSE(queue.Push([](std::string*) { return true; }));
    }
}
