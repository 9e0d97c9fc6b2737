// How many cores this process may run on.
#pragma once

namespace taa {

// The CPUs this process's affinity allows (a scheduler's cgroup or cpuset, as Slurm gives a
// task), not the machine's count; at least 1.
int usableCores();

}  // namespace taa
