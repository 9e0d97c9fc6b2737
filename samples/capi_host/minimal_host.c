/* The smallest host of taa's C ABI (taa.h): make a node, set parameters by name, push frames
 * held in the host's own memory (here: y-up float RGBA with padded rows, as OpenGL or OpenFX
 * lay images out), read each resolved frame back, destroy the node. The frames are a bright
 * bar moving 1 px per frame over grey, rendered with Halton jitter like a real renderer would.
 * Exit status 0 when everything worked. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "taa/taa.h"

enum { WIDTH = 64, HEIGHT = 36, FRAMES = 12, ROW_FLOATS = WIDTH * 4 + 8 /* padding */ };

static float halton(int index, int base) {
  float result = 0.0f, f = 1.0f / (float)base;
  for (; index > 0; index /= base, f /= (float)base) result += f * (float)(index % base);
  return result;
}

/* Point-samples the scene at each pixel centre offset by this frame's jitter (the bar is
 * vertical, so only the x jitter matters). Row 0 of the buffers is the bottom row (y_up). */
static void render_frame(int frame, float* color, float* motion) {
  const float jx = halton(frame, 2) - 0.5f;
  const float bar_left = 10.0f + (float)frame, bar_right = bar_left + 6.5f;
  for (int row = 0; row < HEIGHT; ++row) {
    for (int x = 0; x < WIDTH; ++x) {
      const float sx = (float)x + 0.5f + jx;
      const int on_bar = sx >= bar_left && sx < bar_right;
      float* px = &color[row * ROW_FLOATS + x * 4];
      px[0] = px[1] = px[2] = on_bar ? 4.0f : 0.18f;
      px[3] = 1.0f;
      motion[(row * WIDTH + x) * 2 + 0] = on_bar ? -1.0f : 0.0f; /* to the previous frame */
      motion[(row * WIDTH + x) * 2 + 1] = 0.0f;
    }
  }
}

static int fail(const char* what, const char* message) {
  fprintf(stderr, "minimal_host: %s: %s\n", what, message);
  return 1;
}

int main(void) {
  if (taa_abi_version() != TAA_ABI_VERSION) return fail("ABI", "library and header differ");

  taa_node* node = NULL;
  if (taa_node_create(NULL, &node) != TAA_OK) return fail("create", taa_last_error());
  if (taa_node_set_float(node, "blend", 0.2f) != TAA_OK ||
      taa_node_set_string(node, "jitter", "halton") != TAA_OK) {
    const int status = fail("parameters", taa_node_last_error(node));
    taa_node_destroy(node);
    return status;
  }

  float* color = calloc((size_t)ROW_FLOATS * HEIGHT, sizeof(float));
  float* motion = calloc((size_t)WIDTH * HEIGHT * 2, sizeof(float));
  float* resolved = calloc((size_t)ROW_FLOATS * HEIGHT, sizeof(float));
  taa_buffer color_buffer = {color, WIDTH, HEIGHT, 4, TAA_PIXEL_FLOAT,
                             ROW_FLOATS * sizeof(float), 0, 1};
  taa_buffer motion_buffer = {motion, WIDTH, HEIGHT, 2, TAA_PIXEL_FLOAT, 0, 0, 1};
  taa_buffer output_buffer = color_buffer;
  output_buffer.data = resolved;

  int status = 0;
  for (int frame = 1; frame <= FRAMES && status == 0; ++frame) {
    render_frame(frame, color, motion);
    taa_frame input;
    taa_frame_init(&input);
    input.frame = frame; /* Halton index and history continuity */
    input.color = &color_buffer;
    input.motion = &motion_buffer;
    if (taa_node_push_frame(node, &input) != TAA_OK ||
        taa_node_read_output(node, &output_buffer) != TAA_OK) {
      status = fail("frame", taa_node_last_error(node));
    }
  }
  if (status == 0) {
    /* A jittered point sample is 0.18 or 4; accumulated over frames, the half-covered pixel at
     * the bar's right edge settles between them. */
    const int row = HEIGHT / 2, edge = 10 + FRAMES + 6; /* the bar ends half-way across it */
    const float value = resolved[row * ROW_FLOATS + edge * 4];
    printf("resolved %d frames of %dx%d; edge pixel %d = %.3f\n", FRAMES, WIDTH, HEIGHT, edge,
           value);
    if (!isfinite(value)) status = fail("output", "not finite");
  }
  free(color);
  free(motion);
  free(resolved);
  taa_node_destroy(node);
  return status;
}
