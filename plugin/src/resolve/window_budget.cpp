#include "resolve/window_budget.h"

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

}  // namespace taa
