#include "capi_window_fixture.h"
#include "capi_test_util.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int window_fixture_load(const char* path, window_fixture* out) {
  memset(out, 0, sizeof *out);
  FILE* in = fopen(path, "rb");
  if (!in) {
    fprintf(stderr, "cannot open fixture %s\n", path);
    return 0;
  }
  char magic[8];
  int32_t header[4];
  int ok = fread(magic, 1, 8, in) == 8 && memcmp(magic, "TAAWIN01", 8) == 0 &&
           fread(header, sizeof(int32_t), 4, in) == 4 && header[3] == REFERENCE_COUNT;
  if (ok) {
    out->width = header[0];
    out->height = header[1];
    out->count = header[2];
    out->frames = calloc((size_t)out->count, sizeof(window_frame));
    ok = out->frames != NULL;
  }
  const size_t pixels = (size_t)out->width * out->height;
  for (int i = 0; ok && i < out->count; ++i) {
    window_frame* f = &out->frames[i];
    int32_t number;
    ok = fread(&number, sizeof number, 1, in) == 1 &&
         fread(f->world_to_camera, sizeof(float), 16, in) == 16 &&
         fread(f->world_to_ndc, sizeof(float), 16, in) == 16 &&
         fixture_read_floats(in, &f->color, pixels * 4) &&
         fixture_read_floats(in, &f->depth, pixels) &&
         fixture_read_floats(in, &f->motion, pixels * 2);
    for (int r = 0; ok && r < REFERENCE_COUNT; ++r) {
      ok = fixture_read_floats(in, &f->reference[r], pixels * 4);
    }
    f->frame = number;
  }
  fclose(in);
  if (!ok) fprintf(stderr, "fixture %s is truncated or malformed\n", path);
  return ok;
}

void window_fixture_free(window_fixture* f) {
  for (int i = 0; f->frames && i < f->count; ++i) {
    free(f->frames[i].color);
    free(f->frames[i].depth);
    free(f->frames[i].motion);
    for (int r = 0; r < REFERENCE_COUNT; ++r) free(f->frames[i].reference[r]);
  }
  free(f->frames);
  memset(f, 0, sizeof *f);
}
