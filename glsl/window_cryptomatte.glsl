// Cryptomatte in the window gather (issue 21): each sample carries up to two IDs with their
// coverage (an input pixel's first rank layer: id0, coverage0, id1, coverage1). A pixel's
// coverage of an ID is the weight of the samples that carry it over the weight of all its
// samples, each weighed exactly as the beauty weighs it. IDs are compared bit for bit (they
// are hashes stored as floats). A pixel keeps CRYPTO_SLOTS IDs; an ID arriving when all are
// taken replaces the lightest if it weighs more (its weight still counts in the total).

#define CRYPTO_SLOTS 8

uniform sampler2DArray uCrypto;  // RGBA32F: the first rank layer of each frame's samples

// The pixel's IDs, each with two weights: settled (t's own samples, thin features, and each
// source once weighed whole) and pending (the current source's, before its agreement and
// frame weight are known). One set of slots for both, so that a sample is placed once and a
// source is settled by one pass over the slots (before, the current source kept slots of its
// own, merged ID by ID into the pixel's: two placements a sample and eight a source).
uint gCryptoId[CRYPTO_SLOTS];
float gCryptoSettled[CRYPTO_SLOTS];
float gCryptoPending[CRYPTO_SLOTS];
float gCryptoTotal, gCryptoPendingTotal;

// Adds `settled` and `pending` to `id`'s slot, or takes the lightest slot for it. An empty slot
// weighs nothing; a slot is judged by both weights together. (A macro: GLSL copies arrays
// passed to functions, which llvmpipe pays for on every sample. Every index is the loop's
// counter, never a computed slot: llvmpipe keeps arrays indexed only by unrolled counters in
// registers, and moves an array indexed by a value (the lightest slot) to memory, for every
// access.)
#define CRYPTO_ADD(id, settled, pending)                                            \
  {                                                                                 \
    uint cryptoId = (id);                                                           \
    float cryptoSettled = (settled), cryptoPending = (pending);                     \
    float cryptoWeight = cryptoSettled + cryptoPending;                             \
    bool placed = !(cryptoWeight > 0.0);                                            \
    int lightest = 0;                                                               \
    float lightestWeight = 0.0;                                                     \
    for (int slot = 0; slot < CRYPTO_SLOTS; ++slot) {                               \
      float held = gCryptoSettled[slot] + gCryptoPending[slot];                     \
      bool same = !placed && held > 0.0 && gCryptoId[slot] == cryptoId;             \
      gCryptoSettled[slot] += same ? cryptoSettled : 0.0;                           \
      gCryptoPending[slot] += same ? cryptoPending : 0.0;                           \
      placed = placed || same;                                                      \
      bool lighter = slot == 0 || held < lightestWeight;                            \
      lightest = lighter ? slot : lightest;                                         \
      lightestWeight = lighter ? held : lightestWeight;                             \
    }                                                                               \
    bool replace = !placed && cryptoWeight > lightestWeight;                        \
    for (int slot = 0; slot < CRYPTO_SLOTS; ++slot) {                               \
      bool here = replace && slot == lightest;                                      \
      gCryptoId[slot] = here ? cryptoId : gCryptoId[slot];                          \
      gCryptoSettled[slot] = here ? cryptoSettled : gCryptoSettled[slot];           \
      gCryptoPending[slot] = here ? cryptoPending : gCryptoPending[slot];           \
    }                                                                               \
  }

void cryptoBegin() {
  for (int slot = 0; slot < CRYPTO_SLOTS; ++slot) {
    gCryptoId[slot] = 0u;
    gCryptoSettled[slot] = 0.0;
    gCryptoPending[slot] = 0.0;
  }
  gCryptoTotal = 0.0;
  gCryptoPendingTotal = 0.0;
}

// A source left out (or not weighed) leaves nothing behind: its IDs' slots fall empty unless
// settled weight holds them.
void cryptoSourceBegin() {
  for (int slot = 0; slot < CRYPTO_SLOTS; ++slot) gCryptoPending[slot] = 0.0;
  gCryptoPendingTotal = 0.0;
}

// A sample's two IDs (its `ranks` texel), settled with `settled` and pending with `pending`.
void cryptoAddRanks(vec4 ranks, float settled, float pending) {
  float coverage0 = max(ranks.y, 0.0), coverage1 = max(ranks.w, 0.0);
  CRYPTO_ADD(floatBitsToUint(ranks.x), settled * coverage0, pending * coverage0)
  CRYPTO_ADD(floatBitsToUint(ranks.z), settled * coverage1, pending * coverage1)
  gCryptoTotal += settled * (coverage0 + coverage1);
  gCryptoPendingTotal += pending * (coverage0 + coverage1);
}

void cryptoAddSample(ivec2 texel, int layer, float settled, float pending) {
  cryptoAddRanks(texelFetch(uCrypto, ivec3(texel, layer), 0), settled, pending);
}

// The source weighed whole: its pending weights settle with `scale` (agreement x frame weight).
void cryptoSourceEnd(float scale) {
  for (int slot = 0; slot < CRYPTO_SLOTS; ++slot) {
    gCryptoSettled[slot] += scale * gCryptoPending[slot];
    gCryptoPending[slot] = 0.0;
  }
  gCryptoTotal += scale * gCryptoPendingTotal;
  gCryptoPendingTotal = 0.0;
}

// The six heaviest IDs with their coverage, heaviest first, as three rank layers of two pairs
// (id, coverage, id, coverage); empty pairs are 0, 0. Indexed by counters only (CRYPTO_ADD).
void cryptoOutput(out vec4 rank0, out vec4 rank1, out vec4 rank2) {
  float pairs[12];
  bool taken[CRYPTO_SLOTS];
  for (int slot = 0; slot < CRYPTO_SLOTS; ++slot) taken[slot] = false;
  for (int rank = 0; rank < 6; ++rank) {
    int heaviest = -1;
    float most = 0.0;
    uint id = 0u;
    for (int slot = 0; slot < CRYPTO_SLOTS; ++slot) {
      bool heavier = !taken[slot] && gCryptoSettled[slot] > most;
      most = heavier ? gCryptoSettled[slot] : most;
      id = heavier ? gCryptoId[slot] : id;
      heaviest = heavier ? slot : heaviest;
    }
    for (int slot = 0; slot < CRYPTO_SLOTS; ++slot) taken[slot] = taken[slot] || slot == heaviest;
    bool found = heaviest >= 0;
    pairs[2 * rank] = found ? uintBitsToFloat(id) : 0.0;
    pairs[2 * rank + 1] = found ? most / max(gCryptoTotal, 1e-30) : 0.0;
  }
  rank0 = vec4(pairs[0], pairs[1], pairs[2], pairs[3]);
  rank1 = vec4(pairs[4], pairs[5], pairs[6], pairs[7]);
  rank2 = vec4(pairs[8], pairs[9], pairs[10], pairs[11]);
}
