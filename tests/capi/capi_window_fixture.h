/* The window-mode fixture written by make_capi_window_fixture: frames as taatool read them
 * (with their camera matrices) and taatool's window-mode outputs on them. Plain C99. */
#ifndef TAA_CAPI_WINDOW_FIXTURE_H
#define TAA_CAPI_WINDOW_FIXTURE_H

/* The references, in the fixture's order (make_capi_window_fixture.cpp's kReferences). */
enum {
  REFERENCE_K2 = 0,        /* --mode window --window 2 */
  REFERENCE_K4 = 1,        /* --mode window --window 4 */
  REFERENCE_K2_SHOT5 = 2,  /* --mode window --window 2 --reset-frames 5 */
  REFERENCE_COUNT = 3
};

typedef struct window_frame {
  int frame;
  float world_to_camera[16], world_to_ndc[16]; /* row-major, as in the EXR header */
  float* color;                                /* width * height * 4, rows top first */
  float* depth;                                /* width * height */
  float* motion;                               /* width * height * 2 */
  float* reference[REFERENCE_COUNT];           /* width * height * 4: taatool's output */
} window_frame;

typedef struct window_fixture {
  int width, height, count;
  window_frame* frames; /* frames[i].frame == first + i */
} window_fixture;

/* Reads the fixture file; returns 0 and prints why on failure. */
int window_fixture_load(const char* path, window_fixture* out);
void window_fixture_free(window_fixture* f);

#endif
