#include "Platform/EncodeQueue.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

TEST(EncodeQueue, RunsJobsInOrderOnTheWorker) {
    for (bool threaded : {false, true}) {
        std::vector<int> order;                  // touched by the worker only, read after Finish
        std::vector<std::thread::id> ranOn(50);  // likewise
        EncodeQueue queue(2, threaded);
        for (int i = 0; i < 50; ++i)
            ASSERT_TRUE(queue.Push([i, &order, &ranOn](std::string*) {
                order.push_back(i);
                ranOn[i] = std::this_thread::get_id();
                return true;
            }));
        std::string error;
        ASSERT_TRUE(queue.Finish(&error));
        ASSERT_EQ(order.size(), 50u);
        for (int i = 0; i < 50; ++i) EXPECT_EQ(order[i], i);
        // Threaded: every job on one worker thread, not the producer's; unthreaded: inline in Push.
        for (int i = 0; i < 50; ++i) {
            if (threaded) {
                EXPECT_NE(ranOn[i], std::this_thread::get_id()) << "job " << i << " ran on the producer";
                EXPECT_EQ(ranOn[i], ranOn[0]) << "job " << i;
            } else {
                EXPECT_EQ(ranOn[i], std::this_thread::get_id()) << "job " << i;
            }
        }
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
        EXPECT_GE(ran.load(), 4);  // jobs 0..3 all ran: the failure is reached
        EXPECT_LE(ran.load(), 5);  // at most the failing job plus one queued behind it (capacity 1)
        if (!threaded) {
            EXPECT_EQ(ran.load(), 4);  // inline: Push refuses job 4 once job 3 failed
        }
        EXPECT_FALSE(queue.Push([](std::string*) { return true; }));
    }
}
