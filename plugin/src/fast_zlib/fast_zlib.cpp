#include "fast_zlib/fast_zlib.h"

#include <dlfcn.h>
#include <libdeflate.h>
#include <zlib.h>

#include <array>
#include <memory>

namespace taa::fast_zlib {
namespace {

using Compress2 = int (*)(Bytef*, uLongf*, const Bytef*, uLong, int);
using Uncompress = int (*)(Bytef*, uLongf*, const Bytef*, uLong);

// zlib's own definitions, behind this unit's in the lookup order.
Compress2 zlibCompress2() {
  static const auto next = reinterpret_cast<Compress2>(dlsym(RTLD_NEXT, "compress2"));
  return next;
}
Uncompress zlibUncompress() {
  static const auto next = reinterpret_cast<Uncompress>(dlsym(RTLD_NEXT, "uncompress"));
  return next;
}

struct CompressorDeleter {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};
struct DecompressorDeleter {
  void operator()(libdeflate_decompressor* d) const { libdeflate_free_decompressor(d); }
};

// libdeflate's (de)compressors are not thread-safe; OpenEXR calls from its own worker threads
// and taatool's readers and writers, so each thread keeps its own, one per level.
libdeflate_compressor* compressorFor(int level) {
  thread_local std::array<std::unique_ptr<libdeflate_compressor, CompressorDeleter>, 10> byLevel;
  auto& compressor = byLevel[std::size_t(level)];
  if (!compressor) compressor.reset(libdeflate_alloc_compressor(level));
  return compressor.get();
}

libdeflate_decompressor* decompressor() {
  thread_local std::unique_ptr<libdeflate_decompressor, DecompressorDeleter> instance(
      libdeflate_alloc_decompressor());
  return instance.get();
}

}  // namespace

bool active() {
  return dlsym(RTLD_DEFAULT, "compress2") == reinterpret_cast<void*>(&::compress2) &&
         dlsym(RTLD_DEFAULT, "uncompress") == reinterpret_cast<void*>(&::uncompress) &&
         zlibCompress2() && zlibUncompress();
}

std::string description() {
  return active() ? std::string("libdeflate ") + LIBDEFLATE_VERSION_STRING +
                        " (zlib's compress2/uncompress, used by OpenEXR's ZIP codec)"
                  : std::string("zlib ") + zlibVersion();
}

}  // namespace taa::fast_zlib

// Visible whatever the build's default visibility: the dynamic linker must see them.
#define TAA_ZLIB_EXPORT __attribute__((visibility("default")))

using taa::fast_zlib::compressorFor;
using taa::fast_zlib::decompressor;

// zlib's compress2: a zlib stream of `source` into `dest` (capacity *destLength), at `level`
// (-1: zlib's default, 6). libdeflate levels 1-9 trade speed for size much as zlib's do.
extern "C" TAA_ZLIB_EXPORT int compress2(Bytef* dest, uLongf* destLength, const Bytef* source, uLong sourceLength,
                         int level) {
  if (level == Z_DEFAULT_COMPRESSION) level = 6;
  if (level >= 1 && level <= 9) {
    if (libdeflate_compressor* compressor = compressorFor(level)) {
      const std::size_t written =
          libdeflate_zlib_compress(compressor, source, sourceLength, dest, *destLength);
      if (written > 0) {
        *destLength = uLongf(written);
        return Z_OK;
      }
    }
  }
  // Level 0 (stored), an invalid level, or output that did not fit: zlib decides, as it would.
  return taa::fast_zlib::zlibCompress2()(dest, destLength, source, sourceLength, level);
}

extern "C" TAA_ZLIB_EXPORT int compress(Bytef* dest, uLongf* destLength, const Bytef* source,
                        uLong sourceLength) {
  return compress2(dest, destLength, source, sourceLength, Z_DEFAULT_COMPRESSION);
}

// zlib's uncompress: the zlib stream `source` into `dest` (capacity *destLength).
extern "C" TAA_ZLIB_EXPORT int uncompress(Bytef* dest, uLongf* destLength, const Bytef* source,
                          uLong sourceLength) {
  if (libdeflate_decompressor* d = decompressor()) {
    std::size_t produced = 0;
    if (libdeflate_zlib_decompress(d, source, sourceLength, dest, *destLength, &produced) ==
        LIBDEFLATE_SUCCESS) {
      *destLength = uLongf(produced);
      return Z_OK;
    }
  }
  // Corrupt or truncated data, or too small a buffer: zlib's own result and error code.
  return taa::fast_zlib::zlibUncompress()(dest, destLength, source, sourceLength);
}
