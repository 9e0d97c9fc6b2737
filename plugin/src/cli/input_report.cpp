#include "cli/input_report.h"

#include "io/sequence_pattern.h"
#include "taa/error.h"
#include "util/frame_span.h"

namespace taa::cli {
namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

std::string plural(long long count, const std::string& one, const std::string& many) {
  return std::to_string(count) + " " + (count == 1 ? one : many);
}

std::string sizeText(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace

std::string frameListText(const std::vector<int>& frames) {
  std::string text;
  for (std::size_t i = 0; i < frames.size();) {
    std::size_t end = i;
    while (end + 1 < frames.size() && isNextFrame(frames[end], frames[end + 1])) ++end;
    text += (text.empty() ? "" : ", ") + std::to_string(frames[i]);
    if (end > i) text += "-" + std::to_string(frames[end]);
    i = end + 1;
  }
  return text;
}

void InputReport::Tally::add(long long count, const std::string& where) {
  if (count <= 0) return;
  if (frames == 0) first = where;
  values += count;
  ++frames;
}

InputReport::InputReport(const CommandLine& commandLine)
    : strict_(commandLine.strict),
      colorChannels_(joined(commandLine.job.layout.color.channels)),
      motionChannels_(commandLine.job.layout.motion
                          ? joined(commandLine.job.layout.motion->channels)
                          : ""),
      skipped_(commandLine.missingFrames) {
  if (strict_ && !skipped_.empty()) {
    const int first = skipped_.front();
    throw Error(plural(long(skipped_.size()), "frame", "frames") +
                    " missing from the sequence: " + frameListText(skipped_) +
                    " (--strict: not skipped)",
                {io::expandFramePattern(commandLine.job.layout.color.pattern, first), first, ""});
  }
}

void InputReport::frameRead(const FrameReport& report) {
  const std::string where = "frame " + std::to_string(report.frame) + ", " + report.inputPath;
  if (strict_) {
    const auto fail = [&](const std::string& what, const std::string& file,
                          const std::string& channels) {
      throw Error(what + " (--strict)", {file, report.frame, channels});
    };
    if (report.nonFiniteColorValues > 0) {
      fail(plural(report.nonFiniteColorValues, "NaN/Inf colour value", "NaN/Inf colour values") +
               " would be set to 0",
           report.inputPath, colorChannels_);
    }
    if (report.nonFiniteMotionValues > 0) {
      fail(plural(report.nonFiniteMotionValues, "NaN/Inf motion value", "NaN/Inf motion values") +
               " would be set to 0",
           report.motionPath, motionChannels_);
    }
    if (report.clampedColorValues > 0) {
      fail(plural(report.clampedColorValues, "colour value", "colour values") +
               " beyond half float's range for a half output (results beyond +-65504 would be "
               "clamped)",
           report.inputPath, colorChannels_);
    }
    if (report.jitterTakenOutOfProjection) {
      fail("the camera's projection carries the frame's jitter (its principal point is off the "
           "centre by exactly the jitter) and would be corrected",
           report.inputPath, "");
    }
    if (report.sizeChanged && lastSize_) {
      fail("the image size changes from " + sizeText(lastSize_->first, lastSize_->second) +
               " to " + sizeText(report.width, report.height) + ", which restarts history",
           report.inputPath, "");
    }
  }
  nonFiniteColor_.add(report.nonFiniteColorValues, where);
  nonFiniteMotion_.add(report.nonFiniteMotionValues,
                       "frame " + std::to_string(report.frame) + ", " + report.motionPath);
  clampedColor_.add(report.clampedColorValues, where);
  noCamera_.add(report.noCamera ? 1 : 0, where);
  projectionJitter_.add(report.jitterTakenOutOfProjection ? 1 : 0, where);
  if (report.sizeChanged && lastSize_) {
    sizeChanges_.add(1, "frame " + std::to_string(report.frame) + ", " +
                            sizeText(report.width, report.height) + " after " +
                            sizeText(lastSize_->first, lastSize_->second) + ", " +
                            report.inputPath);
  }
  lastSize_ = std::make_pair(report.width, report.height);
}

std::vector<std::string> InputReport::warnings() const {
  std::vector<std::string> lines;
  const auto inFrames = [](const Tally& t) {
    return " in " + plural(t.frames, "frame", "frames") + " (first: " + t.first + ")";
  };
  if (!skipped_.empty()) {
    lines.push_back("skipped " + plural(long(skipped_.size()), "missing frame", "missing frames") +
                    " (" + frameListText(skipped_) + "): history restarts after each gap");
  }
  if (nonFiniteColor_.frames > 0) {
    lines.push_back("set " + plural(nonFiniteColor_.values, "NaN/Inf colour value",
                                    "NaN/Inf colour values") +
                    " to 0" + inFrames(nonFiniteColor_));
  }
  if (nonFiniteMotion_.frames > 0) {
    lines.push_back("set " + plural(nonFiniteMotion_.values, "NaN/Inf motion value",
                                    "NaN/Inf motion values") +
                    " to 0" + inFrames(nonFiniteMotion_));
  }
  if (clampedColor_.frames > 0) {
    lines.push_back("read " + plural(clampedColor_.values, "colour value", "colour values") +
                    " beyond half float's range for a half output (results beyond +-65504 are "
                    "clamped to it)" +
                    inFrames(clampedColor_));
  }
  if (sizeChanges_.frames > 0) {
    lines.push_back("the image size changed " + plural(sizeChanges_.frames, "time", "times") +
                    ", history restarted there (first: " + sizeChanges_.first + ")");
  }
  if (projectionJitter_.frames > 0) {
    lines.push_back("took the jitter out of the camera's projection" +
                    inFrames(projectionJitter_) +
                    ": its principal point was off the centre by exactly the frame's jitter (a "
                    "jittered projection, as Blender's calc_matrix_camera gives on a jittered "
                    "frame); write the projection without it");
  }
  if (noCamera_.frames > 0) {
    lines.push_back("no camera matrices (header, camera note or --camera-sidecar)" +
                    inFrames(noCamera_) +
                    ": the window resolve carried their samples along the motion vectors only, "
                    "not by exact reprojection from depth, which costs sharpness on static "
                    "surfaces (a Cycles shot of a fence, floor and ball: 23.8 dB against 25.1 "
                    "with the camera); render through taa's Blender add-on or give "
                    "--camera-sidecar");
  }
  return lines;
}

}  // namespace taa::cli
