// The passes streamed from the GL thread to the writer band by band (resolve/pass_band_stream):
// the same bytes as the whole frame's sums give, whatever the bands and the writer's rows; and
// neither side is left waiting when the other fails.
#include "resolve/pass_band_stream.h"

#include <gtest/gtest.h>

#include <chrono>
#include <future>
#include <thread>
#include <vector>

#include "resolve/pass_plan.h"
#include "taa/error.h"

namespace taa {
namespace {

using namespace std::chrono_literals;

// Light x colour, colour, a normal, an ID (kept): two groups and a kept channel, half and float.
PassPlan testPlan() {
  const std::vector<std::string> names = {"L.DiffDir.R", "L.DiffCol.R", "L.Normal.X",
                                          "L.Normal.Y",  "L.Normal.Z",  "L.IndexOB.X"};
  const auto H = OIIO::TypeHalf, F = OIIO::TypeFloat;
  return planPasses(names, {H, H, F, F, F, F}, {});
}

// Rows [first, first + rows) of `whole` as an image `height` rows high (the rest 0).
Image rowsOf(const Image& whole, int first, int rows, int height) {
  Image band(whole.width, height, whole.channels);
  const std::size_t rowValues = std::size_t(whole.width) * std::size_t(whole.channels);
  for (int y = 0; y < rows; ++y) {
    for (std::size_t i = 0; i < rowValues; ++i) {
      band.pixels[std::size_t(y) * rowValues + i] =
          whole.pixels[std::size_t(first + y) * rowValues + i];
    }
  }
  return band;
}

std::vector<unsigned char> packedBytes(const io::ExtraChannels::Packed& packed,
                                       std::size_t pixelBytes, int rowsACall) {
  std::vector<unsigned char> bytes(std::size_t(packed.width) * packed.height * pixelBytes);
  const std::size_t width = std::size_t(packed.width);
  for (int y = 0; y < packed.height; y += rowsACall) {
    const int rows = std::min(rowsACall, packed.height - y);
    packed.rows(std::size_t(y) * width, std::size_t(rows) * width,
                &bytes[std::size_t(y) * width * pixelBytes], pixelBytes);
  }
  return bytes;
}

TEST(PassBandStream, StreamedPassesAreTheWholeFramesBytesWhateverTheBandsAndTheWritersRows) {
  const PassPlan plan = testPlan();
  constexpr int kWidth = 5, kHeight = 7, kBandRows = 3;  // bands of 3, 3 and 1 rows
  PassSums whole;
  float value = 0.25f;
  for (int g = 0; g < plan.groups(); ++g) {
    Image sums(kWidth, kHeight, 4);
    for (float& v : sums.pixels) {
      value += 0.37f;
      v = value - float(int(value));  // 0..1, varied
    }
    whole.groups.emplace_back(std::move(sums));
  }
  Image kept(kWidth, kHeight, plan.keptCount);
  for (float& v : kept.pixels) v = (value += 1.0f);
  std::size_t pixelBytes = 0;
  for (const OIIO::TypeDesc& format : plan.formats) pixelBytes += format.size();
  const std::vector<unsigned char> expected =
      packedBytes(finishPassesPacked(whole, kept, plan), pixelBytes, 2);

  for (int buffers : {1, 2}) {
    auto stream = std::make_shared<PassBandStream>(buffers);
    const int frame = 12;
    const io::ExtraChannels::Packed packed =
        finishPassesStreamed(stream, frame, kept, plan, kWidth, kHeight);
    // The GL's side on its own thread, band by band (taking a buffer waits for the writer).
    std::thread gl([&] {
      for (int first = 0; first < kHeight; first += kBandRows) {
        const int rows = std::min(kBandRows, kHeight - first);
        PassSums band = stream->take();
        band.groups.clear();
        for (const TypedImage& group : whole.groups) {
          band.groups.emplace_back(rowsOf(*group.floats(), first, rows, kBandRows));
        }
        stream->publish(frame, first, rows, std::move(band));
      }
    });
    // The writer's calls are two rows each: the second crosses from the first band into the next.
    const std::vector<unsigned char> streamed = packedBytes(packed, pixelBytes, 2);
    gl.join();
    stream->finished(frame);
    EXPECT_EQ(streamed, expected) << buffers << " buffers";
  }
}

TEST(PassBandStream, AWriterWaitingForAFrameWhoseResolveFailedGetsAnError) {
  PassBandStream stream(1);
  auto waiting = std::async(std::launch::async, [&] { return stream.band(3, 0).rows; });
  EXPECT_EQ(waiting.wait_for(50ms), std::future_status::timeout);  // nothing published yet
  stream.abandon(3);
  try {
    waiting.get();
    FAIL() << "a band of an abandoned frame was handed out";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the frame's passes were not resolved"),
              std::string::npos)
        << e.what();
  }
}

// Whether `future` is ready within a second; if not, `unblock` lets its thread go, so that a
// broken stream fails the test rather than hanging it (a future of std::async waits when it
// goes).
template <typename T, typename F>
bool readyWithin(std::future<T>& future, F unblock) {
  if (future.wait_for(1s) == std::future_status::ready) return true;
  unblock();
  future.wait();
  return false;
}

// Every published band's buffer back to the GL's side, by the writer's path (asking for a
// later frame's band, which that frame's abandonment answers): unblocks a waiting take().
void giveEveryBufferBack(PassBandStream& stream) {
  constexpr int kLater = 1 << 30;
  stream.abandon(kLater);
  try {
    stream.band(kLater, 0);
  } catch (const Error&) {
  }
}

TEST(PassBandStream, TheGlThreadWaitsForTheWriterAndNotForAWriteThatEnded) {
  PassBandStream stream(1);
  stream.publish(1, 0, 2, stream.take());
  // The one buffer is out: the next take waits until the writer moves past that band.
  auto next = std::async(std::launch::async, [&] { return stream.take(); });
  EXPECT_EQ(next.wait_for(50ms), std::future_status::timeout);
  EXPECT_EQ(stream.band(1, 1).firstRow, 0);
  EXPECT_EQ(next.wait_for(50ms), std::future_status::timeout);  // still reading that band
  // Asking for a row past it gives its buffer back, and waits for the band the GL fills with it.
  auto writer = std::async(std::launch::async, [&] { return stream.band(1, 2).firstRow; });
  if (!readyWithin(next, [&] { giveEveryBufferBack(stream); })) {
    stream.abandon(1);
    FAIL() << "the writer moved past the band and the GL still waits for its buffer";
  }
  EXPECT_EQ(writer.wait_for(50ms), std::future_status::timeout);
  stream.publish(1, 2, 2, next.get());
  ASSERT_TRUE(readyWithin(writer, [&] { stream.abandon(1); }));
  EXPECT_EQ(writer.get(), 2);

  // A write that failed before it took its bands: they go back, and later ones of its frame are
  // dropped as they come, so the GL thread finishing the frame never waits.
  stream.finished(1);
  PassBandStream failed(1);
  failed.publish(2, 0, 2, failed.take());
  failed.finished(2);
  for (int first = 2; first < 8; first += 2) {
    auto take = std::async(std::launch::async, [&] { return failed.take(); });
    ASSERT_TRUE(readyWithin(take, [&] { giveEveryBufferBack(failed); }))
        << "band at row " << first;
    failed.publish(2, first, 2, take.get());
  }
}

// The write-behind queue starts frame 3's write before it waits for frame 2's: frame 3's writer
// asking first must not take frame 2's band from its writer (a run once hung so).
TEST(PassBandStream, AWriteStartedBeforeTheOneBeforeItEndsTakesOnlyItsOwnFramesBands) {
  PassBandStream stream(1);
  stream.publish(2, 0, 4, stream.take());
  auto third = std::async(std::launch::async, [&] { return stream.band(3, 0).frame; });
  EXPECT_EQ(third.wait_for(50ms), std::future_status::timeout);  // frame 3 has no band yet
  auto second = std::async(std::launch::async, [&] { return stream.band(2, 0).frame; });
  if (!readyWithin(second, [&] { stream.publish(2, 0, 4, PassSums()); })) {
    stream.abandon(3);
    FAIL() << "frame 2's band went to frame 3's writer";
  }
  EXPECT_EQ(second.get(), 2);
  stream.finished(2);
  auto gl = std::async(std::launch::async, [&] { return stream.take(); });
  ASSERT_TRUE(readyWithin(gl, [&] { giveEveryBufferBack(stream); }));
  stream.publish(3, 0, 4, gl.get());
  ASSERT_TRUE(readyWithin(third, [&] { stream.abandon(3); }));
  EXPECT_EQ(third.get(), 3);
}

}  // namespace
}  // namespace taa
