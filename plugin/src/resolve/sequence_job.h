// Resolving a whole sequence: the orchestration above io and the two resolve strategies. Frames
// are read ahead and written behind (resolve/frame_queues) while the GL thread resolves: in
// order through the history (resolve/resolver), or from a ring of each frame's window
// (resolve/window_plan, resolve/window_resolver). Every output is written atomically. The CLI,
// the farm and Python faces describe a job and run it through here.
#pragma once

#include <functional>
#include <set>
#include <string>
#include <vector>

#include "gl/context.h"
#include "io/aov_layout.h"
#include "io/exr_writer.h"
#include "resolve/camera.h"
#include "taa/options.h"

namespace taa {

// Where each frame's jitter comes from. Auto: the camera sidecar's "jitter" where its entry has
// one, else the color header's camera note's (io/camera_note.h) where the frame has one, else
// the resolve options'; Options: the resolve options' JitterOptions (Halton or none), whatever
// the files hold; HeaderAttribute: a float[2] attribute of the color header (pixels, x right,
// y down); Sidecar: the camera sidecar's "jitter" entry, required for every frame.
enum class JobJitterSource { Auto, Options, HeaderAttribute, Sidecar };

// One view of a multi-view file and where its AOVs live (io/views.h).
struct JobView {
  std::string name;
  io::AovLayout layout;
};

struct SequenceJob {
  io::AovLayout layout;        // where color, depth and motion come from
  // A multi-view file's views to resolve, each as if alone (its own history or ring), written
  // back together as one multi-view file. Empty: `layout` alone, a file without views.
  std::vector<JobView> views;
  std::vector<int> frames;     // frames to resolve, in order
  // Frames whose inputs exist (the color pattern's files on disk), for the window resolve:
  // it reads those within K of a resolved frame, in its shot, even outside `frames`. Empty:
  // `frames` alone.
  std::vector<int> availableFrames;
  std::string outputPattern;   // frame-numbered output path
  io::WriteOptions write;
  ResolveOptions resolve;
  gl::Backend backend = gl::Backend::Auto;
  std::set<int> resetFrames;   // frames that start a new history (cuts)
  // History mode: frames of `frames` resolved only to build the history of later ones, never
  // written (a farm chunk's read-only pre-roll, farm/chunk_plan.h). Window mode: none.
  std::set<int> prerollFrames;
  bool debugLayers = false;    // write the resolver's diagnostics as extra layers
  NdcConvention ndc = NdcConvention::ZeroOneYDown;  // of the headers' worldToNDC
  JobJitterSource jitterSource = JobJitterSource::Auto;
  std::string jitterAttribute = "taa:jitter";  // for HeaderAttribute
  std::string cameraSidecar;   // JSON file (io/camera_sidecar.h); empty: none
  // Output color channel names (4). Empty: the color input's names (a missing alpha gets the
  // red channel's prefix + "A"), so the output can replace the input in a comp.
  std::vector<std::string> outputChannels;
  // Frames read ahead and written behind on worker threads while the GL thread resolves (0: all
  // on the calling thread, one step after another). Output is identical either way. Each frame
  // in flight holds its AOVs in memory: at most kMaxIoThreads. kAutoIoThreads: see ioDepthOf.
  int ioThreads = -1;
};

inline constexpr int kMaxIoThreads = 16;
inline constexpr int kAutoIoThreads = -1;

// The frames in flight for `job`: its ioThreads, or by default 2, and 0 where the window
// resolve carries passes (`passes`): a 1080p frame with a render's every pass holds about
// 0.4 GB as read and as written, and on few cores the reads and writes compete with the
// resolve for them (docs/PERFORMANCE.md, "Fourth measurement").
int ioDepthOf(const SequenceJob& job, bool passes);

// The output's 4 color channel names for `job` (see SequenceJob::outputChannels).
std::vector<std::string> outputChannelNames(const SequenceJob& job);

struct FrameReport {
  int index = 0;  // position in job.frames, 0-based
  int count = 0;  // job.frames.size()
  int frame = 0;
  std::string inputPath, outputPath;
  int nonFiniteColorValues = 0;   // NaN/Inf colour values set to 0
  int nonFiniteMotionValues = 0;  // NaN/Inf motion values (before or after conversion) set to 0
  int clampedColorValues = 0;     // float colour beyond +-65504 for a half output (results
                                  // beyond it are clamped)
  std::string motionPath;         // where motion came from (empty: no motion)
  int width = 0, height = 0;      // the colour data window's size
  bool sizeChanged = false;   // the size differs from the previous frame's: history restarted
  bool historyReset = false;  // the frame started a new history (first frame, gap, reset frame,
                              // size change)
  bool cutDetected = false;   // cut detection reset history on this frame
  bool preroll = false;       // resolved for history only, nothing written (prerollFrames)
  // Window mode: the frame has no camera matrices (header, note or sidecar), so its samples
  // follow their motion vectors only, without exact camera reprojection.
  bool noCamera = false;
  // The frame's projection carried its jitter, which was taken out (resolve/projection_jitter).
  bool jitterTakenOutOfProjection = false;
};

struct JobCallbacks {
  gl::LogSink log;                                      // informational messages
  gl::LogSink detail;  // what only a verbose run says (the window resolve following vectors)
  // After a frame is read, before it is resolved, with what its input changed silently
  // (non-finite values, clamped values, a new size). Throwing stops the job there: nothing of
  // that frame is written (taatool --strict).
  std::function<void(const FrameReport&)> frameRead;
  std::function<void(const FrameReport&)> frameDone;   // after each frame is written
  // Polled before each frame: true stops the job once the frames in flight are written, with
  // util/interruption.h's Stopped (SIGINT/SIGTERM in taatool, KeyboardInterrupt in Python).
  std::function<bool()> stopRequested;
};

// One input file of a frame and the AOV it serves ("color", "depth", "motion").
struct InputFile {
  std::string path, aov;
};

// Every input file of `frame`: color, then depth and motion (the color file again where they are
// its channels).
std::vector<InputFile> frameInputFiles(const io::AovLayout& layout, int frame);

// Frames of `layout` whose every input file (color, and depth and motion where they are files
// of their own) exists, ascending.
std::vector<int> availableInputFrames(const io::AovLayout& layout);

// The output files' taa:options attribute for `job`: every resolve option as "name=value; ...",
// the jitter source when it is not the options', and a multi-view job's views. io::checkOutputComplete compares it, so a
// frame resolved with other options is not taken for this job's.
std::string outputOptionsAttribute(const SequenceJob& job);

// Checks the job before any work: frames present and ascending (history runs forward), every
// input file of every frame exists, the output pattern can name each frame distinctly and never
// names an input file, ioThreads within [0, kMaxIoThreads], pre-roll frames only in history mode
// and among the frames.
// Throws taa::Error naming the file, frame and channel at fault.
void validateSequenceJob(const SequenceJob& job);

// Validates, removes temporaries of dead writers beside the output (io/stale_temp_files.h; each
// logged), creates the GL context and runs the job. Throws taa::Error on failure (Stopped on a
// stop request); frames written before are complete files, the failing frame leaves nothing.
void runSequenceJob(const SequenceJob& job, const JobCallbacks& callbacks = {});

}  // namespace taa
