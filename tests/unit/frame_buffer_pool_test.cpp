// Frame-sized buffers kept for the next frame, bounded, and given back on release.
#include "util/frame_buffer_pool.h"

#include <gtest/gtest.h>

#include <vector>

#include "util/image.h"

namespace taa {
namespace {

constexpr std::size_t kFrameBytes = std::size_t(8) << 20;

class FrameBufferPoolTest : public ::testing::Test {
 protected:
  void SetUp() override { releaseFrameBuffers(); }
  void TearDown() override { releaseFrameBuffers(); }
};

TEST_F(FrameBufferPoolTest, AFreedFrameBufferServesTheNextRequestOfItsSize) {
  void* first = takeFrameBuffer(kFrameBytes);
  giveBackFrameBuffer(first, kFrameBytes);
  void* second = takeFrameBuffer(kFrameBytes);
  EXPECT_EQ(second, first);
  giveBackFrameBuffer(second, kFrameBytes);
}

TEST_F(FrameBufferPoolTest, ABufferOfAnotherSizeIsNotHandedOut) {
  void* kept = takeFrameBuffer(kFrameBytes);
  giveBackFrameBuffer(kept, kFrameBytes);
  void* other = takeFrameBuffer(kFrameBytes + 4096);
  EXPECT_NE(other, kept);
  giveBackFrameBuffer(other, kFrameBytes + 4096);
}

TEST_F(FrameBufferPoolTest, ReleaseGivesTheKeptBuffersBack) {
  void* kept = takeFrameBuffer(kFrameBytes);
  giveBackFrameBuffer(kept, kFrameBytes);
  EXPECT_EQ(keptFrameBufferBytes(), kFrameBytes);
  releaseFrameBuffers();
  EXPECT_EQ(keptFrameBufferBytes(), 0u);
}

TEST_F(FrameBufferPoolTest, NothingIsKeptWhileFrameBuffersNotKeptLives) {
  void* before = takeFrameBuffer(kFrameBytes);
  giveBackFrameBuffer(before, kFrameBytes);
  ASSERT_EQ(keptFrameBufferBytes(), kFrameBytes);
  {
    FrameBuffersNotKept notKept;
    EXPECT_EQ(keptFrameBufferBytes(), 0u);  // what was kept is freed at once
    void* during = takeFrameBuffer(kFrameBytes);
    giveBackFrameBuffer(during, kFrameBytes);
    EXPECT_EQ(keptFrameBufferBytes(), 0u);
  }
  void* after = takeFrameBuffer(kFrameBytes);
  giveBackFrameBuffer(after, kFrameBytes);
  EXPECT_EQ(keptFrameBufferBytes(), kFrameBytes);  // kept again once it is gone
}

TEST_F(FrameBufferPoolTest, SmallBuffersAreNotKept) {
  void* small = takeFrameBuffer(4096);
  giveBackFrameBuffer(small, 4096);
  EXPECT_EQ(keptFrameBufferBytes(), 0u);
}

TEST_F(FrameBufferPoolTest, KeepsAtMostSixteenBuffers) {
  std::vector<void*> buffers;
  for (int i = 0; i < 20; ++i) buffers.push_back(takeFrameBuffer(kFrameBytes));
  for (void* b : buffers) giveBackFrameBuffer(b, kFrameBytes);
  EXPECT_EQ(keptFrameBufferBytes(), 16 * kFrameBytes);
  // The four given back first were freed; the newest sixteen are served, newest first.
  for (int i = 19; i >= 4; --i) {
    void* again = takeFrameBuffer(kFrameBytes);
    EXPECT_EQ(again, buffers[std::size_t(i)]) << i;
  }
  for (int i = 4; i < 20; ++i) giveBackFrameBuffer(buffers[std::size_t(i)], kFrameBytes);
}

TEST_F(FrameBufferPoolTest, ImagesOfAFrameSizeReuseTheSameMemoryZeroed) {
  const float* firstPixels = nullptr;
  {
    Image first(1024, 1024, 4);  // 16 MiB
    first.pixels[17] = 5.0f;
    firstPixels = first.pixels.data();
  }
  Image second(1024, 1024, 4);
  EXPECT_EQ(second.pixels.data(), firstPixels);
  EXPECT_EQ(second.pixels[17], 0.0f);  // a new image starts at zero, as a std::vector does
}

}  // namespace
}  // namespace taa
