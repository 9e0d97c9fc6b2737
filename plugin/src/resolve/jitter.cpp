#include "resolve/jitter.h"

#include <cmath>
#include <sstream>

namespace taa {

double radicalInverse(long long index, int base) {
  double result = 0.0;
  double digitWeight = 1.0 / base;
  for (long long i = index; i > 0; i /= base) {
    result += (i % base) * digitWeight;
    digitWeight /= base;
  }
  return result;
}

long long haltonIndex(int frame, const JitterOptions& options) {
  long long index = static_cast<long long>(frame) + options.indexOffset;
  if (options.period > 0) {
    long long wrapped = (index - 1) % options.period;
    if (wrapped < 0) wrapped += options.period;
    return wrapped + 1;
  }
  // Without a period a negative index (frames before the offset) mirrors to positive so that
  // pre-roll frames still get well-distributed offsets.
  return index < 0 ? -index : index;
}

glm::vec2 frameJitter(int frame, const JitterOptions& options) {
  if (options.source == JitterSource::None) return {0.0f, 0.0f};
  const long long i = haltonIndex(frame, options);
  return options.scale * glm::vec2(static_cast<float>(radicalInverse(i, 2) - 0.5),
                                   static_cast<float>(radicalInverse(i, 3) - 0.5));
}

glm::vec2 checkedJitter(glm::vec2 jitter, const std::string& source,
                        const ErrorContext& context) {
  const bool finite = std::isfinite(jitter.x) && std::isfinite(jitter.y);
  if (finite && std::abs(jitter.x) <= kMaxJitter && std::abs(jitter.y) <= kMaxJitter) {
    return jitter;
  }
  std::ostringstream what;  // prints nan, inf, -inf
  what << "jitter (" << jitter.x << ", " << jitter.y << ") from " << source;
  if (finite) {
    what << " is more than " << kMaxJitter << " pixel from the pixel centre: a jitter is a "
         << "sub-pixel offset in pixels (is it in another unit?)";
  } else {
    what << " is not a finite number of pixels";
  }
  throw Error(what.str(), context);
}

}  // namespace taa
