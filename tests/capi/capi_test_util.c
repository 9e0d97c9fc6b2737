#include "capi_test_util.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int test_failures = 0;

int check_impl(int ok, const char* file, int line, const char* expr, const char* fmt, ...) {
  if (ok) return 1;
  ++test_failures;
  fprintf(stderr, "%s:%d: CHECK(%s) failed: ", file, line, expr);
  va_list args;
  va_start(args, fmt);
  vfprintf(stderr, fmt, args);
  va_end(args);
  fputc('\n', stderr);
  return 0;
}

int test_report(const char* name) {
  if (test_failures == 0) {
    printf("%s: all checks passed\n", name);
    return 0;
  }
  printf("%s: %d check(s) failed\n", name, test_failures);
  return 1;
}

int fixture_read_floats(FILE* in, float** out, size_t n) {
  *out = malloc(n * sizeof(float));
  return *out && fread(*out, sizeof(float), n, in) == n;
}

int fixture_load(const char* path, fixture* out) {
  memset(out, 0, sizeof *out);
  FILE* in = fopen(path, "rb");
  if (!in) {
    fprintf(stderr, "cannot open fixture %s\n", path);
    return 0;
  }
  char magic[8];
  int32_t header[3];
  int ok = fread(magic, 1, 8, in) == 8 && memcmp(magic, "TAAFIX01", 8) == 0 &&
           fread(header, sizeof(int32_t), 3, in) == 3;
  if (ok) {
    out->width = header[0];
    out->height = header[1];
    out->count = header[2];
    out->frames = calloc((size_t)out->count, sizeof(fixture_frame));
    ok = out->frames != NULL;
  }
  const size_t pixels = (size_t)out->width * out->height;
  for (int i = 0; ok && i < out->count; ++i) {
    fixture_frame* f = &out->frames[i];
    int32_t number;
    ok = fread(&number, sizeof number, 1, in) == 1 &&
         fixture_read_floats(in, &f->color, pixels * 4) &&
         fixture_read_floats(in, &f->depth, pixels) &&
         fixture_read_floats(in, &f->motion, pixels * 2) &&
         fixture_read_floats(in, &f->reference, pixels * 4);
    f->frame = number;
  }
  fclose(in);
  if (!ok) fprintf(stderr, "fixture %s is truncated or malformed\n", path);
  return ok;
}

void fixture_free(fixture* f) {
  for (int i = 0; f->frames && i < f->count; ++i) {
    free(f->frames[i].color);
    free(f->frames[i].depth);
    free(f->frames[i].motion);
    free(f->frames[i].reference);
  }
  free(f->frames);
  memset(f, 0, sizeof *f);
}

taa_buffer float_buffer(float* data, int width, int height, int channels) {
  taa_buffer b;
  memset(&b, 0, sizeof b);
  b.data = data;
  b.width = width;
  b.height = height;
  b.channels = channels;
  b.type = TAA_PIXEL_FLOAT;
  return b;
}

taa_buffer half_buffer(uint16_t* data, int width, int height, int channels) {
  taa_buffer b = float_buffer(NULL, width, height, channels);
  b.data = data;
  b.type = TAA_PIXEL_HALF;
  return b;
}

uint16_t float_to_half(float value) {
  uint32_t f;
  memcpy(&f, &value, 4);
  const uint32_t sign = (f >> 16) & 0x8000u;
  const int32_t exponent = (int32_t)((f >> 23) & 0xffu);
  uint32_t mantissa = f & 0x7fffffu;
  if (exponent == 0xff) return (uint16_t)(sign | 0x7c00u | (mantissa ? 0x200u : 0u));
  int32_t e = exponent - 127 + 15;
  if (e >= 0x1f) return (uint16_t)(sign | 0x7c00u); /* overflow -> inf */
  if (e <= 0) {                                     /* subnormal half or zero */
    if (e < -10) return (uint16_t)sign;
    mantissa |= 0x800000u;
    const int shift = 14 - e;
    uint32_t half = mantissa >> shift;
    const uint32_t rest = mantissa & ((1u << shift) - 1u), halfway = 1u << (shift - 1);
    if (rest > halfway || (rest == halfway && (half & 1u))) ++half;
    return (uint16_t)(sign | half);
  }
  uint32_t half = ((uint32_t)e << 10) | (mantissa >> 13);
  const uint32_t rest = mantissa & 0x1fffu;
  if (rest > 0x1000u || (rest == 0x1000u && (half & 1u))) ++half; /* may carry into inf: ok */
  return (uint16_t)(sign | half);
}

float half_to_float(uint16_t bits) {
  const uint32_t sign = (uint32_t)(bits & 0x8000u) << 16;
  const uint32_t exponent = (bits >> 10) & 0x1fu, mantissa = bits & 0x3ffu;
  float magnitude;
  if (exponent == 0) {
    magnitude = ldexpf((float)mantissa, -24);
  } else if (exponent == 0x1f) {
    magnitude = mantissa ? NAN : INFINITY;
  } else {
    magnitude = ldexpf((float)(mantissa | 0x400u), (int)exponent - 25);
  }
  uint32_t f;
  memcpy(&f, &magnitude, 4);
  f |= sign;
  memcpy(&magnitude, &f, 4);
  return magnitude;
}

taa_node* make_node(void) {
  taa_node* node = NULL;
  const taa_status status = taa_node_create(NULL, &node);
  CHECK(status == TAA_OK && node, "taa_node_create: status %d, %s", status, taa_last_error());
  return node;
}

taa_status resolve_fixture(taa_node* node, const fixture* f, int first, int count,
                           float* outputs) {
  const size_t frame_values = (size_t)f->width * f->height * 4;
  for (int i = 0; i < count; ++i) {
    const fixture_frame* in = &f->frames[first + i];
    taa_buffer color = float_buffer(in->color, f->width, f->height, 4);
    taa_buffer depth = float_buffer(in->depth, f->width, f->height, 1);
    taa_buffer motion = float_buffer(in->motion, f->width, f->height, 2);
    taa_buffer out = float_buffer(outputs + (size_t)i * frame_values, f->width, f->height, 4);
    taa_frame frame;
    taa_frame_init(&frame);
    frame.frame = in->frame;
    frame.color = &color;
    frame.depth = &depth;
    frame.motion = &motion;
    taa_status status = taa_node_push_frame(node, &frame);
    if (status == TAA_OK) status = taa_node_read_output(node, &out);
    if (status != TAA_OK) return status;
  }
  return TAA_OK;
}

float max_abs_diff(const float* a, const float* b, size_t n) {
  float worst = 0.0f;
  for (size_t i = 0; i < n; ++i) {
    const float d = fabsf(a[i] - b[i]);
    if (!(d <= worst)) worst = d; /* NaN wins */
  }
  return worst;
}
