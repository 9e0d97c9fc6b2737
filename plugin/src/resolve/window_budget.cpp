#include "resolve/window_budget.h"

#include <algorithm>

namespace taa {

double ringBytesPerPixel(const PassPlan* passes) {
  double bytes = 20.0;
  if (!passes) return bytes;
  for (bool half : passes->halfGroups) bytes += half ? 8.0 : 16.0;
  return bytes + 16.0 * double(passes->cryptomatte.size());
}

double windowRingBytes(int radius, double frameBytes) {
  return frameBytes * double(2 * radius + 2);
}

int windowRadiusWithinBudget(int asked, int nearRadius, double frameBytes, bool withPasses,
                             double budget) {
  int radius = asked;
  if (!withPasses) return radius;
  while (radius > nearRadius && radius > 0 && windowRingBytes(radius, frameBytes) > budget) {
    --radius;
  }
  return radius;
}

int windowRadiusWithinLayers(int asked, int largestLayers) {
  return std::max(0, std::min(asked, (largestLayers - 2) / 2));
}

}  // namespace taa
