#include "resolve/window_resolver.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "color/ocio_bracket.h"
#include "color/ocio_gpu_resources.h"
#include "gl/objects.h"
#include "resolve/pass_band_stream.h"
#include "resolve/pass_packs.h"
#include "resolve/reconstruction_filter.h"
#include "resolve/resolve_input.h"
#include "resolve/window_budget.h"
#include "resolve/window_frame_weight.h"
#include "resolve/window_tiles.h"
#include "taa/error.h"
#include "util/frame_buffer_pool.h"
#include "util/frame_span.h"

namespace taa {
namespace {

// Texture units. Every pass binds its own inputs from unit 0; the bracket's LUTs follow.
enum TextureUnit : int {
  kRingUnit = 0,       // gather and classify: the ring
  kRingMotionUnit,     // and its motion
  kColourStageUnit = 0,  // prepare: the staged frame
  kDepthStageUnit,
  kMotionStageUnit,
  kFirstOcioUnit,
  kTileReachUnit = kMotionStageUnit  // gather: the tile test's reach per tile
};

// The tile test (--window-near): its statistics at every 4th pixel each way (a sixteenth of a
// gather's cost), pooled over tiles of 32 px (64 pixels each; docs/TUNING.md, "The tile
// test": every 2nd pixel with 16 px tiles scored no better, at four times the cost).
constexpr int kStatsStride = 4;
constexpr int kTileSize = 32;

// The region test's stricter tolerance (--window-region-near-moving) holds within this many
// blocks of one holding a moving sample of t, a block a pixel at the yardstick's 320x180 and
// more in a larger picture (nearMovingStride; window_near_moving.frag): a contact shadow's
// reach grows with the picture (docs/TUNING.md, "The region test near moving objects": 8 px
// kept less of the shadow at 320x180; "Contact shadows at 1080p": at 1080p 16 px gave 18.90 dB
// inside cycles_contact's shadow, 96 px 23.04).
constexpr int kNearMovingRadius = 16;
constexpr int kNearMovingReferenceSize = 180;  // the shorter side where a block is a pixel

constexpr int kMaxSources = 2 * kMaxWindowRadius;  // window_gather.frag's MAX_SOURCES
// Pass groups one gather writes besides the colour and diagnostics as draw buffers: 8, GL's
// guaranteed minimum, less those two. (4, to save two frame-sized targets, cost more time
// than the memory was worth: docs/PERFORMANCE.md, "Fourth measurement".) With image stores
// (OpenGL 4.2) a draw writes as many as the context's units hold (passGroupsPerDraw).
constexpr int kPassGroupsPerDrawBuffers = 6;
constexpr int kCryptomatteRanks = 3;  // rank layers a Cryptomatte set's draw writes
// With image stores a pass draw runs in bands of this many rows, its sums written to images of
// a band's size and read back after each band: fifteen frame-sized RGBA32F sums (a render's
// every pass in one draw) take 500 MB at 1080p, 300 MB more than six, on a run whose bar is
// 4 GiB (docs/PERFORMANCE.md, "Seventh measurement": its peak rose 290 MB). Bands of 128 rows
// rather than 256 leave 86 MB more of that bar (the band's images here and its buffer in the
// writer's stream) to a frame's read buffers kept for the next (docs/PERFORMANCE.md, "Every
// pass reusing its buffers").
constexpr int kPassBandRows = 128;

// How window_classify.frag decides which samples are static.
enum class Classify : int { NoCamera = 0, PreviousCamera = 1, NextFrame = 2, AllStatic = 3 };

void validateOptions(const ResolveOptions& o) {
  const WindowOptions& w = o.window;
  if (w.radius < 0 || 2 * w.radius > kMaxSources) {
    throw Error("window radius must be in [0, " + std::to_string(kMaxSources / 2) + "], got " +
                std::to_string(w.radius));
  }
  if (!(w.sigma > 0.0f)) throw Error("window sigma must be > 0");
  if (!(w.falloff >= 0.0f)) throw Error("window falloff must be >= 0");
  if (!(w.colourTolerance >= 0.0f)) throw Error("window colour tolerance must be >= 0");
  if (!(w.regionTolerance >= 0.0f)) throw Error("window region tolerance must be >= 0");
  if (!(w.regionToleranceNearMoving >= 0.0f)) {
    throw Error("window region tolerance near moving objects must be >= 0");
  }
  if (!(w.settle >= 0.0f && w.settle <= 1.0f)) throw Error("window settle must be in [0, 1]");
  if (!(w.ownFallback >= 0.0f)) throw Error("window own fallback must be >= 0");
  if (!(w.staticTolerance >= 0.0f)) throw Error("window static tolerance must be >= 0");
  if (!(w.reconstructionWeight >= 0.0f)) throw Error("window reconstruction weight must be >= 0");
  if (w.nearRadius < 0) throw Error("window near radius must be >= 0");
  if (w.movingRadius < 0) throw Error("window moving radius must be >= 0");
  if (w.thinSearchRadius < 0 || w.thinSearchRadius > WindowOptions::kMaxThinSearch) {
    throw Error("window thin search must be in [0, " +
                std::to_string(WindowOptions::kMaxThinSearch) + "], got " +
                std::to_string(w.thinSearchRadius));
  }
  if (!(o.depthTolerance >= 0.0f)) throw Error("depth tolerance must be >= 0");
}

}  // namespace

struct WindowResolver::Impl {
  gl::Context& context;
  const gl::Functions& gl;
  ResolveOptions options;
  gl::FullscreenTriangle triangle;

  gl::Program prepareProgram, classifyProgram, countMovingProgram, regionStatsProgram;
  // What the gather needs from around each pixel of the frame resolved
  // (window_surroundings.frag): along rows, then along columns of those.
  gl::Program surroundingsRowProgram, surroundingsProgram;
  gl::Texture surroundingRows, surroundings;
  gl::Framebuffer surroundingRowsTarget, surroundingsTarget;
  // Where a moving sample of t is near, on blocks of nearMovingStride() pixels
  // (window_near_moving.frag): which blocks have one, then those widened along rows, then
  // along columns.
  gl::Program nearMovingBlocksProgram, nearMovingWidenProgram;
  gl::Texture nearMovingBlocks, nearMovingRows, nearMoving;
  gl::Framebuffer nearMovingBlocksTarget, nearMovingRowsTarget, nearMovingTarget;
  // The gather's variants, built when first needed (gatherVariant): with and without the chains
  // of moving samples (a window whose frames have no moving sample uses the one without, which
  // llvmpipe runs in half the time), and with and without the static samples' camera carry (a
  // resolved frame without a camera has none: vectors only), that carry for pinhole cameras
  // alone or for any (resolve/camera's isPinhole: a pinhole carry's offset is a translation,
  // and 14 of the 48 values each source loads lane by lane are zeros). llvmpipe would run the
  // code left out for every pixel, masked.
  // Each variant's draws (gatherProgram): the beauty, PASS_GROUPS n (1 to passGroupsPerDraw),
  // with or without the first Cryptomatte set, CRYPTOMATTE, TILE_STATS; by (variant, draw,
  // Cryptomatte joined, image stores: passImages, which a new pass plan may change).
  static constexpr int kGatherVariants = 6;  // chains (bit 0) x STATIC_SAMPLES 0, 1, 2
  static constexpr int kCryptomatteDraw = -1, kTileStatsDraw = -2;
  std::vector<std::string> gatherPrefix[kGatherVariants];
  color::OcioBracket::Range gatherWorkingRange{};  // glsl/finite_range.glsl's limits
  std::map<std::tuple<int, int, bool, bool, std::string>, gl::Program> gatherPrograms;
  gl::AnySamplesQuery movingQuery;
  // The tile test: its targets (the gather's TILE_STATS draw writes them), the tiles' reach.
  gl::Texture stats[4], tileReach;
  gl::Framebuffer statsTarget;
  // The statistics read back, and unpacked to a code per pixel and source: kept between frames.
  std::vector<float> statsWords;
  std::vector<std::uint8_t> statsCodes;
  color::OcioGpuResources toWorkingLuts, fromWorkingLuts;
  color::OcioGpuResources gatherToWorkingLuts;  // linear sums: after fromWorkingLuts' units

  // The ring: one layer per frame, each sample's colour (the bracket's working space, 16 bits
  // of mantissa) and depth (a float, signed by window_classify.frag) packed in one texel
  // (window_ring.glsl); its motion at the same layer of the motion ring, as halves (1/1024 px
  // at 1 px, 1/64 at 64). One layer more than the ring holds: a frame is (re)classified from
  // its layer into the spare one, and the two swap.
  int width = 0, height = 0;
  gl::TextureArray ring, ringMotion;
  std::vector<gl::Framebuffer> layerTargets;
  // The region test's statistics (window_region_stats.frag), a layer per ring layer, kept
  // while the layer's classification stands (RGBA32F at a quarter of the pixels: 4 bytes a pixel
  // a layer). None with passes: their rings take the memory (issue 21's bar).
  gl::TextureArray regionStats;
  std::vector<gl::Framebuffer> regionTargets;
  int spareLayer = 0;
  // A frame passes through these on its way into the ring.
  gl::Texture colourStage, depthStage, motionStage;
  SampleType colourStageType = SampleType::Float;
  gl::Texture output, debug;
  gl::Framebuffer gatherTarget;
  bool gatherHasDebug = false;

  // With passes a run's peak memory is its bar (4 GiB at 1080p with every pass), and idle
  // buffers in the frame buffer pool were 55 MB of it, for no time (docs/PERFORMANCE.md,
  // "Every pass and the pool"): while this resolver has passes the pool keeps none, whichever
  // face (taatool, taa-farm, the C ABI, Python, OpenFX) drives it. Declared before the buffers
  // it covers, so that it outlives them.
  std::optional<FrameBuffersNotKept> buffersNotKept;
  // Passes (setPassGroups): the groups of four values in rings of several groups of one type
  // side by side (resolve/pass_packs), a layer per frame that stays put (the colour ring's
  // layers swap as frames are classified); the sums of the last frame.
  std::vector<bool> passHalf;
  PassPackLayout passLayout;
  std::vector<gl::TextureArray> passPackRings;  // per pack of passLayout
  std::vector<unsigned char> passUploadBand;    // a band of a pack's rows, for its upload
  std::vector<int> freePassLayers;
  // The sums of one draw (its groups', and a Cryptomatte set's three rank layers from
  // cryptomatteOutput()), read back before the next draw writes them: with image stores as
  // many as a draw writes (15 for a render's every pass: one draw), else 6.
  std::vector<gl::Texture> passOutputs;
  // Per draw: output, debug, and without image stores its groups' sums.
  std::vector<gl::Framebuffer> passTargets;
  PassSums lastSums;  // read back as the groups' ring type: half groups' sums as half
  int cryptomatteSets = 0;
  std::vector<gl::TextureArray> cryptomatteRings;  // RGBA32F, at the frames' pass layers
  std::vector<gl::Framebuffer> cryptomatteTargets;  // a set's draw: -, -, its three ranks
  // With passes the beauty's own draw runs first: its stratified or two-cluster mean counts
  // each sample by a factor of the pixel's (window_gather.frag, SHARES), which it writes here;
  // the pass and Cryptomatte draws weigh their values by the same factors, so that the passes
  // add up to the beauty and a matte follows its edges.
  gl::Texture shares;

  // How a frame's samples were last classified (window_classify.frag's modes).
  struct Slot {
    int layer = 0;
    Classify classified = Classify::NoCamera;
    bool classifiedOnce = false;
    glm::vec2 jitter{0.0f};
    std::optional<FrameCamera> camera;
    RasterWindow window;
    NdcConvention ndc = NdcConvention::ZeroOneYDown;
    bool hasDepth = false, hasMotion = false;
    bool hasMoving = false;  // any sample classified moving
    bool pinhole = false;    // its camera's rays meet at its origin (resolve/camera: isPinhole)
    int passLayer = -1;
  };
  std::map<int, Slot> slots;
  std::vector<int> freeLayers;

  bool debugOutput = false;
  Image lastDebug;
  // Stand-ins for a missing depth or motion AOV, made when first needed (24 MB at 1080p).
  std::vector<float> ones, zeros;

  Impl(gl::Context& ctx, const ResolveOptions& opts)
      : context(ctx), gl(ctx.functions()), options(opts), triangle(gl) {
    buildPrograms();
  }

  int capacity() const { return 2 * options.window.radius + 1; }

  void buildPrograms() {
    const color::OcioBracket bracket(options.color);
    // Linear sums: the ring keeps input values and the gather takes them through the bracket
    // and back at the end (into the output colorspace), so it needs both functions.
    const bool linear = options.window.linear;
    const std::string linearDefine = "#define LINEAR_SUM " + std::string(linear ? "1" : "0");
    prepareProgram = gl::Program(
        gl, gl::embeddedShaderSource("fullscreen.vert"),
        gl::embeddedShaderSource("window_prepare.frag",
                                 {linearDefine, bracket.toWorking()->getShaderText()}));
    classifyProgram = gl::Program(gl, "fullscreen.vert", "window_classify.frag");
    countMovingProgram = gl::Program(gl, "fullscreen.vert", "window_count_moving.frag");
    regionStatsProgram = gl::Program(gl, "fullscreen.vert", "window_region_stats.frag");
    surroundingsRowProgram = gl::Program(gl, gl::embeddedShaderSource("fullscreen.vert"),
                                         gl::embeddedShaderSource("window_surroundings.frag",
                                                                  {"#define FROM_RING 1"}));
    surroundingsProgram = gl::Program(gl, gl::embeddedShaderSource("fullscreen.vert"),
                                      gl::embeddedShaderSource("window_surroundings.frag",
                                                               {"#define FROM_RING 0"}));
    nearMovingBlocksProgram = gl::Program(gl, gl::embeddedShaderSource("fullscreen.vert"),
                                          gl::embeddedShaderSource("window_near_moving.frag",
                                                                   {"#define FROM_RING 1"}));
    nearMovingWidenProgram = gl::Program(gl, gl::embeddedShaderSource("fullscreen.vert"),
                                         gl::embeddedShaderSource("window_near_moving.frag",
                                                                  {"#define FROM_RING 0"}));
    for (int variant = 0; variant < kGatherVariants; ++variant) {
      std::vector<std::string> prefix = {
          "#define CHAINS " + std::to_string(variant & 1),
          "#define STATIC_SAMPLES " + std::to_string(variant >> 1), linearDefine,
          bracket.fromWorking()->getShaderText()};
      if (linear) prefix.push_back(bracket.toWorking()->getShaderText());
      gatherPrefix[variant] = prefix;
    }
    toWorkingLuts = color::OcioGpuResources(gl, bracket.toWorking(), kFirstOcioUnit);
    fromWorkingLuts = color::OcioGpuResources(gl, bracket.fromWorking(), kFirstOcioUnit);
    gatherToWorkingLuts =
        linear ? color::OcioGpuResources(gl, bracket.toWorking(),
                                         kFirstOcioUnit + fromWorkingLuts.unitCount())
               : color::OcioGpuResources();
    toWorkingLuts.setUniforms(prepareProgram);
    // glsl/finite_range.glsl's limits: the bracket's image of half's range, or that range
    // itself for input values.
    const color::OcioBracket::Range range =
        linear ? color::OcioBracket::Range{-65504.0f, 65504.0f} : bracket.workingRange();
    gatherWorkingRange = range;
    movingQuery = gl::AnySamplesQuery(gl);
    gatherPrograms.clear();
  }

  bool tileTest() const {
    return options.window.nearRadius > 0 && options.window.nearRadius < options.window.radius;
  }

  // A variant's gather: `draw` 0 the beauty alone, n > 0 with n pass groups laid out in their
  // packs as `packDefines` say (passPackDefines; and, with `joinedCryptomatte`, a Cryptomatte
  // set: image stores only), kCryptomatteDraw a Cryptomatte set, kTileStatsDraw the tile
  // test's statistics. Built when first needed.
  const gl::Program& gatherProgram(int variant, int draw, bool joinedCryptomatte = false,
                                   const std::vector<std::string>& packDefines = {}) {
    std::string layout;
    for (const std::string& line : packDefines) layout += line + "\n";
    const auto key = std::make_tuple(variant, draw, joinedCryptomatte, passImages(), layout);
    auto found = gatherPrograms.find(key);
    if (found != gatherPrograms.end()) return found->second;
    std::vector<std::string> prefix = gatherPrefix[variant];
    prefix.insert(prefix.begin(), packDefines.begin(), packDefines.end());
    if (draw != 0) {
      prefix.insert(prefix.begin(), draw == kTileStatsDraw     ? std::string("#define TILE_STATS 1")
                                    : draw == kCryptomatteDraw ? std::string("#define CRYPTOMATTE 1")
                                    : "#define PASS_GROUPS " + std::to_string(draw));
    }
    if ((draw > 0 || draw == kCryptomatteDraw) && passImages()) {
      if (joinedCryptomatte) prefix.insert(prefix.begin(), "#define CRYPTOMATTE 1");
      prefix.insert(prefix.begin(), "#define PASS_IMAGES 1");
      // Ahead of the bracket's code in the prefix: an #extension precedes any code.
      prefix.insert(prefix.begin(), "#extension GL_ARB_shader_image_load_store : require");
    }
    gl::Program p(gl, gl::embeddedShaderSource("fullscreen.vert"),
                  gl::embeddedShaderSource("window_gather.frag", prefix));
    fromWorkingLuts.setUniforms(p);
    if (options.window.linear) gatherToWorkingLuts.setUniforms(p);
    p.set("uWorkingRange", gatherWorkingRange.lo, gatherWorkingRange.hi);
    return gatherPrograms.emplace(key, std::move(p)).first->second;
  }
  // The variant of the gather (gatherPrograms) frame's window first..last needs.
  int gatherVariant(bool chains, int frame, int first, int last) const {
    const Slot& target = slots.at(frame);
    const bool cameras = target.camera && options.cameraMotion != CameraMotion::Vectors;
    // The pinhole carry where every carry is between pinhole cameras (the sources without a
    // camera carry nothing by the cameras).
    bool pinhole = target.pinhole;
    for (int f : FrameSpan(first, last)) {
      const Slot& source = slots.at(f);
      pinhole = pinhole && (!source.camera || source.pinhole);
    }
    const int staticSamples = !cameras ? 0 : pinhole ? 2 : 1;
    return (chains ? 1 : 0) + 2 * staticSamples;
  }

  // The first texture unit free for the passes: after the bracket's LUTs.
  int firstPassUnit() const {
    return kFirstOcioUnit + fromWorkingLuts.unitCount() + gatherToWorkingLuts.unitCount();
  }

  bool hasPasses() const { return !passHalf.empty() || cryptomatteSets > 0; }
  bool regionTest() const { return options.window.regionTolerance > 0.0f && !hasPasses(); }
  // Whether the gather writes its pass sums and Cryptomatte ranks as images (OpenGL 4.2's
  // image stores) rather than draw buffers: then one draw holds every pass group (up to
  // passGroupsPerDraw) and the first Cryptomatte set, and a frame's weights are worked out
  // once rather than once a draw (docs/PERFORMANCE.md, "One draw for every pass"). Runs with
  // pass groups only: Cryptomatte alone is one draw a set either way.
  bool passImages() const {
    return !passHalf.empty() &&
           context.info().fragmentImageUnits >= kPassGroupsPerDrawBuffers + kCryptomatteRanks;
  }
  int passGroupsPerDraw() const {
    if (!passImages()) return kPassGroupsPerDrawBuffers;
    const gl::ContextInfo& info = context.info();
    // Texture units past firstPassUnit: the groups' rings, then cryptomatteUnit's two, the
    // region statistics and the surroundings.
    const int byTextures = info.fragmentTextureUnits - firstPassUnit() - 4;
    const int byImages = info.fragmentImageUnits - kCryptomatteRanks;
    return std::max(kPassGroupsPerDrawBuffers, std::min(byTextures, byImages));
  }
  // A Cryptomatte set's ring, and the beauty's shares at the unit after it.
  int cryptomatteUnit() const { return firstPassUnit() + passGroupsPerDraw(); }
  int sharesUnit() const { return cryptomatteUnit() + 1; }
  // The first of passOutputs a Cryptomatte set's ranks are written to.
  int cryptomatteOutput() const {
    return passImages() ? std::min(int(passHalf.size()), passGroupsPerDraw()) : 0;
  }
  // The unit the gather reads the region statistics from: past the pass groups' units.
  int regionStatsUnit() const { return cryptomatteUnit() + 2; }
  // A radius of 1 searches t's 3x3 alone, which the gather reads anyway: nothing to find.
  bool thinSearch() const { return options.window.thinSearchRadius > 1; }
  int surroundingsUnit() const { return regionStatsUnit() + 1; }
  // Pixels a block of the near-moving search takes each way (kNearMovingRadius): the shorter
  // side over 180, at least 1 (6 at 1920x1080).
  int nearMovingStride() const {
    return std::max(1, std::min(width, height) / kNearMovingReferenceSize);
  }

  // window_surroundings.frag's reductions around each pixel of `frame` (t, just classified):
  // the thin search's depth, and nearness to a moving sample for the region test.
  void writeSurroundings(int frame) {
    if (!surroundings.id()) {
      surroundingRows = gl::Texture(gl, width, height, GL_R32F);  // the rows' nearest depth
      surroundings = gl::Texture(gl, width, height, GL_RG32F);
      surroundingRowsTarget = gl::Framebuffer(gl, surroundingRows);
      surroundingsTarget = gl::Framebuffer(gl, surroundings);
    }
    const int thinRadius = thinSearch() ? options.window.thinSearchRadius : 0;
    // A frame without a moving sample has none near any pixel, and one without cameras has
    // only moving samples, where the region test never runs: their rows skip the wider loop.
    const Slot& slot = slots.at(frame);
    const bool moving =
        regionTest() && slot.hasMoving && slot.classified != Classify::NoCamera;
    if (moving) writeNearMoving(slot.layer);
    const gl::Program& rows = surroundingsRowProgram;
    rows.set("uRing", int(kRingUnit));
    rows.set("uLayer", slot.layer);
    rows.set("uRadius", thinRadius);
    surroundingRowsTarget.bind();
    rows.use();
    ring.bind(kRingUnit);
    triangle.draw("window surroundings pass (rows)");
    const gl::Program& columns = surroundingsProgram;
    columns.set("uRows", 0);
    columns.set("uRadius", thinRadius);
    columns.set("uAnyMoving", moving ? 1 : 0);
    columns.set("uNearMoving", 1);
    columns.set("uNearMovingStride", nearMovingStride());
    surroundingsTarget.bind();
    columns.use();
    surroundingRows.bind(0);
    if (moving) nearMoving.bind(1);
    triangle.draw("window surroundings pass (columns)");
  }

  // window_near_moving.frag: the blocks within kNearMovingRadius blocks of one where a sample
  // of ring layer `layer` moves.
  void writeNearMoving(int layer) {
    const int stride = nearMovingStride();
    const int blocksWide = (width + stride - 1) / stride;
    const int blocksHigh = (height + stride - 1) / stride;
    if (!nearMoving.id()) {
      nearMovingBlocks = gl::Texture(gl, blocksWide, blocksHigh, GL_R32F);
      nearMovingRows = gl::Texture(gl, blocksWide, blocksHigh, GL_R32F);
      nearMoving = gl::Texture(gl, blocksWide, blocksHigh, GL_R32F);
      nearMovingBlocksTarget = gl::Framebuffer(gl, nearMovingBlocks);
      nearMovingRowsTarget = gl::Framebuffer(gl, nearMovingRows);
      nearMovingTarget = gl::Framebuffer(gl, nearMoving);
    }
    const gl::Program& blocks = nearMovingBlocksProgram;
    blocks.set("uRing", int(kRingUnit));
    blocks.set("uLayer", layer);
    blocks.set("uStride", stride);
    nearMovingBlocksTarget.bind();
    blocks.use();
    ring.bind(kRingUnit);
    triangle.draw("window near-moving blocks");
    const gl::Program& widen = nearMovingWidenProgram;
    widen.set("uBlocks", 0);
    widen.set("uReach", kNearMovingRadius);
    widen.use();
    widen.set("uAlongColumns", 0);
    nearMovingRowsTarget.bind();
    nearMovingBlocks.bind(0);
    triangle.draw("window near-moving widening (rows)");
    widen.set("uAlongColumns", 1);
    nearMovingTarget.bind();
    nearMovingRows.bind(0);
    triangle.draw("window near-moving widening (columns)");
  }

  void allocateRegionStats() {
    regionTargets.clear();
    regionStats = gl::TextureArray();
    if (!regionTest() || width == 0) return;
    regionStats =
        gl::TextureArray(gl, (width + 1) / 2, (height + 1) / 2, capacity() + 1, GL_RGBA32F);
    for (int layer = 0; layer <= capacity(); ++layer) {
      regionTargets.emplace_back(gl, std::vector<gl::Attachment>{{regionStats, layer}});
    }
  }

  // The pass groups' packs (resolve/pass_packs): as many groups a ring as the driver's widest
  // and largest texture array of capacity() layers holds. TAA_PASS_PACK_GROUPS=n in the
  // environment holds a ring to n groups (1: a ring a group, the layout before the packs: the
  // tests check that the packing changes no bit).
  void allocatePassPacks() {
    const char* cap = std::getenv("TAA_PASS_PACK_GROUPS");
    const int most = cap ? std::max(1, std::atoi(cap)) : std::numeric_limits<int>::max();
    passLayout = packPassGroups(passHalf, [&](int groups, bool half) {
      const GLenum format = half ? GL_RGBA16F : GL_RGBA32F;
      return groups <= most &&
             gl::largestTextureArrayLayers(gl, groups * width, height, capacity(), format) >=
                 capacity();
    });
    for (const PassPackLayout::Pack& pack : passLayout.packs) {
      passPackRings.emplace_back(gl, int(pack.groups.size()) * width, height, capacity(),
                                 pack.half ? GL_RGBA16F : GL_RGBA32F);
    }
  }

  // `sums` made to hold `rows` rows of every group (by its ring type: half groups' sums as
  // half) and every Cryptomatte rank; images already of that size are kept, not reallocated.
  void sizePassSums(PassSums& sums, int rows) const {
    sums.groups.resize(passHalf.size());
    for (std::size_t g = 0; g < passHalf.size(); ++g) {
      TypedImage& group = sums.groups[g];
      const SampleType type = passHalf[g] ? SampleType::Half : SampleType::Float;
      if (group.width() != width || group.height() != rows || group.type() != type) {
        group = TypedImage(width, rows, 4, type);
      }
    }
    sums.cryptomatte.resize(std::size_t(3 * cryptomatteSets));
    for (Image& ranks : sums.cryptomatte) {
      if (ranks.width != width || ranks.height != rows) ranks = Image(width, rows, 4);
    }
  }

  // A frame's pass groups into their packs' layer `layer`, a band of rows at a time (a pack's
  // whole layer interleaved would be 130 MB more at 1080p on a run whose bar is 4 GiB).
  void uploadPassGroups(const std::vector<ImageView>& groups, int layer) {
    constexpr std::size_t kBandBytes = std::size_t(8) << 20;
    for (std::size_t p = 0; p < passLayout.packs.size(); ++p) {
      const PassPackLayout::Pack& pack = passLayout.packs[p];
      const int n = int(pack.groups.size());
      const std::size_t rowBytes = std::size_t(width) * pack.pixelBytes();
      const int bandRows = std::max(1, int(kBandBytes / rowBytes));
      passUploadBand.resize(std::size_t(std::min(bandRows, height)) * rowBytes);
      for (int row = 0; row < height; row += bandRows) {
        const int rows = std::min(bandRows, height - row);
        for (int i = 0; i < n; ++i) {
          interleaveGroupRows(groups[std::size_t(pack.groups[std::size_t(i)])], row, rows, i,
                              pack, passUploadBand.data());
        }
        passPackRings[p].uploadRows(layer, row, rows, passUploadBand.data(), 4,
                                    pack.half ? GL_HALF_FLOAT : GL_FLOAT);
      }
    }
  }

  void allocatePasses() {
    passLayout = PassPackLayout();
    passPackRings.clear();
    passOutputs.clear();
    passTargets.clear();
    freePassLayers.clear();
    cryptomatteRings.clear();
    cryptomatteTargets.clear();
    shares = gl::Texture();
    gatherTarget = gl::Framebuffer();
    allocateRegionStats();
    if (!hasPasses() || width == 0) return;
    shares = gl::Texture(gl, width, height, GL_RGBA32F);
    allocatePassPacks();
    for (int s = 0; s < cryptomatteSets; ++s) {
      cryptomatteRings.emplace_back(gl, width, height, capacity(), GL_RGBA32F);
    }
    const int outputs =
        std::max(std::min(int(passHalf.size()), passGroupsPerDraw()),
                 cryptomatteOutput() + (cryptomatteSets > 0 ? kCryptomatteRanks : 0));
    const int outputRows = passImages() ? std::min(height, kPassBandRows) : height;
    for (int o = 0; o < outputs; ++o) {
      passOutputs.emplace_back(gl, width, outputRows, GL_RGBA32F);
    }
    for (int layer = capacity() - 1; layer >= 0; --layer) freePassLayers.push_back(layer);
  }

  void allocate(int w, int h) {
    width = w;
    height = h;
    const int layers = capacity() + 1;
    ring = gl::TextureArray(gl, w, h, layers, GL_RGBA32UI);
    ringMotion = gl::TextureArray(gl, w, h, layers, GL_R32UI);
    layerTargets.clear();
    freeLayers.clear();
    for (int layer = layers - 2; layer >= 0; --layer) freeLayers.push_back(layer);
    spareLayer = layers - 1;
    for (int layer = 0; layer < layers; ++layer) {
      layerTargets.emplace_back(gl,
                                std::vector<gl::Attachment>{{ring, layer}, {ringMotion, layer}});
    }
    colourStage = gl::Texture();
    depthStage = gl::Texture(gl, w, h, GL_R32F);
    motionStage = gl::Texture(gl, w, h, GL_RG32F);
    output = gl::Texture(gl, w, h, GL_RGBA32F);
    debug = gl::Texture();
    gatherTarget = gl::Framebuffer();
    for (gl::Texture& t : stats) t = gl::Texture();
    statsTarget = gl::Framebuffer();
    tileReach = gl::Texture();
    surroundingRows = gl::Texture();
    surroundings = gl::Texture();
    surroundingRowsTarget = gl::Framebuffer();
    surroundingsTarget = gl::Framebuffer();
    nearMovingBlocks = gl::Texture();
    nearMovingRows = gl::Texture();
    nearMoving = gl::Texture();
    nearMovingBlocksTarget = gl::Framebuffer();
    nearMovingRowsTarget = gl::Framebuffer();
    nearMovingTarget = gl::Framebuffer();
    ones.clear();
    zeros.clear();
    slots.clear();
    allocatePasses();
  }

  // Packs a frame into `layer`: colour into the working space, depth, motion.
  void prepare(const ResolveInput& input, int layer) {
    const ImageView& color = input.color;
    if (!colourStage.id() || colourStageType != color.type) {
      colourStageType = color.type;
      colourStage = gl::Texture(gl, width, height,
                                color.type == SampleType::Half ? GL_RGBA16F : GL_RGBA32F);
    }
    colourStage.upload(color.data, 4, glType(color.type));
    if (!input.depth && ones.empty()) ones.assign(std::size_t(width) * height, 1.0f);
    if (!input.motion && zeros.empty()) zeros.assign(std::size_t(width) * height * 2, 0.0f);
    depthStage.upload(input.depth ? input.depth.data : ones.data(), 1,
                      input.depth ? glType(input.depth.type) : GL_FLOAT);
    motionStage.upload(input.motion ? input.motion.data : zeros.data(), 2,
                       input.motion ? glType(input.motion.type) : GL_FLOAT);
    layerTargets[layer].bind();
    prepareProgram.use();
    prepareProgram.set("uColour", int(kColourStageUnit));
    prepareProgram.set("uDepth", int(kDepthStageUnit));
    prepareProgram.set("uMotion", int(kMotionStageUnit));
    colourStage.bind(kColourStageUnit);
    depthStage.bind(kDepthStageUnit);
    motionStage.bind(kMotionStageUnit);
    toWorkingLuts.bind();
    triangle.draw("window prepare pass");
  }

  // Classifies a frame's samples (window_classify.frag) against `other` (the frame before or
  // after it) or uniformly: reads its layer (the depth's sign ignored), writes the spare layer,
  // and the two swap.
  void classify(Slot& slot, Classify mode, const Slot* other) {
    if (slot.classifiedOnce && slot.classified == mode && !other) return;
    const gl::Program& p = classifyProgram;
    p.set("uClassifyMode", int(mode));
    p.set("uRing", int(kRingUnit));
    p.set("uRingMotion", int(kRingMotionUnit));
    p.set("uLayer", slot.layer);
    p.set("uOtherLayer", other ? other->layer : slot.layer);
    p.set("uJitter", slot.jitter.x, slot.jitter.y);
    p.set("uTolerance", options.window.staticTolerance);
    if (other) {
      const ReprojectionMatrices m =
          reprojectionMatrices(*slot.camera, *other->camera, slot.window, slot.ndc);
      p.setMatrix4("uRasterToCamera", &m.rasterToCamera[0][0]);
      p.setMatrix4("uCameraToOtherRaster", &m.cameraToPreviousRaster[0][0]);
      p.setMatrix4("uCameraToOtherCamera", &m.cameraToPreviousCamera[0][0]);
    }
    layerTargets[spareLayer].bind();
    p.use();
    ring.bind(kRingUnit);
    ringMotion.bind(kRingMotionUnit);
    triangle.draw("window classify pass");
    std::swap(slot.layer, spareLayer);
    if (regionTest()) writeRegionStats(slot.layer);
    slot.classified = mode;
    slot.classifiedOnce = true;
    slot.hasMoving = mode == Classify::NoCamera || (mode != Classify::AllStatic && anyMoving(slot));
  }

  // The region test's statistics of the frame at `layer`, just classified.
  void writeRegionStats(int layer) {
    const gl::Program& p = regionStatsProgram;
    p.set("uRing", int(kRingUnit));
    p.set("uLayer", layer);
    p.set("uLinear", options.window.linear ? 1 : 0);
    regionTargets[std::size_t(layer)].bind();
    p.use();
    ring.bind(kRingUnit);
    triangle.draw("window region statistics pass");
  }

  // Whether any sample of a classified frame moves (an occlusion query, nothing written).
  bool anyMoving(const Slot& slot) {
    const gl::Program& p = countMovingProgram;
    p.set("uRing", int(kRingUnit));
    p.set("uLayer", slot.layer);
    layerTargets[spareLayer].bind();
    p.use();
    ring.bind(kRingUnit);
    gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    movingQuery.begin();
    triangle.draw("window moving-sample query");
    const bool any = movingQuery.endAndRead();
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl::checkError(gl, "window moving-sample query");
    return any;
  }

  // Whether a frame's samples are told apart one by one (camera, depth and vectors all there,
  // and camera-motion neither vectors-only nor camera-only).
  bool classifiesPerSample(const Slot& slot) const {
    return slot.camera && slot.hasDepth && slot.hasMotion &&
           options.cameraMotion != CameraMotion::Vectors &&
           options.cameraMotion != CameraMotion::Camera;
  }

  Classify uniformClassification(const Slot& slot) const {
    if (!slot.camera || !slot.hasDepth || options.cameraMotion == CameraMotion::Vectors) {
      return Classify::NoCamera;
    }
    return Classify::AllStatic;
  }

  // Every frame of the window classified against its neighbour inside the window: the frame
  // before it when that is in the window, else the one after it, else (a window of one) all
  // static. So a frame's output depends on its window alone, whatever else the ring holds.
  void classifyWindow(int first, int last) {
    for (int f : FrameSpan(first, last)) {
      Slot& slot = slots.at(f);
      if (!classifiesPerSample(slot)) {
        classify(slot, uniformClassification(slot), nullptr);
        continue;
      }
      const Slot* before = f > first ? &slots.at(f - 1) : nullptr;
      const Slot* after = f < last ? &slots.at(f + 1) : nullptr;
      if (before && before->camera) {
        if (!(slot.classifiedOnce && slot.classified == Classify::PreviousCamera)) {
          classify(slot, Classify::PreviousCamera, before);
        }
      } else if (after && after->camera) {
        if (!(slot.classifiedOnce && slot.classified == Classify::NextFrame)) {
          classify(slot, Classify::NextFrame, after);
        }
      } else {
        classify(slot, Classify::AllStatic, nullptr);
      }
    }
  }

  void addFrame(int frame, const ResolveInput& input) {
    const ImageView& color = input.color;
    if (!color || color.channels != 4) {
      throw Error("resolve needs an RGBA color image", {"", std::nullopt, "color"});
    }
    checkPlane(input.depth, color, 1, "depth");
    checkPlane(input.motion, color, 2, "motion");
    if (slots.count(frame)) {
      throw Error("window resolve: frame " + std::to_string(frame) + " added twice", {"", frame});
    }
    if (slots.empty() && (color.width != width || color.height != height)) {
      allocate(color.width, color.height);
    } else if (color.width != width || color.height != height) {
      throw Error("frame is " + std::to_string(color.width) + "x" + std::to_string(color.height) +
                      " but the frames of its window are " + std::to_string(width) + "x" +
                      std::to_string(height) + " (a new size needs a new shot: --reset-frames)",
                  {"", frame, "color"});
    }
    if (input.passGroups.size() != passHalf.size() ||
        int(input.cryptomatte.size()) != cryptomatteSets) {
      throw Error("window resolve: frame brings " + std::to_string(input.passGroups.size()) +
                      " pass groups and " + std::to_string(input.cryptomatte.size()) +
                      " Cryptomatte sets where the resolve was set up for " +
                      std::to_string(passHalf.size()) + " and " +
                      std::to_string(cryptomatteSets),
                  {"", frame});
    }
    std::vector<ImageView> passImages = input.passGroups;
    passImages.insert(passImages.end(), input.cryptomatte.begin(), input.cryptomatte.end());
    for (const ImageView& pass : passImages) {
      if (!pass || pass.channels != 4 || pass.width != color.width ||
          pass.height != color.height) {
        throw Error("window resolve: a pass group is not four channels of the colour's size",
                    {"", frame});
      }
    }
    // Each group comes in its ring's type (PackedPasses are packed by the same plan).
    for (std::size_t g = 0; g < passHalf.size(); ++g) {
      if ((input.passGroups[g].type == SampleType::Half) != passHalf[g]) {
        throw Error("window resolve: pass group " + std::to_string(g) + " is " +
                        (passHalf[g] ? "float" : "half") + " where its ring is " +
                        (passHalf[g] ? "half" : "float"),
                    {"", frame});
      }
    }
    if (freeLayers.empty()) {
      throw Error("window resolve: the ring of " + std::to_string(capacity()) +
                  " frames is full", {"", frame});
    }
    Slot slot;
    slot.layer = freeLayers.back();
    slot.jitter = input.jitter;
    if (input.camera) slot.camera = *input.camera;
    slot.window = input.window;
    slot.ndc = input.ndc;
    slot.pinhole = input.camera && isPinhole(*input.camera, slot.window, slot.ndc);
    slot.hasDepth = bool(input.depth);
    slot.hasMotion = bool(input.motion);
    freeLayers.pop_back();
    if (hasPasses()) {
      slot.passLayer = freePassLayers.back();
      freePassLayers.pop_back();
      uploadPassGroups(input.passGroups, slot.passLayer);
      for (std::size_t s = 0; s < cryptomatteRings.size(); ++s) {
        cryptomatteRings[s].upload(slot.passLayer, input.cryptomatte[s].data, 4, GL_FLOAT);
      }
      gl::checkError(gl, "window pass upload");
    }
    slots.emplace(frame, slot);
    prepare(input, slot.layer);
  }

  void dropFrame(int frame) {
    const auto found = slots.find(frame);
    if (found == slots.end()) return;
    freeLayers.push_back(found->second.layer);
    if (found->second.passLayer >= 0) freePassLayers.push_back(found->second.passLayer);
    slots.erase(found);
    // Its neighbours may be classified against it: a frame added later under its number (with
    // other content, as a C ABI host may push) must not find that classification still there.
    for (int neighbour : {offsetFrame(frame, -1), offsetFrame(frame, 1)}) {
      const auto it = slots.find(neighbour);
      if (it != slots.end()) it->second.classifiedOnce = false;
    }
  }

  // Returns each source's distance from `frame` in frames, in the gather's order.
  std::vector<int> setGatherUniforms(const gl::Program& p, int frame, int first, int last) {
    const Slot& target = slots.at(frame);
    p.set("uRing", int(kRingUnit));
    p.set("uRingMotion", int(kRingMotionUnit));
    p.set("uTargetLayer", target.layer);
    p.set("uTargetJitter", target.jitter.x, target.jitter.y);
    const std::array<float, 9> weights =
        reconstructionWeights(options.reconstruction, target.jitter);
    p.setArray("uReconstruction", weights.data(), int(weights.size()));
    const bool useCameras = target.camera && options.cameraMotion != CameraMotion::Vectors;
    p.set("uTargetPassLayer", target.passLayer);

    std::vector<int> layers, passLayers, offsets, hasCamera;
    std::vector<float> frameWeights, jitters, toTargetAlong, toTargetOffset, toTargetDepthAlong,
        toTargetDepthOffset, fromTargetAlong, fromTargetOffset;
    // Only the rows the gather uses, as 3x3 over (x, y, 1): a carry's offset is always applied
    // to (x, y, 1, 1), so its last two columns fold into one.
    auto appendRows = [](std::vector<float>& to, const glm::mat4& m, std::initializer_list<int> rows,
                         bool offset) {
      for (int column = 0; column < 3; ++column) {
        for (int row : rows) to.push_back(m[column][row] + (offset && column == 2 ? m[3][row] : 0.0f));
      }
    };
    auto appendRaster = [&](std::vector<float>& to, const glm::mat4& m, bool offset) {
      appendRows(to, m, {0, 1, 3}, offset);  // raster x, y and w
    };
    auto appendDepth = [&](std::vector<float>& to, const glm::mat4& m, bool offset) {
      appendRows(to, m, {2}, offset);  // camera z: the planar depth
    };
    // Nearest first, behind before ahead: the shader's chains walk outward in this order, and
    // the sum's order is fixed by the window alone (never by what else the ring holds).
    for (int distance = 1; distance <= options.window.radius; ++distance) {
      for (const long long wide : {(long long)frame - distance, (long long)frame + distance}) {
        if (wide < first || wide > last) continue;  // 64 bits: beyond INT_MAX is outside too
        const int source = int(wide);
        const auto found = slots.find(source);
        if (found == slots.end()) {
          throw Error("window resolve: frame " + std::to_string(source) + " of frame " +
                      std::to_string(frame) + "'s window is not in the ring");
        }
        const Slot& s = found->second;
        layers.push_back(s.layer);
        passLayers.push_back(s.passLayer);
        offsets.push_back(source - frame);
        frameWeights.push_back(windowFrameWeight(source - frame, options.window));
        jitters.push_back(s.jitter.x);
        jitters.push_back(s.jitter.y);
        const bool cameras = useCameras && s.camera;
        hasCamera.push_back(cameras ? 1 : 0);
        FrameCarry toTarget, fromTarget;
        if (cameras) {
          toTarget = frameCarry(*s.camera, *target.camera, s.window, s.ndc);
          fromTarget = frameCarry(*target.camera, *s.camera, target.window, target.ndc);
        }
        appendRaster(toTargetAlong, toTarget.toRaster.alongDepth, false);
        appendRaster(toTargetOffset, toTarget.toRaster.offset, true);
        appendDepth(toTargetDepthAlong, toTarget.toCamera.alongDepth, false);
        appendDepth(toTargetDepthOffset, toTarget.toCamera.offset, true);
        appendRaster(fromTargetAlong, fromTarget.toRaster.alongDepth, false);
        appendRaster(fromTargetOffset, fromTarget.toRaster.offset, true);
      }
    }
    const int count = int(layers.size());
    p.set("uSourceCount", count);
    if (count == 0) return offsets;
    p.setIntArray("uSourceLayer", layers.data(), count);
    p.setIntArray("uSourcePassLayer", passLayers.data(), count);
    p.setIntArray("uSourceOffset", offsets.data(), count);
    p.setArray("uSourceWeight", frameWeights.data(), count);
    p.setVec2Array("uSourceJitter", jitters.data(), count);
    p.setIntArray("uSourceHasCamera", hasCamera.data(), count);
    p.setMatrix3Array("uToTargetAlong", toTargetAlong.data(), count);
    p.setMatrix3Array("uToTargetOffset", toTargetOffset.data(), count);
    p.setVec3Array("uToTargetDepthAlong", toTargetDepthAlong.data(), count);
    p.setVec3Array("uToTargetDepthOffset", toTargetDepthOffset.data(), count);
    p.setMatrix3Array("uFromTargetAlong", fromTargetAlong.data(), count);
    p.setMatrix3Array("uFromTargetOffset", fromTargetOffset.data(), count);
    return offsets;
  }

  // The tile test: the gather's statistics at every kStatsStride-th pixel (set up and bound by
  // `setUniforms`, which returns the sources' offsets), pooled per tile into how far each side
  // of its window reaches (resolve/window_tiles), uploaded for the gather. False when no
  // source lies beyond the near frames (nothing to decide).
  bool decideTiles(int variant,
                   const std::function<std::vector<int>(const gl::Program&)>& setUniforms) {
    const int statsWidth = (width + kStatsStride - 1) / kStatsStride;
    const int statsHeight = (height + kStatsStride - 1) / kStatsStride;
    if (!statsTarget.id()) {
      for (gl::Texture& t : stats) t = gl::Texture(gl, statsWidth, statsHeight, GL_RGBA32F);
      statsTarget = gl::Framebuffer(gl, std::vector<gl::Attachment>{&stats[0], &stats[1],
                                                                     &stats[2], &stats[3]});
    }
    const gl::Program& p = gatherProgram(variant, kTileStatsDraw);
    statsTarget.bind();
    const std::vector<int> offsets = setUniforms(p);
    bool beyond = false;
    for (int offset : offsets) beyond = beyond || std::abs(offset) > options.window.nearRadius;
    if (!beyond) return false;
    p.set("uStatsStride", kStatsStride);
    triangle.draw("window tile statistics pass");
    // Three codes to a float word, four words to a texel, four texels: source k's code is
    // byte k % 3 of word k / 3.
    const std::size_t pixels = std::size_t(statsWidth) * statsHeight;
    const std::size_t count = offsets.size();
    statsCodes.resize(pixels * count);
    statsWords.resize(pixels * 4);
    for (int attachment = 0; attachment < 4 && 12 * attachment < int(count); ++attachment) {
      statsTarget.readRGBA(statsWords.data(), GL_FLOAT, attachment);
      for (std::size_t i = 0; i < pixels; ++i) {
        for (std::size_t k = 12 * std::size_t(attachment);
             k < std::min(count, 12 * std::size_t(attachment) + 12); ++k) {
          const auto word = std::uint32_t(statsWords[4 * i + (k % 12) / 3]);
          statsCodes[i * count + k] = std::uint8_t(word >> (8 * (k % 3)));
        }
      }
    }
    const TileReach reach = decideTileReach(statsCodes, statsWidth, statsHeight,
                                            kTileSize / kStatsStride, offsets,
                                            options.window.nearRadius);
    if (tileReach.width() != reach.columns || tileReach.height() != reach.rows) {
      tileReach =
          gl::Texture(gl, reach.columns, reach.rows, GL_RG32F, gl::Texture::Filter::Linear);
    }
    tileReach.upload(reach.frames.data(), 2);
    return true;
  }

  // Every pass in one draw, band by band: what a writer can take as the bands come.
  bool canStreamPasses() const {
    return passImages() && int(passHalf.size()) <= passGroupsPerDraw() && cryptomatteSets <= 1;
  }

  // With `colourReady` given, the colour goes to it once the beauty is drawn and the passes'
  // sums to `stream` band by band (canStreamPasses); the result is then empty.
  TypedImage resolve(int frame, int first, int last, SampleType outputType,
                     const std::function<void(TypedImage)>& colourReady = {},
                     PassBandStream* stream = nullptr) {
    if (stream && !canStreamPasses()) {
      throw Error("window resolve: these passes are not drawn in one band-by-band draw and "
                  "cannot be streamed", {"", frame});
    }
    if (!slots.count(frame) || frame < first || frame > last) {
      throw Error("window resolve: frame " + std::to_string(frame) + " is not in the ring",
                  {"", frame});
    }
    for (int f : FrameSpan(first, last)) {
      if (!slots.count(f)) {
        throw Error("window resolve: frame " + std::to_string(f) + " of frame " +
                        std::to_string(frame) + "'s window is not in the ring", {"", frame});
      }
    }
    classifyWindow(first, last);
    if (thinSearch() || regionTest()) writeSurroundings(frame);
    const int groups = int(passHalf.size());
    const int perDraw = passGroupsPerDraw();
    const int groupDraws = (groups + perDraw - 1) / perDraw;
    // With image stores the first Cryptomatte set is weighed in the last pass-group draw.
    const int joinedSets = passImages() && cryptomatteSets > 0 ? 1 : 0;
    // Without image stores a Cryptomatte set's draw has a target of its own.
    const int setTargets = passImages() ? 0 : cryptomatteSets;
    if (!gatherTarget.id() || gatherHasDebug != debugOutput ||
        int(passTargets.size()) != groupDraws ||
        int(cryptomatteTargets.size()) != setTargets) {
      debug = debugOutput ? gl::Texture(gl, width, height, GL_RGBA32F) : gl::Texture();
      std::vector<gl::Attachment> beautyOutputs{&output, debugOutput ? &debug : nullptr};
      if (hasPasses()) beautyOutputs.emplace_back(&shares);
      gatherTarget = gl::Framebuffer(gl, beautyOutputs);
      gatherHasDebug = debugOutput;
      passTargets.clear();
      for (int d = 0; d < groupDraws; ++d) {
        // The colour is the beauty's draw's: not written again here (with image stores, where
        // the sums need no attachment, the draw has the colour's, its writes masked).
        std::vector<gl::Attachment> attachments{passImages() ? &output : nullptr, nullptr};
        for (int g = d * perDraw; g < std::min(groups, (d + 1) * perDraw) && !passImages();
             ++g) {
          attachments.emplace_back(&passOutputs[std::size_t(g - d * perDraw)]);
        }
        passTargets.emplace_back(gl, attachments);
      }
      cryptomatteTargets.clear();
      for (int set = 0; set < setTargets; ++set) {
        // The colour is the beauty's draw's: not written again here.
        std::vector<gl::Attachment> attachments{nullptr, nullptr};
        for (int rank = 0; rank < kCryptomatteRanks; ++rank) {
          attachments.emplace_back(&passOutputs[std::size_t(cryptomatteOutput() + rank)]);
        }
        cryptomatteTargets.emplace_back(gl, attachments);
      }
    }
    bool chains = false;
    for (int f : FrameSpan(first, last)) chains = chains || slots.at(f).hasMoving;
    // The uniforms every draw of the gather shares (the tile test's own draw included); returns
    // the sources' offsets in frames.
    auto setUniforms = [&](const gl::Program& p, bool tiles) {
      p.set("uSigma", options.window.sigma);
      p.set("uColourTolerance", options.window.colourTolerance);
      p.set("uRegionTolerance", regionTest() ? options.window.regionTolerance : 0.0f);
      p.set("uRegionStats", regionStatsUnit());
      p.set("uRegionToleranceNearMoving", options.window.regionToleranceNearMoving);
      p.set("uDepthTolerance", options.depthTolerance);
      p.set("uReconstructionWeight", options.window.reconstructionWeight);
      p.set("uOpaqueMoving", options.window.opaqueMoving ? 1 : 0);
      p.set("uThinSearch", thinSearch() ? 1 : 0);
      p.set("uSettle", options.window.settle);
      p.set("uSettleSources", WindowOptions::kSettleSources);
      p.set("uOwnFallback", options.window.ownFallback);
      p.set("uOwnFallbackGathered", WindowOptions::kOwnFallbackGathered);
      p.set("uSurroundings", surroundingsUnit());
      p.set("uStrata", options.window.strata ? 1 : 0);
      p.set("uTwoClusters", options.window.twoClusters ? 1 : 0);
      p.set("uAdaptive", options.window.adaptive ? 1 : 0);
      p.set("uTiles", tiles ? 1 : 0);
      p.set("uTileSize", kTileSize);
      p.set("uTileReach", int(kTileReachUnit));
      p.set("uMovingRadius", options.window.movingRadius);
      // The output clamped to what its type holds (glsl/finite_range.glsl).
      p.set("uOutputLimit", outputType == SampleType::Half ? 65504.0f
                                                           : std::numeric_limits<float>::max());
      std::vector<int> offsets = setGatherUniforms(p, frame, first, last);
      p.use();
      ring.bind(kRingUnit);
      ringMotion.bind(kRingMotionUnit);
      fromWorkingLuts.bind();
      gatherToWorkingLuts.bind();
      if (tiles) tileReach.bind(kTileReachUnit);
      if (regionTest()) regionStats.bind(regionStatsUnit());
      if (thinSearch() || regionTest()) surroundings.bind(surroundingsUnit());
      return offsets;
    };
    const int kind = gatherVariant(chains, frame, first, last);
    const bool tiles = tileTest() && decideTiles(kind, [&](const gl::Program& p) {
                         return setUniforms(p, false);
                       });
    // One draw of the gather into `target`; `variant` as gatherProgram's; `bindExtra` binds the
    // draw's own inputs. With passes, the beauty's draw comes first and writes the colour and
    // its shares; each pass or Cryptomatte draw weighs the samples as it did (the same program
    // text and uniforms but for its outputs: the same weights, bit for bit) times the shares.
    // With image stores (`afterBand` given) a pass draw runs band by band, its sums written to
    // band-sized images (kPassBandRows) that afterBand(first row) reads back before the next.
    const int bandRows = passImages() ? std::min(height, kPassBandRows) : height;
    auto drawGather = [&](int variant, bool joined, const std::vector<std::string>& packDefines,
                          const gl::Framebuffer& target,
                          const std::function<void(const gl::Program&)>& bindExtra,
                          const std::function<void(int)>& afterBand = {}) {
      const gl::Program& p = gatherProgram(kind, variant, joined, packDefines);
      target.bind();
      setUniforms(p, tiles);
      if (variant != 0) {
        shares.bind(sharesUnit());
        p.set("uShares", sharesUnit());
      }
      bindExtra(p);
      const char* pass = variant == 0 ? "window gather pass"
                         : joined     ? "window gather pass (pass groups and Cryptomatte)"
                         : variant > 0 ? "window gather pass (pass groups)"
                                       : "window gather pass (Cryptomatte)";
      if (!afterBand) return triangle.draw(pass);
      for (int row = 0; row < height; row += bandRows) {
        // gl_FragCoord counts from the window's corner, so the band's pixels keep their places.
        gl.Viewport(0, row, width, std::min(bandRows, height - row));
        p.set("uBandStart", row);
        triangle.draw(pass);
        // Image stores are seen by the reads back past a barrier; llvmpipe hands an image's
        // tiles back unfinished without glFinish (docs/PERFORMANCE.md, "Seventh measurement").
        gl.MemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
        gl.Finish();
        afterBand(row);
      }
    };
    // One band of `sums` (an image of bandRows rows, RGBA of `type`, `pixelBytes` a pixel)
    // into rows firstRow.. of `whole` (the frame's).
    std::vector<unsigned char> bandScratch;
    auto readBand = [&](const gl::Texture& sums, void* whole, GLenum type, std::size_t pixelBytes,
                        int firstRow) {
      const std::size_t rowBytes = std::size_t(width) * pixelBytes;
      const int rows = std::min(bandRows, height - firstRow);
      auto* at = static_cast<unsigned char*>(whole) + std::size_t(firstRow) * rowBytes;
      if (rows == bandRows) return sums.readRGBA(at, type);
      bandScratch.resize(std::size_t(bandRows) * rowBytes);
      sums.readRGBA(bandScratch.data(), type);
      std::memcpy(at, bandScratch.data(), std::size_t(rows) * rowBytes);
    };
    // A Cryptomatte set's inputs; with image stores its ranks' images from `firstImage` on.
    auto bindCryptomatte = [&](const gl::Program& p, int set, int firstImage) {
      cryptomatteRings[std::size_t(set)].bind(cryptomatteUnit());
      p.set("uCrypto", cryptomatteUnit());
      if (!passImages()) return;
      std::vector<int> images;
      for (int rank = 0; rank < kCryptomatteRanks; ++rank) {
        images.push_back(firstImage + rank);
        passOutputs[std::size_t(cryptomatteOutput() + rank)].bindImage(images.back());
      }
      p.setIntArray("uCryptoOutputs", images.data(), kCryptomatteRanks);
    };
    auto readCryptomatteBand = [&](int set, int firstRow) {
      for (int rank = 0; rank < kCryptomatteRanks; ++rank) {
        readBand(passOutputs[std::size_t(cryptomatteOutput() + rank)],
                 lastSums.cryptomatte[std::size_t(3 * set + rank)].pixels.data(), GL_FLOAT,
                 4 * sizeof(float), firstRow);
      }
    };
    // Read back into the last frame's images where they are still here (takePassSums gives
    // them away); fresh ones come from the frame buffer pool. Streamed, none are kept.
    if (stream) {
      lastSums = PassSums();
    } else {
      sizePassSums(lastSums, height);
    }
    drawGather(0, false, {}, gatherTarget, [](const gl::Program&) {});
    if (colourReady) {
      // The pass draws leave the colour as it is (its writes masked): the writer may start.
      TypedImage colour(width, height, 4, outputType);
      gatherTarget.readRGBA(colour.data(), glType(outputType), 0);
      colourReady(std::move(colour));
    }
    // A band's sums, read back into buffers of the stream's (band-sized images) and handed on.
    auto streamBand = [&](int firstRow) {
      PassSums band = stream->take();
      sizePassSums(band, bandRows);
      for (int g = 0; g < groups; ++g) {
        TypedImage& sums = band.groups[std::size_t(g)];
        passOutputs[std::size_t(g)].readRGBA(sums.data(), glType(sums.type()));
      }
      for (int rank = 0; rank < 3 * cryptomatteSets; ++rank) {
        passOutputs[std::size_t(cryptomatteOutput() + rank)].readRGBA(
            band.cryptomatte[std::size_t(rank)].pixels.data(), GL_FLOAT);
      }
      stream->publish(frame, firstRow, std::min(bandRows, height - firstRow), std::move(band));
    };
    // With image stores the pass draws' target is the colour's, left as the beauty wrote it
    // (the mask put back however the draws end: a resolver outlives a failed frame).
    struct ColourWritesOff {
      const gl::Functions& functions;
      explicit ColourWritesOff(const gl::Functions& f) : functions(f) {
        functions.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
      }
      ~ColourWritesOff() { functions.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE); }
    };
    std::optional<ColourWritesOff> colourWritesOff;
    if (passImages()) colourWritesOff.emplace(gl);
    for (int d = 0; d < groupDraws; ++d) {
      const int firstGroup = d * perDraw;
      const int drawGroups = std::min(groups - firstGroup, perDraw);
      const bool joined = joinedSets > 0 && d == groupDraws - 1;
      const gl::Framebuffer& target = passTargets[std::size_t(d)];
      std::vector<int> packs;
      const std::vector<std::string> packDefines =
          passPackDefines(passLayout, firstGroup, drawGroups, &packs);
      const auto bind = [&](const gl::Program& p) {
        std::vector<int> units, images;
        for (std::size_t k = 0; k < packs.size(); ++k) {
          units.push_back(firstPassUnit() + int(k));
          passPackRings[std::size_t(packs[k])].bind(units.back());
        }
        p.setIntArray("uPassPacks", units.data(), int(units.size()));
        for (int g = 0; g < drawGroups && passImages(); ++g) {
          images.push_back(g);
          passOutputs[std::size_t(g)].bindImage(g);
        }
        if (passImages()) p.setIntArray("uPassOutputs", images.data(), drawGroups);
        if (joined) bindCryptomatte(p, 0, drawGroups);
      };
      if (!passImages()) {
        drawGather(drawGroups, false, packDefines, target, bind);
        for (int g = 0; g < drawGroups; ++g) {
          TypedImage& sums = lastSums.groups[std::size_t(firstGroup + g)];
          target.readRGBA(sums.data(), glType(sums.type()), 2 + g);
        }
        continue;
      }
      drawGather(drawGroups, joined, packDefines, target, bind, [&](int row) {
        if (stream) return streamBand(row);
        for (int g = 0; g < drawGroups; ++g) {
          TypedImage& sums = lastSums.groups[std::size_t(firstGroup + g)];
          readBand(passOutputs[std::size_t(g)], sums.data(), glType(sums.type()),
                   4 * (sums.type() == SampleType::Half ? 2 : 4), row);
        }
        if (joined) readCryptomatteBand(0, row);
      });
    }
    for (int set = joinedSets; set < cryptomatteSets; ++set) {
      const auto bind = [&](const gl::Program& p) { bindCryptomatte(p, set, 0); };
      if (!passImages()) {
        const gl::Framebuffer& target = cryptomatteTargets[std::size_t(set)];
        drawGather(kCryptomatteDraw, false, {}, target, bind);
        for (int rank = 0; rank < kCryptomatteRanks; ++rank) {
          target.readRGBA(lastSums.cryptomatte[std::size_t(3 * set + rank)].pixels.data(),
                          GL_FLOAT, 2 + rank);
        }
        continue;
      }
      drawGather(kCryptomatteDraw, false, {}, passTargets.back(), bind,
                 [&](int row) { readCryptomatteBand(set, row); });
    }

    if (debugOutput) {
      const std::vector<float> rgba = gatherTarget.readRGBA(1);
      lastDebug = Image(width, height, kWindowDebugChannels);
      for (std::size_t i = 0, n = std::size_t(width) * height; i < n; ++i) {
        for (int c = 0; c < kWindowDebugChannels; ++c) {
          lastDebug.pixels[i * kWindowDebugChannels + c] = rgba[i * 4 + c];
        }
      }
    }
    if (colourReady) return TypedImage();
    TypedImage result(width, height, 4, outputType);
    gatherTarget.readRGBA(result.data(), glType(outputType), 0);
    return result;
  }
};

WindowResolver::WindowResolver(gl::Context& context, const ResolveOptions& options) {
  validateOptions(options);
  impl_ = std::make_unique<Impl>(context, options);
}

WindowResolver::~WindowResolver() = default;

int WindowResolver::capacity() const { return impl_->capacity(); }

void WindowResolver::addFrame(int frame, const ResolveInput& input) {
  impl_->addFrame(frame, input);
}

void WindowResolver::dropFrame(int frame) { impl_->dropFrame(frame); }

bool WindowResolver::hasFrame(int frame) const { return impl_->slots.count(frame) > 0; }

void WindowResolver::clear() {
  std::vector<int> frames;
  for (const auto& entry : impl_->slots) frames.push_back(entry.first);
  for (int frame : frames) impl_->dropFrame(frame);
}

TypedImage WindowResolver::resolve(int frame, int first, int last, SampleType outputType) {
  return impl_->resolve(frame, first, last, outputType);
}

void WindowResolver::resolveStreaming(int frame, int first, int last, SampleType outputType,
                                      const std::function<void(TypedImage)>& colourReady,
                                      PassBandStream& bands) {
  impl_->resolve(frame, first, last, outputType, colourReady, &bands);
}

bool WindowResolver::canStreamPasses() const { return impl_->canStreamPasses(); }

void WindowResolver::setDebugOutput(bool enabled) { impl_->debugOutput = enabled; }

void WindowResolver::setPasses(const std::vector<bool>& halfGroups, int cryptomatteSets) {
  if (!impl_->slots.empty()) throw Error("window resolve: passes set with frames in the ring");
  impl_->passHalf = halfGroups;
  impl_->cryptomatteSets = cryptomatteSets;
  impl_->allocatePasses();
  if (!impl_->hasPasses()) {
    impl_->buffersNotKept.reset();
  } else if (!impl_->buffersNotKept) {
    impl_->buffersNotKept.emplace();
  }
}

PassSums WindowResolver::takePassSums() { return std::move(impl_->lastSums); }

const Image& WindowResolver::lastDebug() const { return impl_->lastDebug; }

int windowRadiusTheGlHolds(gl::Context& context, int asked, int width, int height) {
  if (width <= 0 || height <= 0) return asked;
  // The colour ring (RGBA32UI) takes the most bytes a pixel of any ring (a float pass group
  // as many; the pass rings hold several groups side by side only where the driver takes them,
  // else one each): what holds it holds them.
  const int layers = gl::largestTextureArrayLayers(context.functions(), width, height,
                                                   2 * asked + 2, GL_RGBA32UI);
  return windowRadiusWithinLayers(asked, layers);
}

}  // namespace taa
