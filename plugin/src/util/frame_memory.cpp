#include "util/frame_memory.h"

#include <malloc.h>

namespace taa {

void keepFrameBuffersOutOfTheHeap() {
  // A fixed threshold also turns glibc's dynamic adjustment off. 1 MiB: a frame's rows are
  // far above it, the small objects of everything else far below.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
}

}  // namespace taa
