#include "pipeline/bounded_queue.h"

#include <atomic>
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

namespace corridor {
namespace {

using std::chrono::milliseconds;

TEST(BoundedQueueTest, FirstInFirstOut) {
  BoundedQueue<int> queue(3);
  EXPECT_TRUE(queue.Push(1));
  EXPECT_TRUE(queue.Push(2));
  EXPECT_TRUE(queue.Push(3));
  EXPECT_EQ(queue.high_water(), 3u);
  EXPECT_EQ(*queue.Pop(), 1);
  EXPECT_EQ(*queue.Pop(), 2);
  EXPECT_TRUE(queue.Push(4));
  EXPECT_EQ(*queue.Pop(), 3);
  EXPECT_EQ(*queue.Pop(), 4);
  EXPECT_EQ(queue.high_water(), 3u);
}

TEST(BoundedQueueTest, CapacityIsAtLeastOne) {
  EXPECT_EQ(BoundedQueue<int>(0).capacity(), 1u);
  EXPECT_EQ(BoundedQueue<int>(5).capacity(), 5u);
}

TEST(BoundedQueueTest, PushWaitsWhileFull) {
  BoundedQueue<int> queue(2);
  ASSERT_TRUE(queue.Push(1));
  ASSERT_TRUE(queue.Push(2));
  std::atomic<bool> pushed{false};
  std::thread producer([&] {
    queue.Push(3);
    pushed = true;
  });
  std::this_thread::sleep_for(milliseconds(50));
  EXPECT_FALSE(pushed);  // Still blocked: the queue is full.
  EXPECT_EQ(*queue.Pop(), 1);
  producer.join();
  EXPECT_TRUE(pushed);
  EXPECT_EQ(*queue.Pop(), 2);
  EXPECT_EQ(*queue.Pop(), 3);
  EXPECT_EQ(queue.high_water(), 2u);
}

TEST(BoundedQueueTest, CloseWakesABlockedPopAndABlockedPush) {
  BoundedQueue<int> empty(1);
  std::thread consumer([&] { EXPECT_FALSE(empty.Pop().has_value()); });
  std::this_thread::sleep_for(milliseconds(20));
  empty.Close();
  consumer.join();

  BoundedQueue<int> full(1);
  ASSERT_TRUE(full.Push(1));
  std::thread producer([&] { EXPECT_FALSE(full.Push(2)); });
  std::this_thread::sleep_for(milliseconds(20));
  full.Close();
  producer.join();
}

TEST(BoundedQueueTest, PopDrainsWhatIsLeftAfterClose) {
  BoundedQueue<int> queue(4);
  queue.Push(7);
  queue.Push(8);
  queue.Close();
  EXPECT_FALSE(queue.Push(9));  // Dropped.
  EXPECT_EQ(*queue.Pop(), 7);
  EXPECT_EQ(*queue.Pop(), 8);
  EXPECT_FALSE(queue.Pop().has_value());
}

TEST(BoundedQueueTest, ManyItemsBetweenTwoThreadsArriveInOrder) {
  constexpr int kItems = 20000;
  BoundedQueue<int> queue(3);
  std::thread producer([&] {
    for (int i = 0; i < kItems; ++i) queue.Push(i);
    queue.Close();
  });
  int expected = 0;
  while (auto item = queue.Pop()) {
    ASSERT_EQ(*item, expected);
    ++expected;
  }
  producer.join();
  EXPECT_EQ(expected, kItems);
  EXPECT_LE(queue.high_water(), 3u);
}

}  // namespace
}  // namespace corridor
