/* Times loading an OpenFX bundle binary the way a host does (dlopen, then
 * OfxGetNumberOfPlugins), once, in this fresh process: run it several times
 * (docs/OFX.md). Usage: taa_bundle_load_time BUNDLE_BINARY */
#include <dlfcn.h>
#include <stdio.h>
#include <time.h>

int main(int argc, char** argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: %s BUNDLE_BINARY\n", argv[0]);
    return 2;
  }
  struct timespec start, end;
  clock_gettime(CLOCK_MONOTONIC, &start);
  void* library = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
  if (!library) {
    fprintf(stderr, "%s\n", dlerror());
    return 1;
  }
  int (*count)(void) = (int (*)(void))dlsym(library, "OfxGetNumberOfPlugins");
  if (!count) {
    fprintf(stderr, "no OfxGetNumberOfPlugins in %s\n", argv[1]);
    return 1;
  }
  const int plugins = count();
  clock_gettime(CLOCK_MONOTONIC, &end);
  printf("%d plugin(s) loaded in %.3f s\n", plugins,
         (double)(end.tv_sec - start.tv_sec) + (double)(end.tv_nsec - start.tv_nsec) * 1e-9);
  return 0;
}
