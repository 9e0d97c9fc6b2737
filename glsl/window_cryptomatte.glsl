// Cryptomatte in the window gather (issue 21): each sample carries up to two IDs with their
// coverage (an input pixel's first rank layer: id0, coverage0, id1, coverage1). A pixel's
// coverage of an ID is the weight of the samples that carry it over the weight of all its
// samples, each weighed exactly as the beauty weighs it. IDs are compared bit for bit (they
// are hashes stored as floats). A pixel keeps CRYPTO_SLOTS IDs; an ID arriving when all are
// taken replaces the lightest if it weighs more (its weight still counts in the total).

#define CRYPTO_SLOTS 8

uniform sampler2DArray uCrypto;  // RGBA32F: the first rank layer of each frame's samples

// The pixel's IDs and weights (final: t's own, and each source once weighed whole), the
// current source's, and the weight of every sample seen.
uint gCryptoId[CRYPTO_SLOTS];
float gCryptoWeight[CRYPTO_SLOTS];
uint gSourceCryptoId[CRYPTO_SLOTS];
float gSourceCryptoWeight[CRYPTO_SLOTS];
float gCryptoTotal, gSourceCryptoTotal;

// Adds `weight` to `id` in the slots `ids`/`weights` (a macro: GLSL copies arrays passed to
// functions, which llvmpipe pays for on every sample). Every index is the loop's counter, never
// a computed slot: llvmpipe keeps arrays indexed only by unrolled counters in registers, and
// moves an array indexed by a value (the lightest slot) to memory, for every access.
#define CRYPTO_ADD(ids, weights, id, weight)                                          \
  {                                                                                   \
    uint cryptoId = (id);                                                             \
    float cryptoWeight = (weight);                                                    \
    bool placed = !(cryptoWeight > 0.0);                                              \
    int lightest = 0;                                                                 \
    float lightestWeight = 0.0;                                                       \
    for (int slot = 0; slot < CRYPTO_SLOTS; ++slot) {                                 \
      bool same = !placed && weights[slot] > 0.0 && ids[slot] == cryptoId;            \
      weights[slot] += same ? cryptoWeight : 0.0;                                     \
      placed = placed || same;                                                        \
      bool lighter = slot == 0 || weights[slot] < lightestWeight;                     \
      lightest = lighter ? slot : lightest;                                           \
      lightestWeight = lighter ? weights[slot] : lightestWeight;                      \
    }                                                                                 \
    bool replace = !placed && cryptoWeight > lightestWeight;                          \
    for (int slot = 0; slot < CRYPTO_SLOTS; ++slot) {                                 \
      bool here = replace && slot == lightest;                                        \
      ids[slot] = here ? cryptoId : ids[slot];                                        \
      weights[slot] = here ? cryptoWeight : weights[slot];                            \
    }                                                                                 \
  }

void cryptoBegin() {
  for (int slot = 0; slot < CRYPTO_SLOTS; ++slot) {
    gCryptoId[slot] = 0u;
    gCryptoWeight[slot] = 0.0;
  }
  gCryptoTotal = 0.0;
}

void cryptoSourceBegin() {
  for (int slot = 0; slot < CRYPTO_SLOTS; ++slot) {
    gSourceCryptoId[slot] = 0u;
    gSourceCryptoWeight[slot] = 0.0;
  }
  gSourceCryptoTotal = 0.0;
}

// A sample's two IDs (its `ranks` texel) into the pixel's own slots (`toSource` false) or the
// source's.
void cryptoAddRanks(vec4 ranks, float weight, bool toSource) {
  float w0 = weight * max(ranks.y, 0.0), w1 = weight * max(ranks.w, 0.0);
  if (toSource) {
    CRYPTO_ADD(gSourceCryptoId, gSourceCryptoWeight, floatBitsToUint(ranks.x), w0)
    CRYPTO_ADD(gSourceCryptoId, gSourceCryptoWeight, floatBitsToUint(ranks.z), w1)
    gSourceCryptoTotal += w0 + w1;
  } else {
    CRYPTO_ADD(gCryptoId, gCryptoWeight, floatBitsToUint(ranks.x), w0)
    CRYPTO_ADD(gCryptoId, gCryptoWeight, floatBitsToUint(ranks.z), w1)
    gCryptoTotal += w0 + w1;
  }
}

void cryptoAddSample(ivec2 texel, int layer, float weight, bool toSource) {
  cryptoAddRanks(texelFetch(uCrypto, ivec3(texel, layer), 0), weight, toSource);
}

// The source weighed whole: its IDs join the pixel's with `scale` (agreement x frame weight).
void cryptoSourceEnd(float scale) {
  for (int slot = 0; slot < CRYPTO_SLOTS; ++slot) {
    CRYPTO_ADD(gCryptoId, gCryptoWeight, gSourceCryptoId[slot], scale * gSourceCryptoWeight[slot])
  }
  gCryptoTotal += scale * gSourceCryptoTotal;
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
      bool heavier = !taken[slot] && gCryptoWeight[slot] > most;
      most = heavier ? gCryptoWeight[slot] : most;
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
