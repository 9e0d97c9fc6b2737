// Frame numbers are any int, INT_MIN and INT_MAX included. A loop `for (int f = first;
// f <= last; ++f)` never ends when last is INT_MAX, and `frame + 1` or `frame - K` overflows at
// the ends: a frame numbered INT_MAX made the window mode grow without bound (issue 25,
// defect 2). Frame arithmetic goes through these instead.
#pragma once

#include <climits>
#include <cmath>

namespace taa {

// first..last inclusive, iterated in 64 bits; empty when last < first.
class FrameSpan {
 public:
  class iterator {
   public:
    explicit iterator(long long frame) : frame_(frame) {}
    int operator*() const { return int(frame_); }
    iterator& operator++() {
      ++frame_;
      return *this;
    }
    bool operator!=(const iterator& other) const { return frame_ != other.frame_; }

   private:
    long long frame_;
  };

  FrameSpan(int first, int last) : first_(first), last_(last) {}
  iterator begin() const { return iterator(first_); }
  iterator end() const { return iterator(last_ < first_ ? first_ : (long long)last_ + 1); }

 private:
  int first_, last_;
};

// Whether `next` is the frame right after `frame` (false after INT_MAX).
constexpr bool isNextFrame(int frame, int next) { return (long long)frame + 1 == next; }

// `frame + offset` clamped to the int range: the farthest frame number that exists that way.
constexpr int offsetFrame(int frame, long long offset) {
  const long long moved = (long long)frame + offset;
  return moved > INT_MAX ? INT_MAX : moved < INT_MIN ? INT_MIN : int(moved);
}

// The frame number nearest a host's time, clamped to the int range (NaN: frame 0). A cast of
// a double beyond the range is undefined behaviour.
inline int nearestFrame(double time) {
  if (std::isnan(time)) return 0;
  if (time >= double(INT_MAX)) return INT_MAX;
  if (time <= double(INT_MIN)) return INT_MIN;
  return int(std::lround(time));
}

}  // namespace taa
