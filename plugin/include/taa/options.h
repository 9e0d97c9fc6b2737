// Options of the resolve, one struct with defaults. Every field says its range and meaning.
// Fields marked [program] change the resolve shader's #defines: changing them between frames
// rebuilds the GL program; the others are uniforms and cost nothing to change.
#pragma once

#include <string>

#include "taa/version.h"

TAA_NAMESPACE_BEGIN

enum class JitterSource {
  Halton,  // Halton(2,3) at an index derived from the frame number (the default)
  None,    // the renderer did not jitter: samples sit at pixel centres
};

struct JitterOptions {
  JitterSource source = JitterSource::Halton;
  // Halton index = frame + indexOffset. Any integer; use it when the renderer's jitter index
  // is not the frame number (e.g. -1001 for a sequence starting at 1001 whose index starts at 0).
  int indexOffset = 0;
  // 0: the index grows forever. P > 0: the index cycles through 1..P (Halton's index 0, the
  // corner (-0.5, -0.5), is skipped, as game engines do with their 8- or 16-sample cycles).
  int period = 0;
  // Pixels of the images per pixel of the render the offsets were made for: Halton offsets are
  // in the renderer's pixels, so images scaled after rendering (a host's proxy at half size,
  // a downscaled plate) need them scaled alike: 0.5 at half size.
  float scale = 1.0f;
};

// The OpenColorIO tonemap bracket (DESIGN.md section 5): the resolve runs on colour converted
// from `colorspaceIn` into the `bracket` working space, and its result is converted from the
// working space into `colorspaceOut`. All fields are [program].
struct ColorOptions {
  // The OCIO config of the input and output colorspaces, one rule in every face. Empty: the
  // config the OCIO environment variable names when it is set (a studio's), else taa's shipped
  // config (ocio/config.ocio, embedded in the library). "$OCIO": the variable's, an error when
  // it is not set. Anything else: a file.
  std::string ocioConfig;
  // Colorspace (or role) of the input colour, e.g. "ACEScg". The default role exists in any
  // studio config; a config without it takes the input as linear.
  std::string colorspaceIn = "scene_linear";
  // Working space of the resolve. taa's own brackets, "taa_reinhard" (the default, worth +5 dB
  // on the HDR scene of the yardstick, docs/QUALITY.md) and "taa_log2", are maths that work in
  // any config: the input is converted to the config's scene_linear, compressed, resolved and
  // converted back. Otherwise a colorspace or named transform of the config, or "none" (the
  // resolve runs on input values).
  std::string bracket = "taa_reinhard";
  // Colorspace (or role) of the output. Empty: the same as colorspaceIn (the output keeps the
  // input's colorspace, and its header says which: taa:colorspace).
  std::string colorspaceOut;
};

// How frames are combined (DESIGN.md section 4).
enum class ResolveMode {
  History,  // the recursive resolve: each frame blended into a reprojected history image
  Window,   // frame t rebuilt from the raw samples of frames t-K..t+K, each carried along its
            // own motion; every frame independent of the others
};

// The longest window resolve: K frames each side at most (the gather's MAX_SOURCES is 2K).
constexpr int kMaxWindowRadius = 24;

// The window resolve's settings (used when mode is Window).
struct WindowOptions {
  // K: frames used on each side of the resolved frame (2K+1 in all), 0..24. The window stops
  // at the shot's ends (gaps, reset frames). Memory grows with it: 2K+1 frames are kept.
  int radius = 16;
  // Pixels: standard deviation of the Gaussian weighting a carried sample by its distance to
  // the output pixel's centre. Smaller is sharper and noisier. Typical 0.3 .. 0.6.
  float sigma = 0.35f;
  // Frames: temporal weight exp(-(distance / falloff)^2), a Gaussian falloff over the window;
  // 0 weighs every frame alike.
  float falloff = 14.0f;
  // Also weigh frames by a Hann taper over the window, cos^2(pi/2 distance / (K + 1)): frames
  // enter and leave the moving window gently, so the output does not step when they do.
  bool taper = false;
  // Colour consistency, in standard deviations: a carried sample farther than this from the
  // weighted mean of what the pixel gathered before it (its own frame's samples and those of
  // the frames nearer in time; YCoCg, working space, plus a small floor) loses its weight, so
  // shading that changes over the window (moving lights, shadows) does not smear. Larger
  // keeps more samples. 0 turns the test off.
  float colourTolerance = 3.0f;
  // The same test at the scale of a region, in standard errors of its mean: a frame two or more
  // away from t loses its static samples at a pixel where the luma mean of its static samples
  // over the 6x6 around the pixel's surface strays from t's own 6x6 mean (softly from this
  // many standard errors, wholly from twice as many). 36 samples see a change that one
  // sample's noise hides: a contact shadow moving with its object, a light's shadows
  // sweeping (docs/TUNING.md, "The region test": lit +0.46 dB, contact +0.47, inside its
  // shadow +2.5). 0 turns it off; off as well with passes (their rings take the memory).
  float regionTolerance = 3.0f;
  // The region test's tolerance within 16 px of a moving sample of t: a contact shadow moves
  // with its object, and a floor's one-sample noise keeps its 6x6 means within the looser test
  // (docs/TUNING.md, "The region test near moving objects": inside cycles_contact's shadow
  // 18.43 -> 19.77 dB; 1.5 kept more of it but left aliased lines beside moving objects).
  float regionToleranceNearMoving = 2.0f;
  // Pixels: a sample counts as static (carried by exact camera reprojection) when its motion
  // vector agrees with the camera's motion within this; otherwise its vectors are chained.
  float staticTolerance = 0.25f;
  // Weight of the resolved frame's own filtered reconstruction (the history mode's unjitter),
  // added as one more sample: it is what a pixel that gathers little falls back to.
  float reconstructionWeight = 0.1f;
  // Sum the samples' values in linear light (the input's values) instead of the bracket's
  // working space, whose average biases every edge between bright and dark; the colour tests
  // still decide on a compressed luma. Forces a shader rebuild. On by default: +0.65 dB on the
  // real-render yardstick together with opaqueMoving, no scene lower (docs/TUNING.md, sweep 7).
  bool linear = true;
  // A static sample landing where t's own nearest sample is a moving object (and not in front
  // of it) is hidden: a moving object stays opaque where it touches the floor it slides on
  // (cycles_contact: +2.4 dB inside the moving box).
  bool opaqueMoving = true;
  // Sum the samples apart in the four quadrants around the pixel centre and average the
  // quadrants' means: carried samples land at random, and a plain mean weighs each side of an
  // edge by how many samples happened to land there (+0.15 dB on the real-render yardstick, no
  // real scene lower; the analytic hdr_highlights -0.37: docs/TUNING.md, "Strata"). Passes
  // and Cryptomatte IDs are weighed as the beauty's mean weighs their samples, so they still
  // add up to it.
  bool strata = true;
  // Where t's 3x3 spans two surfaces, the near one's samples and the far one's are averaged
  // apart and mixed by the near surface's coverage: its samples' weight over the weight they
  // would have had were it everywhere. A plain mean counts the far surface's samples that land
  // inside the near one's footprint from frames where parallax had it elsewhere, and thins
  // every edge and wire (the 1080p fence: 1.7 px power lines dashed, +5.4 dB on frame 12;
  // docs/TUNING.md, "Two clusters"). Passes and mattes are weighed alike, as with strata.
  bool twoClusters = true;
  // Each side of a pixel's window ends at the first source frame whose samples disagree with
  // what the nearer frames gave (the colour test): a long window where the shot holds still,
  // a short one where shading changes.
  bool adaptive = false;
  // Frames each side always used; with 0 < near < radius, each side of a 32 px tile's window
  // reaches on, frame by frame, while the farther frame's samples agree with t's over the tile
  // (resolve/window_tiles): a long window where the shading holds still, a short one where it
  // changes. 0: the whole window everywhere.
  int nearRadius = 2;
  // Frames each side whose moving samples count, and all the samples of a pixel whose own 3x3
  // at t has a moving one: a moving object's chains stay short, and static samples of farther
  // frames would outweigh its own at its edges. 0: the whole window.
  int movingRadius = 4;
  // Pixels each way around the pixel where t's own samples are searched for a thin feature's
  // depth (a wire t's 3x3 missed), 0..kMaxThinSearch; the other frames' samples at that depth
  // are then gathered too: under parallax they lie a pixel or more from the backdrop's
  // (cycles_fence +2.9 dB, docs/TUNING.md, "The thin search"). 0 or 1: t's 3x3 alone.
  static constexpr int kMaxThinSearch = 8;
  int thinSearchRadius = 4;
  // A pixel stops gathering once it has settled: t's own 3x3 samples and every sample mean of
  // its first kSettleSources agreeing source frames lie within this fraction of the pixel's
  // brightest channel (alpha within this much). Its farther frames would only add the same
  // value: flat colour (sky, flat-shaded or procedural surfaces, mattes) costs a fraction of
  // the window. Pixels with two surfaces, a thin feature or a moving sample near (within 16 px
  // where the thin search or the region test runs the surroundings pass, else in the 3x3)
  // never settle. 0: off (docs/PERFORMANCE.md, "Settled pixels").
  static constexpr int kSettleSources = 4;
  float settle = 0.005f;
  // Beside a moving object (where the region test is stricter, --window-region-near-moving) a
  // pixel whose other frames were left out, as the floor in a contact shadow that moves with
  // the object, had only its nearest own samples: the render's noise, as it was. Such a pixel
  // also takes t's 3x3 samples of its own surface under a wider Gaussian (1 px), with this
  // weight where it gathered nothing from other frames, falling to none at
  // kOwnFallbackGathered. 0: off (docs/TUNING.md, "A contact shadow's own samples").
  static constexpr float kOwnFallbackGathered = 2.0f;
  float ownFallback = 1.5f;
};

enum class Reconstruction { Centre, BlackmanHarris, Lanczos2 };
enum class MotionDilation { Centre, Plus, Box3x3 };
enum class CameraMotion { Vectors, Fill, PreferCamera, Camera };
enum class HistoryFilter { Bilinear, CatmullRom };
enum class Rectify { None, Clamp, Clip, VarianceClip };
enum class BoxSpace { RGB, YCoCg };
enum class Neighbourhood { Plus5, Box9 };

// The resolve's stages (DESIGN.md section 4), in pipeline order. Defaults are chosen from the
// quality yardstick (docs/QUALITY.md), not by eye.
struct ResolveOptions {
  // How frames are combined: the window resolve (the default: +3 dB over the history resolve
  // on the real renders, docs/QUALITY.md), or the recursive history resolve (2.5x faster). The
  // stages below marked (history) apply to the history resolve only; `window` to the window
  // resolve. The C ABI's node starts in history mode (capi/node_parameters.h).
  ResolveMode mode = ResolveMode::Window;
  WindowOptions window;

  // --- unjitter
  // Filter reconstructing the current frame at pixel centres from the 3x3 jittered
  // samples: Centre (the pixel's own sample, no filter), BlackmanHarris (soft, no ringing),
  // Lanczos2 (sharper, small negative lobes).
  Reconstruction reconstruction = Reconstruction::Lanczos2;
  // Keep the reconstructed colour within its 3x3 samples' per-channel range: Lanczos-2's
  // negative lobes otherwise ring around high-contrast edges, down to negative values beside
  // bright ones.
  bool antiRinging = false;
  // How each frame's samples were offset from pixel centres.
  JitterOptions jitter;

  // --- reprojection
  // [program] Motion taken from the pixel itself, or from the closest-depth pixel of the plus
  // (5) or 3x3 (9) neighbourhood so foreground edges carry their own motion. Needs depth.
  MotionDilation motionDilation = MotionDilation::Box3x3;
  // [program] Motion from depth and the two frames' camera matrices (needs both):
  //   Vectors       motion vectors only (zero where there is no motion AOV)
  //   Fill          vectors; camera motion where there are no vectors, or where the vectors are
  //                 zero on pixels with no geometry (renderers write zero on the sky)
  //   PreferCamera  as Fill, and camera motion wherever it agrees with the vector within
  //                 cameraAgreement pixels (exact for static geometry); the vector otherwise
  //   Camera        camera motion only (static scenes, or no motion AOV)
  CameraMotion cameraMotion = CameraMotion::Fill;
  // Pixels; PreferCamera's agreement tolerance. >= 0.
  float cameraAgreement = 0.5f;

  // --- history
  // [program] Bilinear (cheap, blurs under motion) or Catmull-Rom from 5 bilinear taps.
  HistoryFilter historyFilter = HistoryFilter::CatmullRom;

  // --- validation
  // Relative depth difference between the surface seen now and the one history saw that counts
  // as disocclusion (history rejected). 0 turns the test off. Typical 0.02 .. 0.2.
  float depthTolerance = 0.1f;
  // [program] How history is brought back inside the current neighbourhood's colour box:
  //   None          keep it (diagnosis only: ghosts)
  //   Clamp         clamp each component to the min/max box (the textbook version)
  //   Clip          move it toward the filtered colour until it enters the min/max box
  //   VarianceClip  clip to mean +- varianceGamma sigma, intersected with the min/max box
  Rectify rectify = Rectify::VarianceClip;
  // [program] Colour space of the neighbourhood box: YCoCg hugs natural colours tighter.
  BoxSpace boxSpace = BoxSpace::YCoCg;
  // [program] Neighbours forming the box: plus-shaped 5 or 3x3 9.
  Neighbourhood neighbourhood = Neighbourhood::Box9;
  // Width of the variance box in standard deviations, > 0. Smaller rejects more (less ghosting,
  // more flicker). Typical 0.75 .. 1.5.
  float varianceGamma = 1.0f;
  // 0..1: on pixels where depth confirms the same surface and motion is slow, keep this much of
  // the unrectified history, so sub-pixel wires the 3x3 box misses do not fade. Risk: ghosting of
  // shading changes (moving shadows, reflections) on static geometry.
  float thinFeatureHold = 1.0f;
  // Pixels per frame at which the thin-feature hold has faded out completely. > 0.
  float thinFeatureHoldSpeed = 8.0f;

  // --- blend
  // Weight of the current frame in the exponential blend, in (0, 1]. Smaller accumulates more
  // frames (smoother, more ghosting risk); 1 turns accumulation off.
  float blend = 0.04f;
  // Weight of the current frame at high speed, in [0, 1]; values <= blend turn it off. Moving
  // pixels get more of the current frame, since resampled history is softer.
  float velocityBlend = 0.25f;
  // Pixels per frame at which velocityBlend is reached. > 0.
  float velocityScale = 1.0f;
  // 0..1: where history and current luma agree, lower the current weight by this fraction
  // (steadier); where they differ, keep blend (responsive).
  float antiFlicker = 0.0f;
  // Weight history and current by 1 / (1 + luma) so single bright samples cannot dominate.
  bool lumaWeighting = false;
  // Per-pixel sample count: the current weight is at least 1 / (samples so far), so a pixel
  // that just got valid history (first frames, disocclusion) converges at once.
  bool sampleCount = true;

  // --- cuts
  // Fraction of pixels (0..1) whose history is rejected (off-screen or disoccluded) above which
  // a frame is taken as a cut: it is resolved again with history reset. 0 turns detection off.
  // Needs depth to see cuts; explicit cuts go in SequenceJob::resetFrames (--reset-frames).
  float cutDetection = 0.0f;

  // --- output (never fed back into history)
  // Unsharp-mask amount on the output, >= 0 (0: off). Limited to the neighbours' range.
  float sharpen = 0.0f;

  // [program] The tonemap bracket around the resolve.
  ColorOptions color;
};

TAA_NAMESPACE_END
