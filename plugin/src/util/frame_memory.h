// Keeping a long run's memory flat (docs/PERFORMANCE.md, "Soak"). For executables only: a
// library must not change its host's allocator.
#pragma once

namespace taa {

// Frame buffers (tens of MB, allocated and freed on the I/O threads every frame) are served by
// mmap and returned to the system when freed. glibc otherwise raises its mmap threshold after
// the first such buffer is freed and then carves later ones out of per-thread heaps, which
// fragment: peak RSS of a 1080p run crept up by 9% between frames 100 and 1000.
void keepFrameBuffersOutOfTheHeap();

}  // namespace taa
