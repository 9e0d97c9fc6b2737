// Frame-sized buffers kept for the next frame, bounded, and given back on release.
#include "util/frame_buffer_pool.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "util/address_sanitizer.h"
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

TEST_F(FrameBufferPoolTest, KeepsAtMostThirtyTwoBuffers) {
  std::vector<void*> buffers;
  for (int i = 0; i < 36; ++i) buffers.push_back(takeFrameBuffer(kFrameBytes));
  for (void* b : buffers) giveBackFrameBuffer(b, kFrameBytes);
  EXPECT_EQ(keptFrameBufferBytes(), 32 * kFrameBytes);
  // The four given back first were freed; the newest thirty-two are served, newest first.
  for (int i = 35; i >= 4; --i) {
    void* again = takeFrameBuffer(kFrameBytes);
    EXPECT_EQ(again, buffers[std::size_t(i)]) << i;
  }
  for (int i = 4; i < 36; ++i) giveBackFrameBuffer(buffers[std::size_t(i)], kFrameBytes);
}

// A run whose peak is its bar (every pass) keeps its frames' buffers for the next frame even
// where a resolver with passes says to keep none; once it ends, the resolver's word holds.
TEST_F(FrameBufferPoolTest, KeptFrameToFrameKeepsBuffersWhereNotKeptWouldNot) {
  FrameBuffersNotKept notKept;
  {
    FrameBuffersKeptFrameToFrame frameToFrame;
    void* first = takeFrameBuffer(kFrameBytes);
    giveBackFrameBuffer(first, kFrameBytes);
    EXPECT_EQ(keptFrameBufferBytes(), kFrameBytes);
    EXPECT_EQ(takeFrameBuffer(kFrameBytes), first);
    giveBackFrameBuffer(first, kFrameBytes);
  }
  EXPECT_EQ(keptFrameBufferBytes(), 0u);  // freed with the guard
  giveBackFrameBuffer(takeFrameBuffer(kFrameBytes), kFrameBytes);
  EXPECT_EQ(keptFrameBufferBytes(), 0u);
}

// nextFrame() frees what lay idle through a whole frame (given back before the last call and
// not taken since); a buffer taken again and given back within the frame stays.
TEST_F(FrameBufferPoolTest, NextFrameFreesTheBuffersIdleThroughAWholeFrame) {
  FrameBuffersKeptFrameToFrame frameToFrame;
  void* reused = takeFrameBuffer(kFrameBytes);
  void* idle = takeFrameBuffer(2 * kFrameBytes);
  giveBackFrameBuffer(reused, kFrameBytes);
  giveBackFrameBuffer(idle, 2 * kFrameBytes);
  frameToFrame.nextFrame();  // both were given back in this frame: kept
  EXPECT_EQ(keptFrameBufferBytes(), 3 * kFrameBytes);
  ASSERT_EQ(takeFrameBuffer(kFrameBytes), reused);
  giveBackFrameBuffer(reused, kFrameBytes);
  frameToFrame.nextFrame();  // `idle` was not taken again
  EXPECT_EQ(keptFrameBufferBytes(), kFrameBytes);
  EXPECT_EQ(takeFrameBuffer(kFrameBytes), reused);
  giveBackFrameBuffer(reused, kFrameBytes);
}

TEST_F(FrameBufferPoolTest, ABufferFreedWhileFreedAtOnceLivesIsNotKept) {
  void* kept = takeFrameBuffer(kFrameBytes);
  giveBackFrameBuffer(kept, kFrameBytes);
  void* freed = takeFrameBuffer(2 * kFrameBytes);
  {
    FrameBuffersFreedAtOnce atOnce;
    giveBackFrameBuffer(freed, 2 * kFrameBytes);
  }
  EXPECT_EQ(keptFrameBufferBytes(), kFrameBytes);  // what was kept before stays
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

#if !TAA_ADDRESS_SANITIZER  // buffers stay on the heap there
// The mapping that starts at `address` as /proc/self/smaps describes it: its size in KiB and
// its VmFlags ("hg": advised to use huge pages); size 0 if there is none.
struct Mapping {
  std::size_t kib = 0;
  std::string flags;
};
Mapping mappingAt(const void* address) {
  std::ifstream smaps("/proc/self/smaps");
  std::ostringstream start;
  start << std::hex << reinterpret_cast<std::uintptr_t>(address) << '-';
  Mapping found;
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    const bool header = line.find('-') != std::string::npos && line.find(':') > line.find(' ');
    if (header) inside = line.rfind(start.str(), 0) == 0;
    if (!inside) continue;
    if (line.rfind("Size:", 0) == 0) found.kib = std::stoul(line.substr(5));
    if (line.rfind("VmFlags:", 0) == 0) found.flags = line.substr(8) + " ";
  }
  return found;
}

bool hugePagesOnRequest() {
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(mode, modes);
  return !modes.empty() && modes.find("[never]") == std::string::npos;
}

// A buffer the pool will not keep (every frame's are new) is mapped in whole huge pages from a
// huge page's boundary, advised to use them (one page fault a 2 MiB page, not 512), and
// unmapped when freed.
TEST_F(FrameBufferPoolTest, ABufferNotKeptIsMappedInHugePagesAndUnmappedWhenFreed) {
  const std::size_t bytes = (std::size_t(3) << 20) + 5;
  FrameBuffersNotKept notKept;
  auto* buffer = static_cast<unsigned char*>(takeFrameBuffer(bytes));
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(buffer) % (std::size_t(2) << 20), 0u);
  buffer[0] = 1;
  buffer[bytes - 1] = 2;
  const Mapping mapped = mappingAt(buffer);
  EXPECT_EQ(mapped.kib, std::size_t(4) << 10);  // 3 MiB and 5 bytes: two huge pages
  if (hugePagesOnRequest()) {
    EXPECT_NE(mapped.flags.find(" hg "), std::string::npos) << mapped.flags;
  }
  giveBackFrameBuffer(buffer, bytes);
  EXPECT_EQ(mappingAt(buffer).kib, 0u);
}

// A buffer the pool keeps faults once however many frames reuse it, and runs that keep theirs
// were slower with huge pages: it is left to ordinary pages.
TEST_F(FrameBufferPoolTest, ABufferThePoolKeepsIsNotAdvisedToUseHugePages) {
  auto* buffer = static_cast<unsigned char*>(takeFrameBuffer(kFrameBytes));
  buffer[0] = 1;
  const Mapping mapped = mappingAt(buffer);
  EXPECT_GE(mapped.kib, kFrameBytes >> 10);
  EXPECT_EQ(mapped.flags.find(" hg "), std::string::npos) << mapped.flags;
  giveBackFrameBuffer(buffer, kFrameBytes);
}
#endif

}  // namespace
}  // namespace taa
