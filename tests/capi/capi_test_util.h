/* Helpers for the C ABI tests (plain C99): checks that count failures, the raw fixture written
 * by make_capi_fixture, buffers, and a float -> half conversion for half inputs. */
#ifndef TAA_CAPI_TEST_UTIL_H
#define TAA_CAPI_TEST_UTIL_H

#include <stddef.h>
#include <stdio.h>
#include <stdint.h>

#include "taa/taa.h"

extern int test_failures;

/* Records a failure with its location and a printf-style explanation; evaluates to cond. */
#define CHECK(cond, ...) check_impl((cond) != 0, __FILE__, __LINE__, #cond, __VA_ARGS__)
int check_impl(int ok, const char* file, int line, const char* expr, const char* fmt, ...);

/* Prints a summary and returns the process exit code (0 when no check failed). */
int test_report(const char* name);

typedef struct fixture_frame {
  int frame;
  float* color;     /* width * height * 4, rows top first */
  float* depth;     /* width * height */
  float* motion;    /* width * height * 2 */
  float* reference; /* width * height * 4: the C++ Resolver's output */
} fixture_frame;

typedef struct fixture {
  int width, height, count;
  fixture_frame* frames;
} fixture;

/* Reads the fixture file; returns 0 and prints why on failure. */
int fixture_load(const char* path, fixture* out);
/* Reads n floats into a new buffer (*out, freed by the caller); 0 on a short read. */
int fixture_read_floats(FILE* in, float** out, size_t n);
void fixture_free(fixture* f);

/* A tightly packed, top-first float buffer over `data`. */
taa_buffer float_buffer(float* data, int width, int height, int channels);
/* The same over half values (IEEE binary16 bits). */
taa_buffer half_buffer(uint16_t* data, int width, int height, int channels);

/* IEEE 754 binary16 from binary32, round to nearest even. */
uint16_t float_to_half(float value);
float half_to_float(uint16_t bits);

/* Creates a node with default options; fails the test (and returns NULL) if it cannot. */
taa_node* make_node(void);

/* Pushes fixture frames [first, first + count) as packed float, top-first buffers, reading each
 * output into outputs + i * width * height * 4. Returns the first failing status. */
taa_status resolve_fixture(taa_node* node, const fixture* f, int first, int count,
                           float* outputs);

float max_abs_diff(const float* a, const float* b, size_t n);

#endif
