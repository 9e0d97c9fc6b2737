#include "cli/progress_line.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace taa::cli {
namespace {

std::string duration(double seconds) {
  const long long total = std::llround(std::max(0.0, seconds));
  char text[32];
  if (total >= 3600) {
    std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", total / 3600, total / 60 % 60,
                  total % 60);
  } else {
    std::snprintf(text, sizeof text, "%lld:%02lld", total / 60, total % 60);
  }
  return text;
}

}  // namespace

std::string progressText(int done, int total, double elapsedSeconds) {
  std::string text = std::to_string(done) + "/" + std::to_string(total) + " frames";
  if (done <= 0 || elapsedSeconds <= 0.0) return text;
  const double rate = done / elapsedSeconds;
  char rateText[32];
  std::snprintf(rateText, sizeof rateText, rate < 10.0 ? "%.2f" : "%.1f", rate);
  text += std::string(", ") + rateText + " frames/s";
  if (done < total) text += ", " + duration((total - done) / rate) + " left";
  return text;
}

ProgressLine::ProgressLine(std::ostream& out, bool terminal)
    : out_(out), terminal_(terminal), start_(std::chrono::steady_clock::now()) {}

ProgressLine::~ProgressLine() { finish(); }

std::string ProgressLine::textNow(int done, int total) const {
  std::string text = elapsedText(done, total);
  const std::size_t frames = text.find(" frames");  // "6/24 frames, ..." -> "6/24, ..."
  return frames == std::string::npos ? text : text.erase(frames, 7);
}

std::string ProgressLine::elapsedText(int done, int total) const {
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start_;
  return progressText(done, total, elapsed.count());
}

void ProgressLine::frameDone(int frame, int done, int total) {
  const std::string text = elapsedText(done, total);
  if (terminal_) {
    out_ << "\rtaatool: " << text << "\x1b[K" << std::flush;
    lineOpen_ = true;
  } else {
    out_ << "taatool: frame " << frame << " written, " << text << std::endl;
  }
}

void ProgressLine::finish() {
  if (lineOpen_) out_ << "\n" << std::flush;
  lineOpen_ = false;
}

}  // namespace taa::cli
