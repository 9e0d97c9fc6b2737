/* taa's stable C ABI: a temporal anti-aliasing node for hosts (compositors, OpenFX plugins,
 * scripting languages). Plain C99; no C++ exception ever crosses it.
 *
 * ABI version rule. TAA_ABI_VERSION is one integer, compared with taa_abi_version() at run time.
 * Bump it for any change that can break a host compiled against an older header: a removed or
 * renamed function, a changed signature, a changed struct layout or enum value, or a changed
 * meaning of an existing parameter. Adding a function, a parameter name or an enum value at the
 * end is compatible and does not bump it. Structs are never grown in place: a new layout is a
 * new struct (taa_buffer2 ...).
 *
 * Usage:
 *   taa_node* node = NULL;
 *   if (taa_node_create(NULL, &node) != TAA_OK) puts(taa_last_error());
 *   taa_node_set_float(node, "blend", 0.1f);
 *   for each frame: fill a taa_frame (taa_frame_init), taa_node_push_frame, taa_node_read_output
 *   taa_node_destroy(node);
 * In window mode (below): push the frames, then taa_node_resolve_frame and taa_node_read_output
 * for each frame whose window is in.
 *
 * Conventions (the same as taatool's; see docs/ARCHITECTURE.md):
 * - Color is RGBA (3 channels read A = 1), premultiplied. NaN/Inf become 0.
 * - Depth is one channel, positive planar distance; values >= "depth-nohit", NaN and Inf mean
 *   nothing was hit.
 * - Motion is two channels in pixels, converted by the "motion-y", "motion-to" and
 *   "motion-scale" parameters exactly as taatool's flags of the same names.
 * - A buffer's row order (taa_buffer.y_up) only says how rows are laid out in memory; it never
 *   changes the meaning of vector values. Jitter is always in pixels, x right, y down.
 *
 * Window mode (parameter "mode" = "window", "window" = K): frame t is rebuilt from the raw
 * samples of frames t-K..t+K (taatool --mode window --window K). taa_node_push_frame then only
 * puts the frame into the node's ring of 2K+1 frames on the GPU (nothing is resolved), and
 * taa_node_resolve_frame(node, t) resolves t; taa_node_read_output reads that result.
 * - Frames may be pushed and resolved in any order; every result depends only on its window's
 *   frames and the parameters, so it is taatool's frame bit for bit.
 * - The window of t is what taatool's would be if the frames pushed so far were the sequence's
 *   files: the consecutively numbered frames within K of t, not crossing a shot boundary.
 *   taa_node_reset_history marks the next pushed frame as the first of a new shot. The node
 *   cannot know of frames it was never given: push every existing frame within K of t before
 *   resolving t (a frame never pushed ends the window, as a missing file ends taatool's).
 * - Every frame of the window must still be in the ring: otherwise taa_node_resolve_frame
 *   returns TAA_ERROR_MISSING_FRAME, naming the frame and why it is gone (never pushed,
 *   evicted, dropped, removed by a parameter change). Push it again and retry.
 * - Pushing a frame number the ring holds replaces that frame. Pushing into a full ring evicts
 *   the frame farthest in number from the new one (of two as far, the earlier one);
 *   taa_node_drop_frame takes a frame out explicitly (to keep an upcoming window whole).
 * - All frames in the ring have one size; a frame of another size must start a shot (it then
 *   empties the ring). Setting a resolve parameter to a new value empties the ring (its frames
 *   are stored in the working space the parameters choose); the input conventions
 *   ("motion-y", ...) and "output-type" do not. "reset-on-gap" does not apply: a gap always
 *   ends a window. Switching "mode" frees the other mode's history or ring.
 *
 * Threads: a node may be used from any thread, one call at a time. A call made while another
 * thread is inside a call on the same node returns TAA_ERROR_BUSY at once (the message goes to
 * taa_last_error(), not to the node). Different nodes run in parallel; each owns its own OpenGL
 * context, made current on the calling thread for the duration of a call and released after.
 */
#ifndef TAA_TAA_H
#define TAA_TAA_H

#include <stddef.h>

#include "taa/export.h"

#ifdef __cplusplus
extern "C" {
#endif

#define TAA_ABI_VERSION 1

typedef enum taa_status {
  TAA_OK = 0,
  TAA_ERROR_INVALID_ARGUMENT = 1, /* null pointer, wrong size, bad value */
  TAA_ERROR_UNKNOWN_PARAMETER = 2, /* taa_node_set_* with a name the node does not have */
  TAA_ERROR_WRONG_TYPE = 3,        /* taa_node_set_* of the wrong type for that parameter */
  TAA_ERROR_NO_OUTPUT = 4,         /* taa_node_read_output before any frame was pushed */
  TAA_ERROR_BUSY = 5,              /* another thread is inside a call on this node */
  TAA_ERROR_GL = 6,                /* no OpenGL context could be made, or GL failed */
  TAA_ERROR_INTERNAL = 7,          /* anything else; the message says what */
  TAA_ERROR_MISSING_FRAME = 8      /* window mode: a frame the resolve needs is not in the ring */
} taa_status;

typedef enum taa_pixel_type { TAA_PIXEL_HALF = 1, TAA_PIXEL_FLOAT = 2 } taa_pixel_type;

typedef enum taa_gl_backend {
  TAA_GL_AUTO = 0, /* EGL, falling back to OSMesa */
  TAA_GL_EGL = 1,
  TAA_GL_OSMESA = 2
} taa_gl_backend;

/* An image in host memory. Pixel (x, row) lives at
 *   (char*)data + row * row_stride_bytes + x * pixel_stride_bytes,
 * channel c at + c * (2 or 4 bytes). Strides may be negative; 0 means tightly packed. Row 0 is
 * the top row, or the bottom one when y_up is non-zero (OpenFX, OpenGL). */
typedef struct taa_buffer {
  void* data;
  int width, height;
  int channels;                /* channels this buffer holds for taa (see each use) */
  taa_pixel_type type;
  ptrdiff_t row_stride_bytes;   /* 0 = width * pixel stride */
  ptrdiff_t pixel_stride_bytes; /* 0 = channels * sizeof(type); larger skips unused channels */
  int y_up;                     /* non-zero: row 0 is the bottom row */
} taa_buffer;

/* One frame's inputs. Start from taa_frame_init() and fill what you have. */
typedef struct taa_frame {
  int frame;                 /* frame number: Halton index, and history continuity */
  const taa_buffer* color;   /* required: 3 or 4 channels */
  const taa_buffer* depth;   /* optional (NULL): 1 channel; enables motion dilation */
  const taa_buffer* motion;  /* optional (NULL): 2 channels; NULL = static scene */
  int has_jitter;            /* 0: jitter from the frame number and the "jitter*" parameters */
  float jitter[2];           /* with has_jitter: sample offset, pixels, x right, y down */
  /* Optional camera, 16 floats each, row-major row-vector matrices as in EXR headers
   * (worldToCamera: left-handed, +z forward; worldToNDC per the "ndc" parameter). With both,
   * the resolve can reproject from depth ("camera-motion"); the buffer is the whole display
   * window. */
  const float* world_to_camera;
  const float* world_to_ndc;
} taa_frame;

typedef struct taa_create_options {
  taa_gl_backend gl_backend;
  int defer_context; /* non-zero: make the GL context on first use instead of at create */
} taa_create_options;

typedef struct taa_node taa_node;

/* The ABI version of the loaded library (compare with TAA_ABI_VERSION). */
TAA_API int taa_abi_version(void);
/* The library's version string, e.g. "0.1.0". */
TAA_API const char* taa_version_string(void);

/* The message of the last failed call on this thread that had no node to keep it: a null
 * handle, a failed create, TAA_ERROR_BUSY. "" when none. Valid until the next call. */
TAA_API const char* taa_last_error(void);

TAA_API void taa_create_options_init(taa_create_options* options);
TAA_API void taa_frame_init(taa_frame* frame);

/* Creates a node (options may be NULL for defaults). On failure *node is NULL and
 * taa_last_error() says why. */
TAA_API taa_status taa_node_create(const taa_create_options* options, taa_node** node);
/* Destroys a node and its GL context; NULL is ignored. Not while another thread uses it. */
TAA_API void taa_node_destroy(taa_node* node);

/* The message of the node's last failed call ("" after a success). Valid until its next call. */
TAA_API const char* taa_node_last_error(const taa_node* node);

/* Parameters by name: taatool's option names without "--" ('_' may stand for '-').
 * - The resolve options, listed by `taatool --list-options` (e.g. "blend", "jitter",
 *   "jitter-offset", "rectify", "motion-dilation", "bracket", "mode", "window",
 *   "window-sigma"), take any of the three setters: the value is given to the option as
 *   taatool's text (ints as decimals, floats exactly).
 *   Colour, one rule in every face: the OCIO config of "colorspace-in" and "colorspace-out" is
 *   the file "ocio-config" names, else the one $OCIO names when it is set, else taa's shipped
 *   one; the brackets taa_reinhard and taa_log2 are taa's own and work in any config.
 * - The node's input conventions are typed, taatool's flags of the same names: "preset"
 *   (string: a renderer's motion and depth conventions, e.g. "cycles"; the host picks the
 *   channels; "" for taa's own), "motion-y" down|up, "motion-to" previous|next,
 *   "motion-units" pixels|ndc|uv, "motion-encoding" signed|centred (strings);
 *   "motion-scale", "motion-max" (floats); "depth-kind" planar|radial|ndc|reversed-z|inverse
 *   (string; radial needs the frame's camera or "depth-fov"); "depth-near", "depth-far",
 *   "depth-fov", "depth-nohit" (floats); "camera-sidecar" (string: taatool's JSON sidecar;
 *   a frame pushed without world_to_camera/world_to_ndc takes its entry's camera, without a
 *   jitter its entry's jitter; a frame without an entry is TAA_ERROR_INVALID_ARGUMENT);
 *   "reset-on-gap" 0/1 (int, default 1: in history mode, history restarts when a frame is
 *   not the previous one + 1, as taatool does); "ndc" zero-one-y-down|minus-one-one-y-up
 *   (string: what world_to_ndc maps to); "output-type" float|half (string, default float:
 *   the type the result is read back from the GPU in; half suits half output buffers: half
 *   the read-back, no conversion, the same values a float read-back narrowed gives); "aov"
 *   (string: the passes' kinds, taatool's --aov rules "PATTERN=kind" separated by ';', see
 *   taa_pass).
 * An unknown name gives TAA_ERROR_UNKNOWN_PARAMETER, a typed parameter set with another type
 * TAA_ERROR_WRONG_TYPE, a value out of range TAA_ERROR_INVALID_ARGUMENT; the message names the
 * parameter. Changes apply from the next pushed frame (window mode: the next push or resolve). */
TAA_API taa_status taa_node_set_int(taa_node* node, const char* name, int value);
TAA_API taa_status taa_node_set_float(taa_node* node, const char* name, float value);
TAA_API taa_status taa_node_set_string(taa_node* node, const char* name, const char* value);

/* History mode: resolves one frame. Window mode: puts the frame into the ring (evicting the
 * frame farthest from it when the ring is full, replacing a frame of the same number) and
 * resolves nothing. All buffers must have the same width and height. */
TAA_API taa_status taa_node_push_frame(taa_node* node, const taa_frame* frame);

/* A frame's other passes (issue 21): light passes, their colour (albedo) passes, data passes
 * and Cryptomatte, resolved with the beauty's own weights, so the comp's sums still add up
 * (Combined = sum of (Dir + Ind) x Col + Emit + Env, as Cycles writes them). Window mode only.
 * Each channel is named as the render names it ("ViewLayer.DiffDir.R",
 * "ViewLayer.CryptoObject00.r", "Normal.X") and read from one channel of a host buffer (half
 * or float, the colour's size; several channels may share a buffer, e.g. an RGBA plane). Its
 * kind comes from its name as taatool's defaults give it (README, "Every pass"), or from the
 * node's "aov" parameter (taatool's --aov rules, "PATTERN=kind" separated by ';'): light and
 * factor passes are summed (a light with its factor as the product, divided at the end),
 * normals averaged and renormalised, depth, IDs and other data taken from the frame's own
 * sample (never blended), Cryptomatte rank pairs re-weighed per ID. A channel keeps its
 * buffer's type in the ring: give light passes as half, Cryptomatte and positions as float, as
 * the render wrote them. */
typedef struct taa_pass {
  const char* name;          /* unique within a frame */
  const taa_buffer* buffer;  /* holds the channel's values */
  int channel;               /* which channel of `buffer` (0-based) */
} taa_pass;

/* taa_node_push_frame with the frame's `count` passes. Every frame in the ring carries the same
 * channels: pushing other names, kinds or types (or none) empties the ring of the frames pushed
 * with the old ones. count 0: none (taa_node_push_frame). History mode: TAA_ERROR_INVALID_ARGUMENT
 * (the message names "mode" = "window"). The ring holds every pass of its frames: where 2K+2
 * frames with these passes would take more than 3.25 GiB, the node's window is the longest that
 * fits (not shorter than "window-near"), as taatool's is, and its ring holds 2K+1 of those. */
TAA_API taa_status taa_node_push_frame_passes(taa_node* node, const taa_frame* frame,
                                              const taa_pass* passes, int count);

/* Copies channels of the last resolved frame's passes, each by name, into its buffer's channel
 * (the frame's size); a half buffer gets values rounded as Imath::half, clamped to +-65504, as
 * taatool writes a half channel. Any subset, in any order. TAA_ERROR_NO_OUTPUT when the last
 * resolved frame had no passes, TAA_ERROR_INVALID_ARGUMENT for a name it did not have. */
TAA_API taa_status taa_node_read_passes(taa_node* node, const taa_pass* passes, int count);

/* Window mode: resolves `frame` from its window of pushed frames (see "Window mode" above).
 * TAA_ERROR_MISSING_FRAME when the frame or one of its window is not in the ring (the message
 * says which and why); TAA_ERROR_INVALID_ARGUMENT in history mode. */
TAA_API taa_status taa_node_resolve_frame(taa_node* node, int frame);

/* Window mode: takes `frame` out of the ring (nothing when the ring does not hold it). It stays
 * known as pushed, so a window that needs it fails until it is pushed again.
 * TAA_ERROR_INVALID_ARGUMENT in history mode. */
TAA_API taa_status taa_node_drop_frame(taa_node* node, int frame);

/* Copies the last resolved frame into `output` (3 or 4 channels, the frame's size). */
TAA_API taa_status taa_node_read_output(taa_node* node, const taa_buffer* output);

/* The camera matrices given with the last pushed frame (window mode: with the last resolved
 * frame), 16 floats each, row-major. Either pointer may be NULL; a matrix the frame did not
 * carry comes back as zeros. Returns TAA_ERROR_NO_OUTPUT before the first frame. */
TAA_API taa_status taa_node_get_camera(taa_node* node, float world_to_camera[16],
                                       float world_to_ndc[16]);

/* History mode: forgets history, the next frame is resolved on its own (a cut). Window mode:
 * the next pushed frame starts a new shot (no window reaches across it). */
TAA_API taa_status taa_node_reset_history(taa_node* node);

#ifdef __cplusplus
}
#endif

#endif /* TAA_TAA_H */
