/* Threads: two nodes resolving in two threads at once give exactly the results of serial runs;
 * a node handed from one thread to another keeps its history; two threads calling one node at
 * once get TAA_OK or TAA_ERROR_BUSY, never a crash or a corrupted result.
 *   capi_threads_test FIXTURE_FILE */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi_test_util.h"

static fixture fx;
static size_t frame_values;

typedef struct job {
  taa_node* node; /* NULL: the thread creates (and destroys) its own */
  float blend; /* <= 0: the library's default */
  int first, count;
  float* outputs;
  taa_status status;
  char message[512];
} job;

static void* run_job(void* arg) {
  job* j = arg;
  taa_node* node = j->node;
  if (!node && taa_node_create(NULL, &node) != TAA_OK) {
    j->status = TAA_ERROR_GL;
    snprintf(j->message, sizeof j->message, "%s", taa_last_error());
    return NULL;
  }
  j->status = j->blend > 0.0f ? taa_node_set_float(node, "blend", j->blend) : TAA_OK;
  if (j->status == TAA_OK) j->status = resolve_fixture(node, &fx, j->first, j->count, j->outputs);
  snprintf(j->message, sizeof j->message, "%s", taa_node_last_error(node));
  if (!j->node) taa_node_destroy(node);
  return NULL;
}

static job make_job(float blend) {
  job j;
  memset(&j, 0, sizeof j);
  j.blend = blend;
  j.count = fx.count;
  j.outputs = calloc(frame_values * fx.count, sizeof(float));
  return j;
}

static void test_two_nodes_in_parallel(void) {
  const float blends[2] = {0.0f /* the default */, 0.3f};
  job serial[2], parallel[2];
  for (int k = 0; k < 2; ++k) {
    serial[k] = make_job(blends[k]);
    run_job(&serial[k]);
    CHECK(serial[k].status == TAA_OK, "serial %d: %s", k, serial[k].message);
    parallel[k] = make_job(blends[k]);
  }
  pthread_t threads[2];
  for (int k = 0; k < 2; ++k) pthread_create(&threads[k], NULL, run_job, &parallel[k]);
  for (int k = 0; k < 2; ++k) pthread_join(threads[k], NULL);
  for (int k = 0; k < 2; ++k) {
    CHECK(parallel[k].status == TAA_OK, "parallel %d: %s", k, parallel[k].message);
    const float d = max_abs_diff(serial[k].outputs, parallel[k].outputs, frame_values * fx.count);
    CHECK(d == 0.0f, "node %d in a parallel thread differs from its serial run by %g", k, d);
  }
  /* The two blends differ, so the comparison above could have caught swapped results. */
  CHECK(max_abs_diff(serial[0].outputs, serial[1].outputs, frame_values * fx.count) > 1e-4f,
        "blend had no effect");
  /* And the default one matches the C++ Resolver with default options. */
  const float last = max_abs_diff(parallel[0].outputs + (fx.count - 1) * frame_values,
                                  fx.frames[fx.count - 1].reference, frame_values);
  CHECK(last <= 1e-6f, "parallel run differs from the C++ Resolver by %g", last);
  for (int k = 0; k < 2; ++k) {
    free(serial[k].outputs);
    free(parallel[k].outputs);
  }
}

static void test_node_moves_between_threads(void) {
  taa_node* node = make_node();
  if (!node) return;
  job whole = make_job(0.1f);
  run_job(&whole);
  const int half = fx.count / 2;
  job first = make_job(0.1f), second = make_job(0.1f);
  first.node = second.node = node;
  first.count = half;
  second.first = half;
  second.count = fx.count - half;
  pthread_t thread;
  pthread_create(&thread, NULL, run_job, &first);
  pthread_join(thread, NULL);
  pthread_create(&thread, NULL, run_job, &second);
  pthread_join(thread, NULL);
  CHECK(first.status == TAA_OK && second.status == TAA_OK, "%s %s", first.message,
        second.message);
  const float d = max_abs_diff(second.outputs + (second.count - 1) * frame_values,
                               whole.outputs + (fx.count - 1) * frame_values, frame_values);
  CHECK(d == 0.0f, "history lost when the node changed threads: differs by %g", d);
  taa_node_destroy(node);
  free(whole.outputs);
  free(first.outputs);
  free(second.outputs);
}

typedef struct hammer {
  taa_node* node;
  int ok, busy, other;
} hammer;

static void* hammer_node(void* arg) {
  hammer* h = arg;
  const fixture_frame* f = &fx.frames[0];
  taa_buffer color = float_buffer(f->color, fx.width, fx.height, 4);
  taa_frame frame;
  taa_frame_init(&frame);
  frame.frame = f->frame;
  frame.color = &color;
  for (int i = 0; i < 40; ++i) {
    const taa_status s = taa_node_push_frame(h->node, &frame);
    if (s == TAA_OK) {
      ++h->ok;
    } else if (s == TAA_ERROR_BUSY) {
      ++h->busy;
    } else {
      ++h->other;
    }
  }
  return NULL;
}

static void test_one_node_two_threads(void) {
  taa_node* node = make_node();
  if (!node) return;
  hammer h[2] = {{node, 0, 0, 0}, {node, 0, 0, 0}};
  pthread_t threads[2];
  for (int k = 0; k < 2; ++k) pthread_create(&threads[k], NULL, hammer_node, &h[k]);
  for (int k = 0; k < 2; ++k) pthread_join(threads[k], NULL);
  CHECK(h[0].other == 0 && h[1].other == 0, "statuses other than OK/BUSY: %d, %d", h[0].other,
        h[1].other);
  CHECK(h[0].ok + h[1].ok > 0, "no call succeeded");
  printf("one node, two threads: %d ok, %d busy\n", h[0].ok + h[1].ok, h[0].busy + h[1].busy);
  /* The node still works and gives a frame's single-frame result. */
  float* out = malloc(frame_values * sizeof(float));
  CHECK(taa_node_reset_history(node) == TAA_OK, "%s", taa_node_last_error(node));
  CHECK(resolve_fixture(node, &fx, 0, 1, out) == TAA_OK, "%s", taa_node_last_error(node));
  CHECK(max_abs_diff(out, fx.frames[0].reference, frame_values) <= 1e-6f,
        "node damaged by concurrent calls");
  free(out);
  taa_node_destroy(node);
}

int main(int argc, char** argv) {
  if (argc != 2 || !fixture_load(argv[1], &fx)) {
    fprintf(stderr, "usage: capi_threads_test FIXTURE_FILE\n");
    return 1;
  }
  frame_values = (size_t)fx.width * fx.height * 4;
  test_two_nodes_in_parallel();
  test_node_moves_between_threads();
  test_one_node_two_threads();
  fixture_free(&fx);
  return test_report("capi_threads_test");
}
