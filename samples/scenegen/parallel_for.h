// Runs a loop body over [0, count) on a few threads, handing out indices one at a time so
// uneven rows (objects cost more than background) balance themselves.
#pragma once

#include <functional>

namespace taa::scenes {

// threads <= 0: one per hardware thread. `body` must be safe to call concurrently.
void parallelFor(int count, int threads, const std::function<void(int)>& body);

}  // namespace taa::scenes
