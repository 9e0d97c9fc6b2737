/* Error paths of the C ABI: NULL handles, wrong sizes and channel counts, unknown or mistyped
 * parameters, reading before resolving. Each failing call must return its status and leave a
 * message naming what was wrong; the node must stay usable afterwards. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "capi_test_util.h"

enum { W = 16, H = 8 };

static float color_data[W * H * 4], depth_data[W * H], motion_data[W * H * 2];
static float small_depth[8 * 8], output_data[W * H * 4];

static int contains(const char* text, const char* part) {
  return text && strstr(text, part) != NULL;
}

static void test_version(void) {
  CHECK(taa_abi_version() == TAA_ABI_VERSION, "library ABI %d, header %d", taa_abi_version(),
        TAA_ABI_VERSION);
  CHECK(strlen(taa_version_string()) > 0, "empty version string");
}

static void test_null_handles(void) {
  CHECK(taa_node_create(NULL, NULL) == TAA_ERROR_INVALID_ARGUMENT, "create with NULL out");
  CHECK(contains(taa_last_error(), "NULL"), "message: %s", taa_last_error());
  CHECK(taa_node_set_float(NULL, "blend", 0.5f) == TAA_ERROR_INVALID_ARGUMENT, "NULL node");
  CHECK(contains(taa_last_error(), "taa_node_set_float") &&
            contains(taa_last_error(), "NULL"), "message: %s", taa_last_error());
  CHECK(taa_node_push_frame(NULL, NULL) == TAA_ERROR_INVALID_ARGUMENT, "push on NULL node");
  CHECK(taa_node_reset_history(NULL) == TAA_ERROR_INVALID_ARGUMENT, "reset on NULL node");
  taa_node_destroy(NULL); /* must be a no-op */

  /* An enum field holding no enumerator (UBSan: reading it as the C++ enum was undefined). */
  taa_create_options options;
  taa_create_options_init(&options);
  options.gl_backend = (taa_gl_backend)9;
  taa_node* node = NULL;
  CHECK(taa_node_create(&options, &node) == TAA_ERROR_INVALID_ARGUMENT, "back end 9");
  CHECK(node == NULL && contains(taa_last_error(), "unknown GL back end 9"), "message: %s",
        taa_last_error());
}

static void test_parameters(taa_node* node) {
  CHECK(taa_node_set_float(node, "blend", 0.25f) == TAA_OK, "%s", taa_node_last_error(node));
  CHECK(strcmp(taa_node_last_error(node), "") == 0, "message after success: %s",
        taa_node_last_error(node));

  taa_status s = taa_node_set_float(node, "blendd", 0.5f);
  CHECK(s == TAA_ERROR_UNKNOWN_PARAMETER, "unknown name gave %d", s);
  CHECK(contains(taa_node_last_error(node), "\"blendd\""), "message: %s",
        taa_node_last_error(node));
  CHECK(contains(taa_node_last_error(node), "blend,"), "lists the names: %s",
        taa_node_last_error(node));

  s = taa_node_set_int(node, "motion_y", 1);
  CHECK(s == TAA_ERROR_WRONG_TYPE, "int for a string parameter gave %d", s);
  CHECK(contains(taa_node_last_error(node), "motion_y") &&
            contains(taa_node_last_error(node), "string"), "message: %s",
        taa_node_last_error(node));

  s = taa_node_set_float(node, "blend", 0.0f);
  CHECK(s == TAA_ERROR_INVALID_ARGUMENT, "blend 0 gave %d", s);
  CHECK(contains(taa_node_last_error(node), "blend") &&
            contains(taa_node_last_error(node), "\"0\""), "message: %s",
        taa_node_last_error(node));
  /* Resolve options take any type, as taatool's text: an int blend of 1 is 1.0. */
  CHECK(taa_node_set_int(node, "blend", 1) == TAA_OK, "%s", taa_node_last_error(node));
  CHECK(taa_node_set_string(node, "rectify", "clamp") == TAA_OK, "%s",
        taa_node_last_error(node));
  CHECK(taa_node_set_string(node, "rectify", "variance") == TAA_OK, "%s",
        taa_node_last_error(node));

  s = taa_node_set_string(node, "jitter", "sobol");
  CHECK(s == TAA_ERROR_INVALID_ARGUMENT, "jitter sobol gave %d", s);
  CHECK(contains(taa_node_last_error(node), "halton|none") &&
            contains(taa_node_last_error(node), "sobol"), "message: %s",
        taa_node_last_error(node));

  CHECK(taa_node_set_int(node, "jitter_period", -1) == TAA_ERROR_INVALID_ARGUMENT,
        "negative period accepted");
  CHECK(taa_node_set_string(node, "motion_y", NULL) == TAA_ERROR_INVALID_ARGUMENT,
        "NULL string value accepted");
  CHECK(taa_node_set_int(node, NULL, 1) == TAA_ERROR_INVALID_ARGUMENT, "NULL name accepted");
  CHECK(taa_node_set_string(node, "motion_y", "up") == TAA_OK, "%s",
        taa_node_last_error(node));
  CHECK(taa_node_set_string(node, "motion_y", "down") == TAA_OK, "%s",
        taa_node_last_error(node));
}

static taa_frame frame_with(const taa_buffer* color, const taa_buffer* depth,
                            const taa_buffer* motion) {
  taa_frame frame;
  taa_frame_init(&frame);
  frame.frame = 1;
  frame.color = color;
  frame.depth = depth;
  frame.motion = motion;
  return frame;
}

static void test_buffers(taa_node* node) {
  taa_buffer out = float_buffer(output_data, W, H, 4);
  CHECK(taa_node_read_output(node, &out) == TAA_ERROR_NO_OUTPUT, "output before any frame");
  float m1[16], m2[16];
  CHECK(taa_node_get_camera(node, m1, m2) == TAA_ERROR_NO_OUTPUT, "camera before any frame");

  taa_buffer color = float_buffer(color_data, W, H, 4);
  taa_buffer depth = float_buffer(depth_data, W, H, 1);
  taa_buffer motion = float_buffer(motion_data, W, H, 2);

  CHECK(taa_node_push_frame(node, NULL) == TAA_ERROR_INVALID_ARGUMENT, "NULL frame");
  taa_frame frame = frame_with(NULL, &depth, &motion);
  CHECK(taa_node_push_frame(node, &frame) == TAA_ERROR_INVALID_ARGUMENT, "NULL color");
  CHECK(contains(taa_node_last_error(node), "no color"), "message: %s",
        taa_node_last_error(node));

  taa_buffer wrong_size = float_buffer(small_depth, 8, 8, 1);
  frame = frame_with(&color, &wrong_size, &motion);
  CHECK(taa_node_push_frame(node, &frame) == TAA_ERROR_INVALID_ARGUMENT, "depth 8x8");
  CHECK(contains(taa_node_last_error(node), "depth is 8x8 but color is 16x8"), "message: %s",
        taa_node_last_error(node));

  taa_buffer two_channels = float_buffer(color_data, W, H, 2);
  frame = frame_with(&two_channels, NULL, NULL);
  CHECK(taa_node_push_frame(node, &frame) == TAA_ERROR_INVALID_ARGUMENT, "2-channel color");
  CHECK(contains(taa_node_last_error(node), "color buffer must have 3 or 4 channels, has 2"),
        "message: %s", taa_node_last_error(node));

  /* Issue 25: sizes were allocated for before any limit was checked. */
  taa_buffer huge = float_buffer(color_data, 100000, 100000, 4);
  frame = frame_with(&huge, NULL, NULL);
  CHECK(taa_node_push_frame(node, &frame) == TAA_ERROR_INVALID_ARGUMENT, "100000x100000 color");
  CHECK(contains(taa_node_last_error(node), "color buffer is 100000x100000: at most 16384 "
                                            "pixels a side"),
        "message: %s", taa_node_last_error(node));

  taa_buffer short_rows = color;
  short_rows.row_stride_bytes = W * 4 * 4 - 4;
  frame = frame_with(&short_rows, NULL, NULL);
  CHECK(taa_node_push_frame(node, &frame) == TAA_ERROR_INVALID_ARGUMENT, "short row stride");
  CHECK(contains(taa_node_last_error(node), "row stride"), "message: %s",
        taa_node_last_error(node));

  taa_buffer bad_type = color;
  bad_type.type = (taa_pixel_type)7;
  frame = frame_with(&bad_type, NULL, NULL);
  CHECK(taa_node_push_frame(node, &frame) == TAA_ERROR_INVALID_ARGUMENT, "pixel type 7");

  taa_buffer no_data = color;
  no_data.data = NULL;
  frame = frame_with(&no_data, NULL, NULL);
  CHECK(taa_node_push_frame(node, &frame) == TAA_ERROR_INVALID_ARGUMENT, "NULL data");

  /* A jitter that is not a number of pixels would make every reconstruction weight NaN. */
  frame = frame_with(&color, NULL, NULL);
  frame.has_jitter = 1;
  frame.jitter[0] = NAN;
  CHECK(taa_node_push_frame(node, &frame) == TAA_ERROR_INVALID_ARGUMENT, "NaN jitter");
  CHECK(contains(taa_node_last_error(node), "jitter (nan, 0") &&
            contains(taa_node_last_error(node), "finite"), "message: %s",
        taa_node_last_error(node));
  frame.jitter[0] = 0.0f;
  frame.jitter[1] = -INFINITY;
  CHECK(taa_node_push_frame(node, &frame) == TAA_ERROR_INVALID_ARGUMENT, "-Inf jitter");

  /* NaN camera matrices would reproject every pixel to NaN. */
  float nan_matrix[16] = {0};
  nan_matrix[0] = nan_matrix[5] = nan_matrix[10] = nan_matrix[15] = 1.0f;
  nan_matrix[12] = NAN;
  frame = frame_with(&color, NULL, NULL);
  frame.world_to_ndc = nan_matrix;
  CHECK(taa_node_push_frame(node, &frame) == TAA_ERROR_INVALID_ARGUMENT, "NaN matrix");
  CHECK(contains(taa_node_last_error(node), "world_to_ndc holds NaN or Inf"), "message: %s",
        taa_node_last_error(node));

  /* After all that, a valid frame resolves and clears the message. */
  for (int i = 0; i < W * H; ++i) {
    for (int c = 0; c < 4; ++c) color_data[i * 4 + c] = 0.5f;
    depth_data[i] = 5.0f;
  }
  float world_to_camera[16] = {0};
  world_to_camera[0] = world_to_camera[5] = world_to_camera[10] = world_to_camera[15] = 1.0f;
  world_to_camera[12] = 3.0f;
  frame = frame_with(&color, &depth, &motion);
  frame.world_to_camera = world_to_camera;
  CHECK(taa_node_push_frame(node, &frame) == TAA_OK, "valid frame: %s",
        taa_node_last_error(node));
  CHECK(strcmp(taa_node_last_error(node), "") == 0, "stale message: %s",
        taa_node_last_error(node));
  CHECK(taa_node_read_output(node, &out) == TAA_OK, "%s", taa_node_last_error(node));
  CHECK(output_data[0] > 0.49f && output_data[0] < 0.51f, "flat 0.5 resolved to %g",
        output_data[0]);

  CHECK(taa_node_get_camera(node, m1, m2) == TAA_OK, "%s", taa_node_last_error(node));
  CHECK(m1[12] == 3.0f && m1[0] == 1.0f, "world_to_camera not kept");
  CHECK(m2[0] == 0.0f && m2[15] == 0.0f, "missing world_to_ndc must read as zeros");

  taa_buffer small_out = float_buffer(output_data, 8, 8, 4);
  CHECK(taa_node_read_output(node, &small_out) == TAA_ERROR_INVALID_ARGUMENT, "8x8 output");
  CHECK(contains(taa_node_last_error(node), "output is 8x8 but color is 16x8"), "message: %s",
        taa_node_last_error(node));
  taa_buffer one_channel_out = float_buffer(output_data, W, H, 1);
  CHECK(taa_node_read_output(node, &one_channel_out) == TAA_ERROR_INVALID_ARGUMENT,
        "1-channel output");
}

int main(void) {
  test_version();
  test_null_handles();
  taa_node* node = make_node();
  if (node) {
    test_parameters(node);
    test_buffers(node);
    taa_node_destroy(node);
  }
  return test_report("capi_errors_test");
}
