// Reconstruction filters for unjittering the current frame. The weight of each 3x3 neighbour
// depends only on the frame's jitter, so it is computed here once per frame instead of in
// every pixel (Lanczos-2 alone cost about 50 ms of shader CPU per 1080p frame on llvmpipe).
#pragma once

#include <array>

#include <glm/vec2.hpp>

#include "taa/options.h"

namespace taa {

// A Gaussian fit to the Blackman-Harris window of width 3.3 pixels, exp(-2.29 d^2) (Karis, "High
// Quality Temporal Supersampling", SIGGRAPH 2014): soft, never negative. `offset`: pixels from
// the point being reconstructed to the sample.
float blackmanHarrisWeight(glm::vec2 offset);

// Separable Lanczos-2 windowed sinc: sharper than Blackman-Harris, with small negative lobes.
float lanczos2Weight(glm::vec2 offset);

// Normalised weights of the 3x3 neighbours (row-major, dy then dx from -1 to 1) for a frame
// whose samples sit `jitter` pixels from their pixel centres: neighbour (dx, dy)'s sample lies
// (dx, dy) + jitter from this pixel's centre. They sum to 1. Centre, or a filter whose lobes
// cancel out (|sum| <= 1e-4), gives the centre sample alone.
std::array<float, 9> reconstructionWeights(Reconstruction filter, glm::vec2 jitter);

}  // namespace taa
