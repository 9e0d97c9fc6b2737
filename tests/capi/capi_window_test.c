/* Window mode through the C ABI (taa.h, "Window mode") against the real taatool's
 * --mode window output on the same files (make_capi_window_fixture: a 3D scene with a turning
 * camera, so samples travel by camera reprojection and along vectors). Every resolve must equal
 * taatool's frame bit for bit, whatever order frames are pushed and resolved in; missing
 * frames are errors that say which frame and why; history mode is untouched.
 *   capi_window_test FIXTURE_FILE */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi_test_util.h"
#include "capi_window_fixture.h"

static window_fixture fx;
static size_t frame_values; /* width * height * 4 */
static float* output;       /* one frame */

static int contains(const char* text, const char* part) {
  return text && strstr(text, part) != NULL;
}

static const window_frame* frame_data(int frame) {
  return &fx.frames[frame - fx.frames[0].frame];
}
static int first_frame(void) { return fx.frames[0].frame; }
static int last_frame(void) { return fx.frames[fx.count - 1].frame; }

static taa_node* window_node(int radius) {
  taa_node* node = make_node();
  if (!node) return NULL;
  CHECK(taa_node_set_string(node, "mode", "window") == TAA_OK, "%s", taa_node_last_error(node));
  CHECK(taa_node_set_int(node, "window", radius) == TAA_OK, "%s", taa_node_last_error(node));
  return node;
}

/* Pushes frame `frame` of the fixture with its camera, or frame `content`'s pixels and camera
 * under that number (to replace a frame with something else). */
static taa_status push_as(taa_node* node, int frame, int content) {
  const window_frame* f = frame_data(content);
  taa_buffer color = float_buffer(f->color, fx.width, fx.height, 4);
  taa_buffer depth = float_buffer(f->depth, fx.width, fx.height, 1);
  taa_buffer motion = float_buffer(f->motion, fx.width, fx.height, 2);
  taa_frame input;
  taa_frame_init(&input);
  input.frame = frame;
  input.color = &color;
  input.depth = &depth;
  input.motion = &motion;
  input.world_to_camera = f->world_to_camera;
  input.world_to_ndc = f->world_to_ndc;
  return taa_node_push_frame(node, &input);
}

static void push(taa_node* node, int frame) {
  CHECK(push_as(node, frame, frame) == TAA_OK, "push %d: %s", frame, taa_node_last_error(node));
}

/* Resolves `frame` and checks it is taatool's `reference` output bit for bit. */
static void resolve_and_compare(taa_node* node, int frame, int reference, const char* how) {
  const taa_status s = taa_node_resolve_frame(node, frame);
  if (!CHECK(s == TAA_OK, "%s: resolve %d gave %d: %s", how, frame, s,
             taa_node_last_error(node))) {
    return;
  }
  taa_buffer out = float_buffer(output, fx.width, fx.height, 4);
  CHECK(taa_node_read_output(node, &out) == TAA_OK, "%s", taa_node_last_error(node));
  const float* expected = frame_data(frame)->reference[reference];
  CHECK(memcmp(output, expected, frame_values * sizeof(float)) == 0,
        "%s: frame %d differs from taatool's by up to %g", how, frame,
        max_abs_diff(output, expected, frame_values));
}

/* The comparisons can fail: the references differ from each other and from the raw input. */
static void test_references_differ(void) {
  const window_frame* f = frame_data(4);
  CHECK(max_abs_diff(f->reference[REFERENCE_K2], f->reference[REFERENCE_K4], frame_values) >
            1e-3f, "K 2 and K 4 give the same frame 4");
  CHECK(max_abs_diff(f->reference[REFERENCE_K2], f->reference[REFERENCE_K2_SHOT5],
                     frame_values) > 1e-3f, "a shot starting at 5 does not change frame 4");
  CHECK(max_abs_diff(f->reference[REFERENCE_K2], f->color, frame_values) > 1e-3f,
        "the window output is the raw input");
}

/* Frames in order, each resolved as soon as its window is in: a ring of 5 for 8 frames, so
 * every push from frame 6 on evicts the frame farthest behind. */
static void test_streaming_with_eviction(void) {
  const int radius = 2;
  taa_node* node = window_node(radius);
  if (!node) return;
  taa_buffer out = float_buffer(output, fx.width, fx.height, 4);
  CHECK(taa_node_read_output(node, &out) == TAA_ERROR_NO_OUTPUT, "output before a resolve");
  for (int t = first_frame(); t <= last_frame(); ++t) {
    push(node, t);
    if (t == first_frame()) {
      CHECK(taa_node_read_output(node, &out) == TAA_ERROR_NO_OUTPUT, "a push resolved a frame");
    }
    if (t - radius >= first_frame()) resolve_and_compare(node, t - radius, REFERENCE_K2, "stream");
  }
  for (int t = last_frame() - radius + 1; t <= last_frame(); ++t) {
    resolve_and_compare(node, t, REFERENCE_K2, "stream end");
  }
  /* The camera given back is the resolved frame's. */
  float w2c[16], w2ndc[16];
  CHECK(taa_node_get_camera(node, w2c, w2ndc) == TAA_OK, "%s", taa_node_last_error(node));
  CHECK(memcmp(w2c, frame_data(last_frame())->world_to_camera, sizeof w2c) == 0 &&
            memcmp(w2ndc, frame_data(last_frame())->world_to_ndc, sizeof w2ndc) == 0,
        "get_camera does not give the resolved frame's matrices");
  taa_node_destroy(node);
}

/* Every frame pushed in a shuffled order into a ring that holds them all, then resolved in
 * another order, one frame twice. */
static void test_any_order(void) {
  static const int push_order[] = {5, 2, 8, 1, 7, 3, 6, 4};
  static const int resolve_order[] = {6, 1, 8, 3, 5, 2, 7, 4, 6};
  taa_node* node = window_node(4);
  if (!node) return;
  for (size_t i = 0; i < sizeof push_order / sizeof *push_order; ++i) push(node, push_order[i]);
  for (size_t i = 0; i < sizeof resolve_order / sizeof *resolve_order; ++i) {
    resolve_and_compare(node, resolve_order[i], REFERENCE_K4, "shuffled");
  }
  taa_node_destroy(node);
}

/* Random access as an OpenFX render does it: before each frame, drop what its window does not
 * need and push what it lacks. The ring never overflows, so nothing relies on eviction. */
static void test_random_access_with_drops(void) {
  static const int order[] = {6, 2, 8, 4, 1, 7, 3, 5};
  const int radius = 2;
  int held[64] = {0};
  taa_node* node = window_node(radius);
  if (!node) return;
  int pushes = 0;
  for (size_t i = 0; i < sizeof order / sizeof *order; ++i) {
    const int t = order[i];
    for (int f = first_frame(); f <= last_frame(); ++f) {
      if (held[f] && (f < t - radius || f > t + radius)) {
        CHECK(taa_node_drop_frame(node, f) == TAA_OK, "%s", taa_node_last_error(node));
        held[f] = 0;
      }
    }
    for (int f = t - radius; f <= t + radius; ++f) {
      if (f >= first_frame() && f <= last_frame() && !held[f]) {
        push(node, f);
        held[f] = 1;
        ++pushes;
      }
    }
    resolve_and_compare(node, t, REFERENCE_K2, "random access");
  }
  CHECK(pushes < 8 * 5, "every window was pushed whole (%d pushes)", pushes);
  taa_node_destroy(node);
}

/* taa_node_reset_history before frame 5: no window crosses from 4 to 5 (taatool's
 * --reset-frames 5). */
static void test_shot_boundary(void) {
  const int radius = 2;
  taa_node* node = window_node(radius);
  if (!node) return;
  for (int t = first_frame(); t <= last_frame(); ++t) {
    if (t == 5) {
      CHECK(taa_node_reset_history(node) == TAA_OK, "%s", taa_node_last_error(node));
    }
    push(node, t);
    if (t - radius >= first_frame()) {
      resolve_and_compare(node, t - radius, REFERENCE_K2_SHOT5, "shots");
    }
  }
  for (int t = last_frame() - radius + 1; t <= last_frame(); ++t) {
    resolve_and_compare(node, t, REFERENCE_K2_SHOT5, "shots end");
  }
  taa_node_destroy(node);
}

/* Pushing a frame number the ring holds replaces the frame. A frame first pushed with other
 * content and then replaced gives taatool's result: nothing of the other content stays behind,
 * its neighbours' classification against it included. */
static void test_replacing_a_frame(void) {
  taa_node* node = window_node(2);
  if (!node) return;
  push(node, 1);
  push(node, 2);
  CHECK(push_as(node, 3, 7) == TAA_OK, "%s", taa_node_last_error(node));
  push(node, 4);
  push(node, 5);
  CHECK(taa_node_resolve_frame(node, 3) == TAA_OK, "%s", taa_node_last_error(node));
  taa_buffer out = float_buffer(output, fx.width, fx.height, 4);
  CHECK(taa_node_read_output(node, &out) == TAA_OK, "%s", taa_node_last_error(node));
  CHECK(max_abs_diff(output, frame_data(3)->reference[REFERENCE_K2], frame_values) > 1e-3f,
        "frame 3 with frame 7's content gave taatool's frame 3");
  push(node, 3);
  /* Windows 1-5 and 1-4: whole with frames 1-5. */
  resolve_and_compare(node, 3, REFERENCE_K2, "replaced");
  resolve_and_compare(node, 2, REFERENCE_K2, "beside the replaced frame");
  taa_node_destroy(node);
}

static void expect_missing(taa_node* node, int frame, const char* message) {
  const taa_status s = taa_node_resolve_frame(node, frame);
  CHECK(s == TAA_ERROR_MISSING_FRAME, "resolve %d gave %d (%s), expected a missing frame",
        frame, s, taa_node_last_error(node));
  CHECK(contains(taa_node_last_error(node), message), "resolve %d: message \"%s\" lacks \"%s\"",
        frame, taa_node_last_error(node), message);
}

/* Eviction picks the frame farthest from the new one (the earlier of two as far); a window
 * missing a frame fails and says which frame and why. */
static void test_missing_frames(void) {
  taa_node* node = window_node(1); /* a ring of 3 */
  if (!node) return;
  expect_missing(node, 2, "frame 2 has not been pushed (the ring holds no frames)");
  push(node, 1);
  push(node, 2);
  push(node, 5);
  push(node, 3); /* 1 and 5 are both 2 away: 1 goes */
  expect_missing(node, 2,
                 "frame 1 of frame 2's window (frames 1-3) is not in the ring: it was evicted "
                 "when frame 3 was pushed into the full ring of 3 frames; push it again (the "
                 "ring holds frames 2-3, 5)");
  CHECK(taa_node_resolve_frame(node, 5) == TAA_OK, "%s", taa_node_last_error(node));
  push(node, 4); /* farthest from 4: 2 */
  expect_missing(node, 3, "frame 2 of frame 3's window (frames 2-4) is not in the ring: it was "
                          "evicted when frame 4 was pushed");
  expect_missing(node, 9, "frame 9 has not been pushed (the ring holds frames 3-5)");

  CHECK(taa_node_drop_frame(node, 3) == TAA_OK, "%s", taa_node_last_error(node));
  CHECK(taa_node_drop_frame(node, 3) == TAA_OK, "dropping twice: %s", taa_node_last_error(node));
  expect_missing(node, 4, "frame 3 of frame 4's window (frames 3-5) is not in the ring: it was "
                          "dropped (taa_node_drop_frame)");
  expect_missing(node, 3, "frame 3 is not in the ring: it was dropped");
  push(node, 3);
  CHECK(taa_node_resolve_frame(node, 4) == TAA_OK, "pushed again: %s",
        taa_node_last_error(node));

  /* The same value again keeps the ring; a new one empties it. */
  CHECK(taa_node_set_int(node, "window", 1) == TAA_OK, "%s", taa_node_last_error(node));
  CHECK(taa_node_resolve_frame(node, 4) == TAA_OK, "same K: %s", taa_node_last_error(node));
  CHECK(taa_node_set_float(node, "window-sigma", 0.5f) == TAA_OK, "%s",
        taa_node_last_error(node));
  expect_missing(node, 4, "frame 4 is not in the ring: it was removed when a resolve parameter "
                          "changed");

  /* A frame of another size must start a shot, and then empties the ring. */
  for (int t = 3; t <= 5; ++t) push(node, t);
  float small[8 * 8 * 4] = {0};
  taa_buffer small_color = float_buffer(small, 8, 8, 4);
  taa_frame input;
  taa_frame_init(&input);
  input.frame = 6;
  input.color = &small_color;
  const taa_status s = taa_node_push_frame(node, &input);
  CHECK(s == TAA_ERROR_INVALID_ARGUMENT, "another size gave %d", s);
  CHECK(contains(taa_node_last_error(node),
                 "frame 6 is 8x8 but the frames in the ring are 48x32: a frame of another size "
                 "must start a shot"),
        "message: %s", taa_node_last_error(node));
  CHECK(taa_node_resolve_frame(node, 4) == TAA_OK, "the refused push changed the ring: %s",
        taa_node_last_error(node));
  CHECK(taa_node_reset_history(node) == TAA_OK, "%s", taa_node_last_error(node));
  CHECK(taa_node_push_frame(node, &input) == TAA_OK, "%s", taa_node_last_error(node));
  CHECK(taa_node_resolve_frame(node, 6) == TAA_OK, "%s", taa_node_last_error(node));
  expect_missing(node, 4, "it was removed when frame 6 was pushed with another size");
  taa_node_destroy(node);
}

/* resolve and drop belong to window mode; history mode still resolves on push, and a node
 * switched to window and back resolves as a history node that never left. */
static void test_history_mode_unchanged(void) {
  taa_node* node = make_node();
  taa_node* plain = make_node();
  if (!node || !plain) return;
  const taa_status s = taa_node_resolve_frame(node, 1);
  CHECK(s == TAA_ERROR_INVALID_ARGUMENT, "resolve in history mode gave %d", s);
  CHECK(contains(taa_node_last_error(node),
                 "taa_node_resolve_frame needs parameter \"mode\" = \"window\""),
        "message: %s", taa_node_last_error(node));
  CHECK(taa_node_drop_frame(node, 1) == TAA_ERROR_INVALID_ARGUMENT, "drop in history mode");
  CHECK(taa_node_resolve_frame(NULL, 1) == TAA_ERROR_INVALID_ARGUMENT, "NULL node");
  CHECK(contains(taa_last_error(), "taa_node_resolve_frame: node is NULL"), "message: %s",
        taa_last_error());
  CHECK(taa_node_drop_frame(NULL, 1) == TAA_ERROR_INVALID_ARGUMENT, "NULL node");

  CHECK(taa_node_set_string(node, "mode", "window") == TAA_OK, "%s", taa_node_last_error(node));
  push(node, 1);
  CHECK(taa_node_set_string(node, "mode", "history") == TAA_OK, "%s", taa_node_last_error(node));
  float* expected = malloc(frame_values * sizeof(float));
  taa_buffer out = float_buffer(output, fx.width, fx.height, 4);
  taa_buffer expected_out = float_buffer(expected, fx.width, fx.height, 4);
  for (int t = first_frame(); t <= last_frame(); ++t) {
    push(node, t);
    push(plain, t);
    CHECK(taa_node_read_output(node, &out) == TAA_OK, "%s", taa_node_last_error(node));
    CHECK(taa_node_read_output(plain, &expected_out) == TAA_OK, "%s",
          taa_node_last_error(plain));
    CHECK(memcmp(output, expected, frame_values * sizeof(float)) == 0,
          "history frame %d after window mode differs by %g", t,
          max_abs_diff(output, expected, frame_values));
  }
  CHECK(max_abs_diff(output, frame_data(last_frame())->reference[REFERENCE_K2], frame_values) >
            1e-3f, "history mode gave the window result");
  free(expected);
  taa_node_destroy(node);
  taa_node_destroy(plain);
}

/* Issue 25, defect 2: frame numbers at the ends of the int range (and random ones) resolve
 * from their window; a frame numbered INT_MAX made the node plan an endless window. */
static void test_frame_numbers_anywhere_in_the_int_range(void) {
  const int starts[] = {INT_MAX - 2, INT_MIN, -1000000007, 1999999999};
  unsigned seed = 25u;
  for (int round = 0; round < 8; ++round) {
    int start;
    if (round < 4) {
      start = starts[round];
    } else {
      seed = seed * 1103515245u + 12345u; /* any int but the last two */
      start = (int)(seed % 4294967293u - 2147483648.0);
    }
    taa_node* node = window_node(1);
    if (!node) return;
    for (int i = 0; i < 3; ++i) {
      CHECK(push_as(node, start + i, 1 + i) == TAA_OK, "push %d: %s", start + i,
            taa_node_last_error(node));
    }
    for (int i = 0; i < 3; ++i) {
      const taa_status s = taa_node_resolve_frame(node, start + i);
      CHECK(s == TAA_OK, "resolve %d gave %d: %s", start + i, s, taa_node_last_error(node));
    }
    taa_buffer out = float_buffer(output, fx.width, fx.height, 4);
    CHECK(taa_node_read_output(node, &out) == TAA_OK, "%s", taa_node_last_error(node));
    int bad = 0;
    for (size_t i = 0; i < frame_values; ++i) bad += isfinite(output[i]) ? 0 : 1;
    CHECK(bad == 0, "frame %d: %d non-finite output values", start + 2, bad);
    taa_node_destroy(node);
  }
}

int main(int argc, char** argv) {
  if (argc != 2 || !window_fixture_load(argv[1], &fx)) {
    fprintf(stderr, "usage: capi_window_test FIXTURE_FILE\n");
    return 1;
  }
  CHECK(fx.count == 8 && fx.frames[0].frame == 1, "the fixture must hold frames 1-8");
  frame_values = (size_t)fx.width * fx.height * 4;
  output = malloc(frame_values * sizeof(float));
  test_references_differ();
  test_streaming_with_eviction();
  test_any_order();
  test_random_access_with_drops();
  test_shot_boundary();
  test_replacing_a_frame();
  test_missing_frames();
  test_history_mode_unchanged();
  test_frame_numbers_anywhere_in_the_int_range();
  free(output);
  window_fixture_free(&fx);
  return test_report("capi_window_test");
}
