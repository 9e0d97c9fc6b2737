// A window run's pass sums handed from the GL thread to the writer a band of rows at a time
// (issue 21): the frame's write starts once its colour is drawn and packs each band of passes
// as the GL finishes it, so the file work runs beside the pass draws, and a frame's sums are
// never held whole (350 MB for a 1080p render's every pass; a band of 256 rows is 86 MB).
// A few bands' buffers go round: the GL thread waits for one when the writer is that far
// behind (with one, the GL draws the next band while the writer packs the last). Frames are
// produced and consumed in order, one at a time.
#pragma once

#include <condition_variable>
#include <list>
#include <mutex>
#include <optional>
#include <vector>

#include "resolve/pass_plan.h"

namespace taa {

class PassBandStream {
 public:
  // Rows [firstRow, firstRow + rows) of `frame`'s sums (images `rows` or more rows high: row
  // firstRow of the frame is their first).
  struct Band {
    int frame = 0;
    int firstRow = 0;
    int rows = 0;
    PassSums sums;
  };

  explicit PassBandStream(int buffers);

  // The GL thread's side. A band's buffers to fill (empty the first times: the caller sizes
  // them): waits while every buffer is out, unless nothing takes them any more.
  PassSums take();
  // A filled band, after the frame's bands before it.
  void publish(int frame, int firstRow, int rows, PassSums sums);
  // `frame`'s bands not yet published will not come (its resolve failed): the writer waiting
  // for one gets an error instead of waiting for ever.
  void abandon(int frame);

  // The writer's side. The band of `frame` holding `row`, once published; the frame's bands
  // before it go back to the GL thread. Throws taa::Error when the frame was abandoned first.
  // A frame's write may start while the frame before it is still written (io's write-behind
  // starts a write before it waits for the one before): each takes its own frame's bands.
  const Band& band(int frame, int row);
  // The writer is done with `frame` (written, or failed): what is left of its bands goes back,
  // and bands of it or of earlier frames still to be published are dropped as they come.
  void finished(int frame);

  // Frees the buffers nobody holds (between frames: the next read may use the memory).
  void releaseIdle();

 private:
  // Gives back the buffers of the published bands `done` says are read (the lock held).
  template <typename Done>
  void recycle(Done done);

  std::mutex mutex_;
  std::condition_variable changed_;
  const int buffers_;
  int made_ = 0;
  std::vector<PassSums> free_;
  std::list<Band> published_;  // a list: a band read stays where it is as others go
  std::optional<int> abandoned_;        // the last frame abandoned (frames come in order)
  std::optional<int> finishedThrough_;  // frames up to this one are no longer read
};

}  // namespace taa
